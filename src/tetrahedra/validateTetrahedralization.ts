import { orientAnyScale } from './predicates.js';

/*
 * The one check of a stored tetrahedralization (baked files, TetrahedralMesh.fromTetrahedralization):
 * O(tetrahedra), bounded by the input's length, naming the first problem. It does not check the
 * Delaunay property, nor that the hull faces form one closed convex surface (OuterCells does).
 */

/** What is wrong with a stored tetrahedralization. */
export type TetrahedralizationErrorCode =
	| 'range' // a vertex that is not a probe index, a neighbour that is neither −1 nor another tetrahedron
	| 'orientation' // a tetrahedron that is not positively oriented (flat or inverted)
	| 'neighbors'; // links that are not symmetric, do not share a face, overlap, or a hull face shared

/**
 * Thrown by {@link validateTetrahedralization}: a {@link TetrahedralizationError.code} and a
 * message starting with the caller's name (callers with their own error class map it).
 */
export class TetrahedralizationError extends Error {

	/** The failure class. */
	readonly code: TetrahedralizationErrorCode;

	/**
	 * @param code The failure class.
	 * @param message Starts with the function name, then names the field, the index and the problem.
	 */
	constructor( code: TetrahedralizationErrorCode, message: string ) {

		super( message );
		this.name = 'TetrahedralizationError';
		this.code = code;

	}

}

/** A tetrahedralization {@link validateTetrahedralization} accepted, as typed arrays. */
export interface ValidTetrahedralization {

	/** 4 probe indices per tetrahedron, positively oriented. */
	tetrahedra: Uint32Array;

	/** `neighbors[4t + i]`: the tetrahedron across the face opposite vertex i of t, or −1 on the hull. */
	neighbors: Int32Array;

}

function fail( code: TetrahedralizationErrorCode, where: string, message: string ): never {

	throw new TetrahedralizationError( code, `${where}: ${message}` );

}

/**
 * Checks tetrahedra and neighbour links against the positions: indices in range (also for plain
 * numbers, before the typed conversion where −1.5 or 2^32 would wrap), every tetrahedron
 * positively oriented (exact predicate on the float64 positions, at any scale), every link t →(i) n answered by
 * n → t across the same three vertices, with the two apexes on opposite sides of the shared face,
 * no hull face shared. The lengths are the caller's to check (a multiple of 4, equal).
 * @param where Function name the messages start with.
 * @returns The arrays as `Uint32Array` / `Int32Array` (the same objects when they already are).
 * @throws {TetrahedralizationError} naming the first problem.
 */
export function validateTetrahedralization(
	where: string, positions: Float64Array, tetrahedra: ArrayLike<number>, neighbors: ArrayLike<number>,
): ValidTetrahedralization {

	const probeCount = positions.length / 3;
	const tets = checkVertices( where, probeCount, tetrahedra );
	const links = checkNeighborIndices( where, neighbors );
	const tetCount = tets.length / 4;
	for ( let t = 0; t < tetCount; t ++ ) {

		const t4 = 4 * t;
		if ( ! ( orientAnyScale( positions, tets[ t4 ], tets[ t4 + 1 ], tets[ t4 + 2 ], tets[ t4 + 3 ] ) > 0 ) ) {

			fail( 'orientation', where, `tetrahedron ${t} (probes ${tets[ t4 ]}, ${tets[ t4 + 1 ]}, ${tets[ t4 + 2 ]}, ${tets[ t4 + 3 ]}) is not positively oriented (flat or inverted).` );

		}

	}

	checkLinks( where, tets, links );
	checkHullFaces( where, probeCount, tets, links );
	return { tetrahedra: tets, neighbors: links };

}

/** Vertex indices in 0..probeCount − 1 (integers, for plain numbers); a `Uint32Array` of them. */
function checkVertices( where: string, probeCount: number, tetrahedra: ArrayLike<number> ): Uint32Array {

	if ( tetrahedra instanceof Uint32Array ) {

		for ( let i = 0; i < tetrahedra.length; i ++ ) {

			if ( tetrahedra[ i ] >= probeCount ) notProbe( where, i, tetrahedra[ i ], probeCount );

		}

		return tetrahedra;

	}

	for ( let i = 0; i < tetrahedra.length; i ++ ) {

		const v = tetrahedra[ i ];
		if ( ! ( v >= 0 && v < probeCount && v === Math.floor( v ) ) ) notProbe( where, i, v, probeCount );

	}

	return Uint32Array.from( tetrahedra );

}

function notProbe( where: string, i: number, v: number, probeCount: number ): never {

	fail( 'range', where, `tetrahedra[${i}] = ${v} is not a probe index (0..${probeCount - 1}).` );

}

/** Neighbour entries −1 or another tetrahedron's index (integers, for plain numbers); an `Int32Array` of them. */
function checkNeighborIndices( where: string, neighbors: ArrayLike<number> ): Int32Array {

	const tetCount = neighbors.length / 4;
	if ( neighbors instanceof Int32Array ) {

		for ( let i = 0; i < neighbors.length; i ++ ) {

			const n = neighbors[ i ];
			if ( n < - 1 || n >= tetCount || n === i >> 2 ) notNeighbor( where, i, n, tetCount );

		}

		return neighbors;

	}

	for ( let i = 0; i < neighbors.length; i ++ ) {

		const n = neighbors[ i ];
		if ( ! ( n >= - 1 && n < tetCount && n === Math.floor( n ) ) || n === i >> 2 ) notNeighbor( where, i, n, tetCount );

	}

	return Int32Array.from( neighbors );

}

function notNeighbor( where: string, i: number, n: number, tetCount: number ): never {

	fail( 'range', where, `neighbors[${i}] = ${n} is neither −1 nor a tetrahedron index (0..${tetCount - 1}) other than its own (${i >> 2}).` );

}

/**
 * Every link checked once: each verified link t → n (n > t) also verifies n → t, so links are
 * checked from their lower end only; if that leaves a link unaccounted for, the upper ends are
 * checked too, and one of them fails with a precise message.
 */
function checkLinks( where: string, tetrahedra: Uint32Array, neighbors: Int32Array ): void {

	let links = 0, pairs = 0;
	for ( let f = 0; f < neighbors.length; f ++ ) {

		const n = neighbors[ f ];
		if ( n < 0 ) continue;
		links ++;
		if ( n > f >> 2 ) {

			checkLink( where, tetrahedra, neighbors, f );
			pairs ++;

		}

	}

	if ( links !== 2 * pairs ) {

		for ( let f = 0; f < neighbors.length; f ++ ) {

			if ( neighbors[ f ] >= 0 && neighbors[ f ] < f >> 2 ) checkLink( where, tetrahedra, neighbors, f );

		}

		fail( 'neighbors', where, `${links} neighbour links do not pair up (${pairs} symmetric pairs).` );

	}

}

/**
 * Checks the link f = 4t + i: n = neighbors[f] contains t's face i, links back across it, and lies
 * on the other side of it. Indices are already in range.
 */
function checkLink( where: string, tetrahedra: Uint32Array, neighbors: Int32Array, f: number ): void {

	const t = f >> 2, i = f & 3, n = neighbors[ f ], t4 = 4 * t, n4 = 4 * n;
	// The face opposite slot i, in slot order; its orientation seen from the apex is (−1)^i.
	const a = tetrahedra[ t4 + ( i === 0 ? 1 : 0 ) ], b = tetrahedra[ t4 + ( i <= 1 ? 2 : 1 ) ];
	const c = tetrahedra[ t4 + ( i <= 2 ? 3 : 2 ) ];
	let j = - 1, matched = 0, p0 = 0, p1 = 0, p2 = 0;
	for ( let k = 0; k < 4; k ++ ) {

		const v = tetrahedra[ n4 + k ];
		const position = v === a ? 0 : v === b ? 1 : v === c ? 2 : - 1;
		if ( position < 0 ) j = k;
		else if ( matched === 0 ) p0 = position;
		else if ( matched === 1 ) p1 = position;
		else p2 = position;
		if ( position >= 0 && matched < 3 ) matched ++;

	}

	if ( matched !== 3 || j < 0 ) {

		fail( 'neighbors', where, `neighbors[${f}] = ${n}, but tetrahedron ${n} does not share the face opposite vertex ${i} of tetrahedron ${t}: it does not contain the face's probes ${a}, ${b}, ${c}.` );

	}

	if ( neighbors[ n4 + j ] !== t ) {

		fail( 'neighbors', where, `neighbours are not symmetric: neighbors[${f}] = ${n} but neighbors[${n4 + j}] = ${neighbors[ n4 + j ]}, not ${t}.` );

	}

	// Parity of the permutation taking t's face order to n's (both tetrahedra positive): the apexes
	// lie on opposite sides exactly when the induced face orientations differ.
	const inversions = ( p0 > p1 ? 1 : 0 ) + ( p0 > p2 ? 1 : 0 ) + ( p1 > p2 ? 1 : 0 );
	if ( ( inversions + i + j ) % 2 === 0 ) {

		fail( 'neighbors', where, `tetrahedra ${t} and ${n} lie on the same side of their shared face (they overlap).` );

	}

}

/** The sorted probe indices of face i of tetrahedron t, as a map key. */
function faceKey( tetrahedra: Uint32Array, t: number, i: number ): string {

	let a = - 1, b = - 1, c = - 1;
	for ( let k = 0; k < 4; k ++ ) {

		if ( k === i ) continue;
		const v = tetrahedra[ 4 * t + k ];
		if ( a < 0 ) a = v; else if ( b < 0 ) b = v; else c = v;

	}

	const lo = Math.min( a, b, c ), hi = Math.max( a, b, c );
	return `${lo},${a + b + c - lo - hi},${hi}`;

}

/**
 * Symmetric, face-matched links leave one way for a face to belong to three tetrahedra: a hull
 * face (−1) that is also another tetrahedron's face. Hull faces are few (they and their vertices
 * lie on the convex hull), so they are hashed, and only faces whose three vertices are all hull
 * vertices are looked up.
 */
function checkHullFaces( where: string, probeCount: number, tetrahedra: Uint32Array, neighbors: Int32Array ): void {

	const tetCount = tetrahedra.length / 4;
	const onHull = new Uint8Array( probeCount );
	const hull = new Map<string, number>();
	for ( let f = 0; f < 4 * tetCount; f ++ ) {

		if ( neighbors[ f ] !== - 1 ) continue;
		const t = f >> 2, i = f & 3;
		const key = faceKey( tetrahedra, t, i );
		const other = hull.get( key );
		if ( other !== undefined ) {

			fail( 'neighbors', where, `the hull face ${key} belongs to tetrahedra ${other >> 2} and ${t}: they overlap, or the hull faces form more than one closed surface.` );

		}

		hull.set( key, f );
		for ( let k = 0; k < 4; k ++ ) if ( k !== i ) onHull[ tetrahedra[ 4 * t + k ] ] = 1;

	}

	for ( let f = 0; f < 4 * tetCount; f ++ ) {

		if ( neighbors[ f ] < 0 ) continue;
		const t = f >> 2, i = f & 3;
		let all = true;
		for ( let k = 0; k < 4 && all; k ++ ) if ( k !== i && onHull[ tetrahedra[ 4 * t + k ] ] === 0 ) all = false;
		if ( ! all ) continue;
		const key = faceKey( tetrahedra, t, i );
		const other = hull.get( key );
		if ( other !== undefined ) fail( 'neighbors', where, `face ${key} is a hull face of tetrahedron ${other >> 2} and an inner face of tetrahedron ${t} (they overlap).` );

	}

}
