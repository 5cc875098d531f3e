import { TetrahedralizationError, validateTetrahedralization, type ValidTetrahedralization } from '../tetrahedra/validateTetrahedralization.js';
import { OuterCells } from './OuterCells.js';
import { computeInverseMatrices } from './inverseMatrices.js';

/**
 * The arrays of a mesh built elsewhere, for the third constructor argument (internal: used by
 * `TetrahedralMesh.fromTetrahedralization` and `IncrementalTetrahedralMesh`).
 */
export interface TetrahedralMeshParts {

	/** Function name for error messages. */
	where: string;

	/** The mesh's fields of the same names. */
	positions: Float64Array;
	tetrahedra: Uint32Array;
	neighbors: Int32Array;
	duplicates: Uint32Array;
	inverseMatrices: Float64Array;
	hullFaces: Uint32Array;
	hullFaceTetrahedra: Uint32Array;
	hullFaceSlots: Uint8Array;
	outerCells: OuterCells;

}

/**
 * Inverse matrices, hull faces (sorted by tetrahedron) and outer cells of a tetrahedralization.
 * @param where Function name for the outer cells' messages.
 */
export function buildMeshParts(
	where: string, p: Float64Array, tetrahedra: Uint32Array, neighbors: Int32Array, duplicates: Uint32Array,
): TetrahedralMeshParts {

	const inverseMatrices = computeInverseMatrices( p, tetrahedra );

	// Hull faces: count first, so the arrays are allocated once (100,000-probe volumes load here).
	const count = tetrahedra.length / 4;
	let hullCount = 0;
	for ( let i = 0; i < neighbors.length; i ++ ) if ( neighbors[ i ] === - 1 ) hullCount ++;
	const faces = new Uint32Array( 3 * hullCount );
	const owners = new Uint32Array( hullCount );
	const slots = new Uint8Array( hullCount );
	let o = 0;
	for ( let t = 0; t < count; t ++ ) {

		for ( let i = 0; i < 4; i ++ ) {

			if ( neighbors[ 4 * t + i ] !== - 1 ) continue;
			// The face without vertex i, ordered so that vertex i is on its negative side: for a
			// positive tetrahedron that makes it counter-clockwise seen from outside.
			const k = 4 * t, f = 3 * o;
			const v0 = tetrahedra[ k ], v1 = tetrahedra[ k + 1 ], v2 = tetrahedra[ k + 2 ], v3 = tetrahedra[ k + 3 ];
			// i = 0: (v1, v2, v3); 1: (v0, v3, v2); 2: (v0, v1, v3); 3: (v0, v2, v1).
			faces[ f ] = i === 0 ? v1 : v0;
			faces[ f + 1 ] = i === 0 ? v2 : i === 1 ? v3 : i === 2 ? v1 : v2;
			faces[ f + 2 ] = i === 0 ? v3 : i === 1 ? v2 : i === 2 ? v3 : v1;
			owners[ o ] = t; slots[ o ] = i;
			o ++;

		}

	}

	return {
		where, positions: p, tetrahedra, neighbors, duplicates, inverseMatrices,
		hullFaces: faces, hullFaceTetrahedra: owners, hullFaceSlots: slots, outerCells: new OuterCells( p, faces, where ),
	};

}

/**
 * A stored tetrahedralization as typed arrays (kept by reference when they already are):
 * {@link validateTetrahedralization}'s result, with indices out of range as RangeErrors like
 * `where`'s other argument checks, or unchecked when `trusted`.
 */
export function storedTetrahedralization(
	where: string, p: Float64Array, tetrahedra: ArrayLike<number>, neighbors: ArrayLike<number>, trusted: boolean,
): ValidTetrahedralization {

	if ( trusted ) {

		return {
			tetrahedra: tetrahedra instanceof Uint32Array ? tetrahedra : Uint32Array.from( tetrahedra ),
			neighbors: neighbors instanceof Int32Array ? neighbors : Int32Array.from( neighbors ),
		};

	}

	try {

		return validateTetrahedralization( where, p, tetrahedra, neighbors );

	} catch ( error ) {

		if ( error instanceof TetrahedralizationError && error.code === 'range' ) throw new RangeError( error.message );
		throw error;

	}

}

/**
 * The `duplicates` option of fromTetrahedralization: pairs (merged probe, probe it was merged
 * into) of probe indices, or none.
 * @throws TypeError / RangeError naming `where` for anything else.
 */
export function storedDuplicates( where: string, duplicates: unknown, probeCount: number ): Uint32Array {

	if ( duplicates === undefined || duplicates === null ) return new Uint32Array( 0 );
	const list = duplicates as ArrayLike<unknown>;
	if ( typeof duplicates !== 'object' || typeof list.length !== 'number' || list.length % 2 !== 0 ) {

		throw new TypeError( `${where}: options.duplicates must be pairs (merged probe, probe it was merged into) of probe indices, got ${typeof duplicates}.` );

	}

	for ( let i = 0; i < list.length; i ++ ) {

		const v = list[ i ];
		if ( typeof v !== 'number' || v >>> 0 !== v || v >= probeCount ) {

			throw new RangeError( `${where}: options.duplicates[${i}] = ${String( v )} is not a probe index (0..${probeCount - 1}).` );

		}

	}

	return Uint32Array.from( list as ArrayLike<number> );

}
