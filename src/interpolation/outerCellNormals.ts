/**
 * Vertex normals of the outer cells (`OuterCells`) and their repair where a cell's sweep would
 * fold. Pure math: no three.js. The proofs (fold test, tiling, termination): docs/outer-cells.md.
 */

// Queries farther than this many hull sizes from the hull's centre are pulled in along the same
// direction (by OuterCells.locate), so the fold test only needs to hold for τ ≤ FAR_LIMIT.
export const FAR_LIMIT = 1e12;

/**
 * Unit outward normal per probe for the outer cells of hull triangles `faces`: the angle-weighted
 * average of its hull faces' normals, smoothed (`untangle`) and then blended towards radial
 * (`unfold`) only where an outer cell would fold; 0, 0, 0 off the hull. Why and how:
 * docs/outer-cells.md ("Vertex normals", "Repairing folded normals").
 * @param scale The hull's size (the unit of τ in the fold test).
 */
export function outerCellNormals( p: Float64Array, faces: Uint32Array, scale: number ): Float64Array {

	const faceCount = faces.length / 3;
	const normals = new Float64Array( p.length );
	const faceNormals = new Float64Array( 3 * faceCount ), angles = new Float64Array( 3 * faceCount );
	for ( let f = 0; f < faceCount; f ++ ) {

		const ia = 3 * faces[ 3 * f ], ib = 3 * faces[ 3 * f + 1 ], ic = 3 * faces[ 3 * f + 2 ];
		const abx = p[ ib ] - p[ ia ], aby = p[ ib + 1 ] - p[ ia + 1 ], abz = p[ ib + 2 ] - p[ ia + 2 ];
		const acx = p[ ic ] - p[ ia ], acy = p[ ic + 1 ] - p[ ia + 1 ], acz = p[ ic + 2 ] - p[ ia + 2 ];
		const bcx = p[ ic ] - p[ ib ], bcy = p[ ic + 1 ] - p[ ib + 1 ], bcz = p[ ic + 2 ] - p[ ib + 2 ];
		let nx = aby * acz - abz * acy, ny = abz * acx - abx * acz, nz = abx * acy - aby * acx;
		const length = Math.hypot( nx, ny, nz );
		if ( length === 0 ) continue;
		nx /= length; ny /= length; nz /= length;
		faceNormals[ 3 * f ] = nx; faceNormals[ 3 * f + 1 ] = ny; faceNormals[ 3 * f + 2 ] = nz;
		// Corner angles by atan2(|u × v|, u · v): accurate for thin triangles, unlike acos.
		const angleA = Math.atan2( length, abx * acx + aby * acy + abz * acz );
		const angleB = Math.atan2( length, - ( abx * bcx + aby * bcy + abz * bcz ) );
		const angleC = Math.max( 0, Math.PI - angleA - angleB );
		angles[ 3 * f ] = angleA; angles[ 3 * f + 1 ] = angleB; angles[ 3 * f + 2 ] = angleC;
		normals[ ia ] += angleA * nx; normals[ ia + 1 ] += angleA * ny; normals[ ia + 2 ] += angleA * nz;
		normals[ ib ] += angleB * nx; normals[ ib + 1 ] += angleB * ny; normals[ ib + 2 ] += angleB * nz;
		normals[ ic ] += angleC * nx; normals[ ic + 1 ] += angleC * ny; normals[ ic + 2 ] += angleC * nz;

	}

	for ( let i = 0; i < normals.length; i += 3 ) {

		const length = Math.hypot( normals[ i ], normals[ i + 1 ], normals[ i + 2 ] );
		if ( length > 0 ) { normals[ i ] /= length; normals[ i + 1 ] /= length; normals[ i + 2 ] /= length; }

	}

	if ( untangle( p, faces, faceNormals, angles, normals, scale ) ) unfold( p, faces, normals, scale );
	return normals;

}

// Rounds of smoothing untangle() may take (a round costs O(hull faces) and runs only while some
// cell still folds; very flat random layouts need a dozen or more).
const UNTANGLE_ROUNDS = 40;

// How steep over each adjacent face a smoothed normal must stay, as a fraction of the
// angle-weighted normal's steepness there.
const MIN_STEEPNESS = 0.1;

// Least cosine between a ray and the normal of a hull face it starts from: the sweep must leave the
// face (a ray along the face would give a cell of zero thickness there).
const MIN_OUTWARD = 1e-9;

// Weights of the radial direction in the normals of the vertices of cells that still fold after
// smoothing (see `unfold`), step by step; the last, 1, is the purely radial normal.
const RADIAL_BLENDS = [ 0, 0.125, 0.25, 0.5, 1 ];

// Rounds of `unfold` before every hull vertex is made radial (a bound on the build's time: each
// round costs O(hull faces); the survey's flat layouts need a few).
const RADIAL_ROUNDS = 64;

/**
 * Whether outer cell f is not a one-to-one sweep: whether one of the quadratics N(t) · nᵢ of its
 * three vertices (N(t) the moved triangle's normal) fails to stay positive for τ = t / L in
 * [0, FAR_LIMIT]. When no cell folds, the cells tile the outside (proof: docs/outer-cells.md).
 */
function folds( p: Float64Array, faces: Uint32Array, n: Float64Array, f: number, L: number ): boolean {

	const a = 3 * faces[ 3 * f ], b = 3 * faces[ 3 * f + 1 ], c = 3 * faces[ 3 * f + 2 ];
	const e1x = p[ b ] - p[ a ], e1y = p[ b + 1 ] - p[ a + 1 ], e1z = p[ b + 2 ] - p[ a + 2 ];
	const e2x = p[ c ] - p[ a ], e2y = p[ c + 1 ] - p[ a + 1 ], e2z = p[ c + 2 ] - p[ a + 2 ];
	const f1x = n[ b ] - n[ a ], f1y = n[ b + 1 ] - n[ a + 1 ], f1z = n[ b + 2 ] - n[ a + 2 ];
	const f2x = n[ c ] - n[ a ], f2y = n[ c + 1 ] - n[ a + 1 ], f2z = n[ c + 2 ] - n[ a + 2 ];
	const n0x = e1y * e2z - e1z * e2y, n0y = e1z * e2x - e1x * e2z, n0z = e1x * e2y - e1y * e2x;
	const n1x = ( f1y * e2z - f1z * e2y ) + ( e1y * f2z - e1z * f2y );
	const n1y = ( f1z * e2x - f1x * e2z ) + ( e1z * f2x - e1x * f2z );
	const n1z = ( f1x * e2y - f1y * e2x ) + ( e1x * f2y - e1y * f2x );
	const n2x = f1y * f2z - f1z * f2y, n2y = f1z * f2x - f1x * f2z, n2z = f1x * f2y - f1y * f2x;
	const area = Math.hypot( n0x, n0y, n0z );
	if ( ! ( area > 0 ) ) return false;
	const s0 = 1 / area, s1 = L / area, s2 = L * L / area, T = FAR_LIMIT;
	for ( let k = 0; k < 3; k ++ ) {

		const v = k === 0 ? a : k === 1 ? b : c, x = n[ v ], y = n[ v + 1 ], z = n[ v + 2 ];
		const A = ( n0x * x + n0y * y + n0z * z ) * s0;
		const B = ( n1x * x + n1y * y + n1z * z ) * s1;
		const C = ( n2x * x + n2y * y + n2z * z ) * s2;
		if ( ! ( A > MIN_OUTWARD ) ) return true;
		if ( ! ( A + T * ( B + T * C ) > 0 ) ) return true;
		// Interior minimum of the quadratic at τ = −B / 2C.
		if ( C > 0 && B < 0 && - B < 2 * C * T && B * B >= 4 * A * C ) return true;

	}

	return false;

}

/**
 * Where angle-weighted normals make some outer cell fold, smooths the normals of those cells'
 * vertices towards their neighbours', round by round until no cell folds, keeping each ray at least
 * MIN_STEEPNESS as steep over its faces as before. Hulls without folds keep their normals exactly.
 * O(hull faces) per round.
 * @returns Whether some cell still folds (then `unfold` takes over).
 */
function untangle(
	p: Float64Array, faces: Uint32Array, faceNormals: Float64Array, angles: Float64Array, normals: Float64Array, L: number,
): boolean {

	const faceCount = faces.length / 3, vertexCount = normals.length / 3;
	let any = false;
	for ( let f = 0; f < faceCount && ! any; f ++ ) any = folds( p, faces, normals, f, L );
	if ( ! any ) return false;

	// Faces around each vertex (compressed rows), and each vertex's least steepness over them.
	const start = new Int32Array( vertexCount + 1 ), incident = new Int32Array( 3 * faceCount );
	for ( let i = 0; i < faces.length; i ++ ) start[ faces[ i ] + 1 ] ++;
	for ( let v = 0; v < vertexCount; v ++ ) start[ v + 1 ] += start[ v ];
	const fill = start.slice( 0, vertexCount );
	for ( let i = 0; i < faces.length; i ++ ) incident[ fill[ faces[ i ] ] ++ ] = ( i / 3 ) | 0;
	const steepness = ( v: number, x: number, y: number, z: number ): number => {

		let least = Infinity;
		for ( let i = start[ v ]; i < start[ v + 1 ]; i ++ ) {

			const f = 3 * incident[ i ];
			least = Math.min( least, x * faceNormals[ f ] + y * faceNormals[ f + 1 ] + z * faceNormals[ f + 2 ] );

		}

		return least;

	};

	const floor = new Float64Array( vertexCount );
	for ( let v = 0; v < vertexCount; v ++ ) {

		const least = steepness( v, normals[ 3 * v ], normals[ 3 * v + 1 ], normals[ 3 * v + 2 ] );
		floor[ v ] = least > 0 ? MIN_STEEPNESS * least : least;

	}

	// The vertices that move this round, as flags and as a list: rounds cost O(hull faces), not
	// O(probes) (probes inside the hull are never mobile).
	const mobile = new Uint8Array( vertexCount ), target = new Float64Array( normals.length ), moving = new Int32Array( vertexCount );
	let movingCount = 0;
	for ( let round = 0; round <= UNTANGLE_ROUNDS; round ++ ) {

		for ( let m = 0; m < movingCount; m ++ ) {

			const v = moving[ m ];
			mobile[ v ] = 0;
			target[ 3 * v ] = target[ 3 * v + 1 ] = target[ 3 * v + 2 ] = 0;

		}

		movingCount = 0;
		let count = 0;
		for ( let f = 0; f < faceCount; f ++ ) {

			if ( ! folds( p, faces, normals, f, L ) ) continue;
			for ( let k = 0; k < 3; k ++ ) {

				const v = faces[ 3 * f + k ];
				if ( mobile[ v ] === 0 ) { mobile[ v ] = 1; moving[ movingCount ++ ] = v; }

			}

			count ++;

		}

		if ( count === 0 ) return false;
		if ( round === UNTANGLE_ROUNDS ) break;
		for ( let f = 0; f < faceCount; f ++ ) {

			const a = 3 * faces[ 3 * f ], b = 3 * faces[ 3 * f + 1 ], c = 3 * faces[ 3 * f + 2 ];
			const mx = normals[ a ] + normals[ b ] + normals[ c ];
			const my = normals[ a + 1 ] + normals[ b + 1 ] + normals[ c + 1 ];
			const mz = normals[ a + 2 ] + normals[ b + 2 ] + normals[ c + 2 ];
			for ( let k = 0; k < 3; k ++ ) {

				const v = faces[ 3 * f + k ], w = angles[ 3 * f + k ];
				if ( mobile[ v ] === 0 ) continue;
				target[ 3 * v ] += w * mx; target[ 3 * v + 1 ] += w * my; target[ 3 * v + 2 ] += w * mz;

			}

		}

		for ( let m = 0; m < movingCount; m ++ ) {

			const v = moving[ m ], i = 3 * v;
			const tl = Math.hypot( target[ i ], target[ i + 1 ], target[ i + 2 ] );
			if ( tl === 0 ) continue;
			// Full step, then halves of it, back towards the current normal until steep enough.
			for ( let step = 1; step > 1 / 16; step *= 0.5 ) {

				const x = normals[ i ] + step * ( target[ i ] / tl - normals[ i ] );
				const y = normals[ i + 1 ] + step * ( target[ i + 1 ] / tl - normals[ i + 1 ] );
				const z = normals[ i + 2 ] + step * ( target[ i + 2 ] / tl - normals[ i + 2 ] );
				const l = Math.hypot( x, y, z );
				if ( l === 0 || steepness( v, x / l, y / l, z / l ) < floor[ v ] ) continue;
				normals[ i ] = x / l; normals[ i + 1 ] = y / l; normals[ i + 2 ] = z / l;
				break;

			}

		}

	}

	return true;

}

/**
 * The guaranteed end of the normals' repair, for cells smoothing left folded: raises the normals of
 * their vertices, round by round, one step of RADIAL_BLENDS towards the radial direction from the
 * hull vertices' centroid (radial normals never fold), until no cell folds; past RADIAL_ROUNDS every
 * hull vertex takes its radial normal. Terminates (proof: docs/outer-cells.md).
 */
function unfold( p: Float64Array, faces: Uint32Array, normals: Float64Array, L: number ): void {

	const faceCount = faces.length / 3, vertexCount = normals.length / 3;
	const onHull = new Uint8Array( vertexCount );
	let cx = 0, cy = 0, cz = 0, hullCount = 0;
	for ( let i = 0; i < faces.length; i ++ ) {

		const v = faces[ i ];
		if ( onHull[ v ] ) continue;
		onHull[ v ] = 1; hullCount ++;
		cx += p[ 3 * v ]; cy += p[ 3 * v + 1 ]; cz += p[ 3 * v + 2 ];

	}

	cx /= hullCount; cy /= hullCount; cz /= hullCount;
	const base = normals.slice(), level = new Uint8Array( vertexCount ), top = RADIAL_BLENDS.length - 1;
	const blend = ( v: number, s: number ): void => {

		const i = 3 * v, ux = p[ i ] - cx, uy = p[ i + 1 ] - cy, uz = p[ i + 2 ] - cz, ul = Math.hypot( ux, uy, uz );
		if ( s === 1 ) { normals[ i ] = ux / ul; normals[ i + 1 ] = uy / ul; normals[ i + 2 ] = uz / ul; return; }
		const x = ( 1 - s ) * base[ i ] + s * ux / ul, y = ( 1 - s ) * base[ i + 1 ] + s * uy / ul;
		const z = ( 1 - s ) * base[ i + 2 ] + s * uz / ul;
		const l = Math.hypot( x, y, z );
		normals[ i ] = x / l; normals[ i + 1 ] = y / l; normals[ i + 2 ] = z / l;

	};

	for ( let round = 0; round < RADIAL_ROUNDS; round ++ ) {

		// Raise this round from the folds seen at its start (the same for every face of the round).
		let any = false;
		for ( let f = 0; f < faceCount; f ++ ) {

			if ( ! folds( p, faces, normals, f, L ) ) continue;
			any = true;
			for ( let k = 0; k < 3; k ++ ) {

				const v = faces[ 3 * f + k ];
				// 128 + level marks "raise once this round".
				if ( level[ v ] < top ) level[ v ] |= 128;

			}

		}

		if ( ! any ) return;
		for ( let v = 0; v < vertexCount; v ++ ) {

			if ( level[ v ] < 128 ) continue;
			level[ v ] = ( level[ v ] & 127 ) + 1;
			blend( v, RADIAL_BLENDS[ level[ v ] ] );

		}

	}

	for ( let f = 0; f < faceCount; f ++ ) if ( folds( p, faces, normals, f, L ) ) {

		for ( let v = 0; v < vertexCount; v ++ ) if ( onHull[ v ] ) blend( v, 1 );
		return;

	}

}
