import { orient3d, insphere } from 'robust-predicates';

/*
 * Independent, brute-force checks of a tetrahedralization, written against robust-predicates
 * directly (not the library's predicate wrappers) so a sign slip in the library cannot hide here.
 */

/** Exact sign of det[b − a, c − a, d − a] (robust-predicates' orient3d has the opposite sign). */
function volumeSign( p: Float64Array, a: number, b: number, c: number, d: number ): number {

	return - Math.sign( orient3d(
		p[ 3 * a ], p[ 3 * a + 1 ], p[ 3 * a + 2 ], p[ 3 * b ], p[ 3 * b + 1 ], p[ 3 * b + 2 ],
		p[ 3 * c ], p[ 3 * c + 1 ], p[ 3 * c + 2 ], p[ 3 * d ], p[ 3 * d + 1 ], p[ 3 * d + 2 ] ) );

}

function volume( p: Float64Array, a: number, b: number, c: number, d: number ): number {

	const ax = p[ 3 * a ], ay = p[ 3 * a + 1 ], az = p[ 3 * a + 2 ];
	const ux = p[ 3 * b ] - ax, uy = p[ 3 * b + 1 ] - ay, uz = p[ 3 * b + 2 ] - az;
	const vx = p[ 3 * c ] - ax, vy = p[ 3 * c + 1 ] - ay, vz = p[ 3 * c + 2 ] - az;
	const wx = p[ 3 * d ] - ax, wy = p[ 3 * d + 1 ] - ay, wz = p[ 3 * d + 2 ] - az;
	return ( ux * ( vy * wz - vz * wy ) - uy * ( vx * wz - vz * wx ) + uz * ( vx * wy - vy * wx ) ) / 6;

}

export interface DelaunayReport {

	tetrahedra: number;
	nonPositive: number;
	asymmetricNeighbors: number;
	mismatchedFaces: number;
	unusedPoints: number;
	hullViolations: number;
	emptySphereViolations: number;
	volumeSum: number;
	hullVolume: number;

}

/**
 * Runs every check; `skip` holds point indices that were merged as duplicates (not vertices).
 */
export function checkDelaunay( p: Float64Array, tetrahedra: Uint32Array, neighbors: Int32Array, skip: Set<number> = new Set() ): DelaunayReport {

	const n = p.length / 3, count = tetrahedra.length / 4;
	const report: DelaunayReport = {
		tetrahedra: count, nonPositive: 0, asymmetricNeighbors: 0, mismatchedFaces: 0, unusedPoints: 0,
		hullViolations: 0, emptySphereViolations: 0, volumeSum: 0, hullVolume: 0,
	};

	const used = new Uint8Array( n );
	for ( let t = 0; t < count; t ++ ) {

		const [ a, b, c, d ] = tetrahedra.subarray( 4 * t, 4 * t + 4 );
		used[ a ] = used[ b ] = used[ c ] = used[ d ] = 1;
		if ( volumeSign( p, a, b, c, d ) <= 0 ) report.nonPositive ++;
		report.volumeSum += volume( p, a, b, c, d );

		for ( let i = 0; i < 4; i ++ ) {

			const u = neighbors[ 4 * t + i ];
			if ( u === - 1 ) continue;
			let back = - 1;
			for ( let j = 0; j < 4; j ++ ) if ( neighbors[ 4 * u + j ] === t ) back = j;
			if ( back === - 1 ) { report.asymmetricNeighbors ++; continue; }
			const mine = faceKey( tetrahedra, t, i ), theirs = faceKey( tetrahedra, u, back );
			if ( mine !== theirs ) report.mismatchedFaces ++;

		}

	}

	for ( let i = 0; i < n; i ++ ) if ( ! used[ i ] && ! skip.has( i ) ) report.unusedPoints ++;

	// Hull faces: every point on the inner side; their enclosed volume by the divergence theorem,
	// as cones from the centroid (near the hull, so far-away coordinates do not cancel).
	const centroid = [ 0, 0, 0 ];
	for ( let i = 0; i < n; i ++ ) for ( let a = 0; a < 3; a ++ ) centroid[ a ] += p[ 3 * i + a ] / n;
	for ( let t = 0; t < count; t ++ ) {

		for ( let i = 0; i < 4; i ++ ) {

			if ( neighbors[ 4 * t + i ] !== - 1 ) continue;
			const v = Array.from( tetrahedra.subarray( 4 * t, 4 * t + 4 ) );
			// Replace the inner vertex by a test point: positive means the same side as the inner vertex.
			for ( let q = 0; q < n; q ++ ) {

				if ( skip.has( q ) ) continue;
				const w = v.slice(); w[ i ] = q;
				if ( volumeSign( p, w[ 0 ], w[ 1 ], w[ 2 ], w[ 3 ] ) < 0 ) { report.hullViolations ++; break; }

			}

			// The cell with its inner vertex moved to the apex: the signed volume of the cone from the
			// apex over this face, positive when the apex is on the inner side. Summed over a closed
			// outward surface, these give the enclosed volume wherever the apex is.
			report.hullVolume += coneVolume( p, v, i, centroid );

		}

	}

	report.emptySphereViolations = countEmptySphereViolations( p, tetrahedra, skip );
	return report;

}

function faceKey( tetrahedra: Uint32Array, t: number, i: number ): string {

	const f: number[] = [];
	for ( let k = 0; k < 4; k ++ ) if ( k !== i ) f.push( tetrahedra[ 4 * t + k ] );
	return f.sort( ( a, b ) => a - b ).join( ',' );

}

function coneVolume( p: Float64Array, v: number[], i: number, apex: number[] ): number {

	const q = new Float64Array( 12 ); // slot i is the apex, at the origin of these coordinates
	for ( let k = 0; k < 4; k ++ ) {

		if ( k === i ) continue;
		for ( let a = 0; a < 3; a ++ ) q[ 3 * k + a ] = p[ 3 * v[ k ] + a ] - apex[ a ];

	}

	return volume( q, 0, 1, 2, 3 );

}

/**
 * Counts tetrahedra with an input point strictly inside their circumsphere (exact insphere), with a
 * uniform grid over the points to find the candidates inside each sphere's bounding box.
 */
function countEmptySphereViolations( p: Float64Array, tetrahedra: Uint32Array, skip: Set<number> ): number {

	const n = p.length / 3;
	let minX = Infinity, minY = Infinity, minZ = Infinity, maxX = - Infinity, maxY = - Infinity, maxZ = - Infinity;
	for ( let i = 0; i < n; i ++ ) {

		minX = Math.min( minX, p[ 3 * i ] ); maxX = Math.max( maxX, p[ 3 * i ] );
		minY = Math.min( minY, p[ 3 * i + 1 ] ); maxY = Math.max( maxY, p[ 3 * i + 1 ] );
		minZ = Math.min( minZ, p[ 3 * i + 2 ] ); maxZ = Math.max( maxZ, p[ 3 * i + 2 ] );

	}

	const cells = Math.max( 1, Math.round( Math.cbrt( n / 2 ) ) );
	const sx = ( maxX - minX ) / cells || 1, sy = ( maxY - minY ) / cells || 1, sz = ( maxZ - minZ ) / cells || 1;
	const bucket: number[][] = Array.from( { length: cells ** 3 }, () => [] );
	const cell = ( v: number, min: number, s: number ) => Math.min( cells - 1, Math.max( 0, Math.floor( ( v - min ) / s ) ) );
	for ( let i = 0; i < n; i ++ ) {

		if ( skip.has( i ) ) continue;
		bucket[ cell( p[ 3 * i ], minX, sx ) + cells * ( cell( p[ 3 * i + 1 ], minY, sy ) + cells * cell( p[ 3 * i + 2 ], minZ, sz ) ) ].push( i );

	}

	let violations = 0;
	for ( let t = 0, count = tetrahedra.length / 4; t < count; t ++ ) {

		const [ a, b, c, d ] = tetrahedra.subarray( 4 * t, 4 * t + 4 );
		const [ cx, cy, cz, r ] = circumsphere( p, a, b, c, d );
		const pad = r * ( 1 + 1e-6 ) + 1e-12;
		for ( let k = cell( cz - pad, minZ, sz ); k <= cell( cz + pad, minZ, sz ); k ++ ) {

			for ( let j = cell( cy - pad, minY, sy ); j <= cell( cy + pad, minY, sy ); j ++ ) {

				for ( let i = cell( cx - pad, minX, sx ); i <= cell( cx + pad, minX, sx ); i ++ ) {

					for ( const q of bucket[ i + cells * ( j + cells * k ) ] ) {

						if ( q === a || q === b || q === c || q === d ) continue;
						const s = insphere(
							p[ 3 * a ], p[ 3 * a + 1 ], p[ 3 * a + 2 ], p[ 3 * b ], p[ 3 * b + 1 ], p[ 3 * b + 2 ],
							p[ 3 * c ], p[ 3 * c + 1 ], p[ 3 * c + 2 ], p[ 3 * d ], p[ 3 * d + 1 ], p[ 3 * d + 2 ],
							p[ 3 * q ], p[ 3 * q + 1 ], p[ 3 * q + 2 ] );
						// robust-predicates: > 0 inside for a tetrahedron with det[b−a, c−a, d−a] > 0.
						if ( s > 0 ) violations ++;

					}

				}

			}

		}

	}

	return violations;

}

function circumsphere( p: Float64Array, a: number, b: number, c: number, d: number ): [ number, number, number, number ] {

	const ax = p[ 3 * a ], ay = p[ 3 * a + 1 ], az = p[ 3 * a + 2 ];
	const bx = p[ 3 * b ] - ax, by = p[ 3 * b + 1 ] - ay, bz = p[ 3 * b + 2 ] - az;
	const cx = p[ 3 * c ] - ax, cy = p[ 3 * c + 1 ] - ay, cz = p[ 3 * c + 2 ] - az;
	const dx = p[ 3 * d ] - ax, dy = p[ 3 * d + 1 ] - ay, dz = p[ 3 * d + 2 ] - az;
	const b2 = bx * bx + by * by + bz * bz, c2 = cx * cx + cy * cy + cz * cz, d2 = dx * dx + dy * dy + dz * dz;
	const det = 2 * ( bx * ( cy * dz - cz * dy ) - by * ( cx * dz - cz * dx ) + bz * ( cx * dy - cy * dx ) );
	const ox = ( b2 * ( cy * dz - cz * dy ) - c2 * ( by * dz - bz * dy ) + d2 * ( by * cz - bz * cy ) ) / det;
	const oy = ( bx * ( c2 * dz - cz * d2 ) - cx * ( b2 * dz - bz * d2 ) + dx * ( b2 * cz - bz * c2 ) ) / det;
	const oz = ( bx * ( cy * d2 - c2 * dy ) - cx * ( by * d2 - b2 * dy ) + dx * ( by * c2 - b2 * cy ) ) / det;
	return [ ax + ox, ay + oy, az + oz, Math.hypot( ox, oy, oz ) ];

}
