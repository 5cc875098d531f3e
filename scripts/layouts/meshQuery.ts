/**
 * Geometry queries on a scene's OBJ in plain Node, for checking probe layouts: a bounding volume
 * hierarchy over the triangles, first-hit and all-hits ray casts, nearest distance, and a
 * classification of a point as open space or inside geometry from rays in many directions.
 *
 * Used by scripts/layouts/checkLayouts.ts. three's OBJLoader parses the text; the BVH only makes
 * the many rays fast (three's Raycaster gives the same hits: `checkLayouts.ts --self-test`).
 */
import { existsSync, readFileSync } from 'node:fs';
import * as THREE from 'three';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
import { closestPointOnTriangle } from '../../src/geometry/closestPointOnTriangle.js';

/** All triangles of an OBJ in world space, with their material names. */
export interface TriangleSoup {

	/** 9 floats per triangle (a, b, c). */
	positions: Float64Array;
	/** Material index per triangle into `materials`. */
	material: Uint16Array;
	materials: string[];
	/** The parsed object, for three's Raycaster. */
	object: THREE.Group;

}

/** Parses an OBJ file (text) with three's OBJLoader and flattens it to triangles. */
export function loadTriangles( file: string ): TriangleSoup {

	if ( ! existsSync( file ) ) throw new Error( `meshQuery: ${file} not found (set CAPTURE_LIGHTING_ASSETS to the asset folder)` );
	const object = new OBJLoader().parse( readFileSync( file, 'utf8' ) );
	object.updateMatrixWorld( true );
	const positions: number[] = [], material: number[] = [], materials: string[] = [];
	const v = new THREE.Vector3();
	object.traverse( ( child ) => {

		const mesh = child as THREE.Mesh;
		if ( ! mesh.isMesh ) return;
		const attribute = mesh.geometry.getAttribute( 'position' );
		const list = Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ];
		const groups = mesh.geometry.groups.length > 0 ? mesh.geometry.groups : [ { start: 0, count: attribute.count, materialIndex: 0 } ];
		for ( const group of groups ) {

			const name = list[ group.materialIndex ?? 0 ].name;
			let index = materials.indexOf( name );
			if ( index < 0 ) index = materials.push( name ) - 1;
			for ( let i = group.start; i < group.start + group.count; i ++ ) {

				v.fromBufferAttribute( attribute, i ).applyMatrix4( mesh.matrixWorld );
				positions.push( v.x, v.y, v.z );
				if ( ( i - group.start ) % 3 === 0 ) material.push( index );

			}

		}

	} );
	return { positions: Float64Array.from( positions ), material: Uint16Array.from( material ), materials, object };

}

/** A hit of a ray: distance, triangle, and whether the ray met the triangle's back (winding) side. */
export interface Hit { t: number; triangle: number; back: boolean }

const LEAF = 8;

/** Median-split BVH over a triangle soup. */
export class TriangleBVH {

	readonly soup: TriangleSoup;
	private readonly order: Uint32Array;
	/** Per node: min xyz, max xyz. */
	private readonly boxes: Float64Array;
	/** Per node: left child (or −1 for a leaf), right child / first index, count. */
	private readonly nodes: Int32Array;
	private nodeCount = 0;

	constructor( soup: TriangleSoup ) {

		this.soup = soup;
		const count = soup.positions.length / 9;
		this.order = Uint32Array.from( { length: count }, ( _, i ) => i );
		const maxNodes = 2 * Math.ceil( count / ( LEAF / 2 ) ) + 1;
		this.boxes = new Float64Array( 6 * maxNodes );
		this.nodes = new Int32Array( 3 * maxNodes );
		const centroids = new Float64Array( 3 * count );
		for ( let t = 0; t < count; t ++ ) for ( let k = 0; k < 3; k ++ ) {

			centroids[ 3 * t + k ] =
				( soup.positions[ 9 * t + k ] + soup.positions[ 9 * t + 3 + k ] + soup.positions[ 9 * t + 6 + k ] ) / 3;

		}

		this.build( 0, count, centroids );

	}

	private build( start: number, end: number, centroids: Float64Array ): number {

		const node = this.nodeCount ++;
		const p = this.soup.positions, box = this.boxes;
		box.set( [ Infinity, Infinity, Infinity, - Infinity, - Infinity, - Infinity ], 6 * node );
		for ( let i = start; i < end; i ++ ) {

			const t = this.order[ i ];
			for ( let v = 0; v < 3; v ++ ) for ( let k = 0; k < 3; k ++ ) {

				const x = p[ 9 * t + 3 * v + k ];
				if ( x < box[ 6 * node + k ] ) box[ 6 * node + k ] = x;
				if ( x > box[ 6 * node + 3 + k ] ) box[ 6 * node + 3 + k ] = x;

			}

		}

		if ( end - start <= LEAF ) {

			this.nodes.set( [ - 1, start, end - start ], 3 * node );
			return node;

		}

		let axis = 0, extent = - 1;
		for ( let k = 0; k < 3; k ++ ) {

			const e = box[ 6 * node + 3 + k ] - box[ 6 * node + k ];
			if ( e > extent ) { extent = e; axis = k; }

		}

		const slice = Array.from( this.order.subarray( start, end ) )
			.sort( ( a, b ) => centroids[ 3 * a + axis ] - centroids[ 3 * b + axis ] );
		this.order.set( slice, start );
		const middle = ( start + end ) >> 1;
		const left = this.build( start, middle, centroids );
		const right = this.build( middle, end, centroids );
		this.nodes.set( [ left, right, 0 ], 3 * node );
		return node;

	}

	/** Every hit along the ray origin + t·direction, t > tMin, sorted by t. */
	raycastAll( origin: ArrayLike<number>, direction: ArrayLike<number>, tMin = 1e-6 ): Hit[] {

		const hits: Hit[] = [];
		const [ ox, oy, oz ] = [ origin[ 0 ], origin[ 1 ], origin[ 2 ] ];
		const [ dx, dy, dz ] = [ direction[ 0 ], direction[ 1 ], direction[ 2 ] ];
		const ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
		const p = this.soup.positions, box = this.boxes, nodes = this.nodes;
		const stack = [ 0 ];
		while ( stack.length > 0 ) {

			const node = stack.pop() as number;
			const b = 6 * node;
			let t0 = ( box[ b ] - ox ) * ix, t1 = ( box[ b + 3 ] - ox ) * ix;
			let near = Math.min( t0, t1 ), far = Math.max( t0, t1 );
			t0 = ( box[ b + 1 ] - oy ) * iy; t1 = ( box[ b + 4 ] - oy ) * iy;
			near = Math.max( near, Math.min( t0, t1 ) ); far = Math.min( far, Math.max( t0, t1 ) );
			t0 = ( box[ b + 2 ] - oz ) * iz; t1 = ( box[ b + 5 ] - oz ) * iz;
			near = Math.max( near, Math.min( t0, t1 ) ); far = Math.min( far, Math.max( t0, t1 ) );
			if ( ! ( far >= Math.max( near, 0 ) ) ) continue;
			if ( nodes[ 3 * node ] >= 0 ) { stack.push( nodes[ 3 * node ], nodes[ 3 * node + 1 ] ); continue; }

			for ( let i = nodes[ 3 * node + 1 ], e = i + nodes[ 3 * node + 2 ]; i < e; i ++ ) {

				// Möller–Trumbore, both sides.
				const t = this.order[ i ], o = 9 * t;
				const e1x = p[ o + 3 ] - p[ o ], e1y = p[ o + 4 ] - p[ o + 1 ], e1z = p[ o + 5 ] - p[ o + 2 ];
				const e2x = p[ o + 6 ] - p[ o ], e2y = p[ o + 7 ] - p[ o + 1 ], e2z = p[ o + 8 ] - p[ o + 2 ];
				const px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
				const det = e1x * px + e1y * py + e1z * pz;
				if ( Math.abs( det ) < 1e-12 ) continue;
				const inv = 1 / det;
				const sx = ox - p[ o ], sy = oy - p[ o + 1 ], sz = oz - p[ o + 2 ];
				const u = ( sx * px + sy * py + sz * pz ) * inv;
				if ( u < 0 || u > 1 ) continue;
				const qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
				const w = ( dx * qx + dy * qy + dz * qz ) * inv;
				if ( w < 0 || u + w > 1 ) continue;
				const hit = ( e2x * qx + e2y * qy + e2z * qz ) * inv;
				// det < 0: the ray runs along the normal e1 × e2, i.e. it meets the back side.
				if ( hit > tMin ) hits.push( { t: hit, triangle: t, back: det < 0 } );

			}

		}

		return hits.sort( ( a, b ) => a.t - b.t );

	}

	/** Distance from a point to the nearest triangle (and which). */
	nearest( x: number, y: number, z: number, limit = Infinity ): { distance: number; triangle: number } {

		const p = this.soup.positions, box = this.boxes, nodes = this.nodes;
		const out = new Float64Array( 6 );
		let best = limit * limit, triangle = - 1;
		const stack = [ 0 ];
		while ( stack.length > 0 ) {

			const node = stack.pop() as number;
			const b = 6 * node;
			const cx = Math.max( box[ b ] - x, 0, x - box[ b + 3 ] ), cy = Math.max( box[ b + 1 ] - y, 0, y - box[ b + 4 ] ),
				cz = Math.max( box[ b + 2 ] - z, 0, z - box[ b + 5 ] );
			if ( cx * cx + cy * cy + cz * cz >= best ) continue;
			if ( nodes[ 3 * node ] >= 0 ) { stack.push( nodes[ 3 * node ], nodes[ 3 * node + 1 ] ); continue; }
			for ( let i = nodes[ 3 * node + 1 ], e = i + nodes[ 3 * node + 2 ]; i < e; i ++ ) {

				const t = this.order[ i ], o = 9 * t;
				const d = closestPointOnTriangle(
					x, y, z, p[ o ], p[ o + 1 ], p[ o + 2 ], p[ o + 3 ], p[ o + 4 ], p[ o + 5 ], p[ o + 6 ], p[ o + 7 ], p[ o + 8 ], out
				);
				if ( d < best ) { best = d; triangle = t; }

			}

		}

		return { distance: Math.sqrt( best ), triangle };

	}

}

/** `count` directions spread evenly over the sphere (Fibonacci), none axis-aligned. */
export function sphereDirections( count: number ): number[][] {

	const directions: number[][] = [];
	const golden = Math.PI * ( 3 - Math.sqrt( 5 ) );
	for ( let i = 0; i < count; i ++ ) {

		const y = 1 - 2 * ( i + 0.5 ) / count, r = Math.sqrt( 1 - y * y ), phi = golden * i + 0.1;
		directions.push( [ r * Math.cos( phi ), y, r * Math.sin( phi ) ] );

	}

	return directions;

}

/** What the rays from a point saw. */
export interface PointReport {

	/** Distance to the nearest surface. */
	clearance: number;
	/** Fraction of rays whose first hit is a back side (inside a solid, or behind a one-sided wall). */
	backFraction: number;
	/** Fraction of rays that hit nothing (open sky or outside the model). */
	escapeFraction: number;
	/** Fraction of rays crossing an odd number of surfaces (parity test; noisy on open meshes). */
	oddFraction: number;
	/** Material of the nearest surface. */
	nearestMaterial: string;

}

const DIRECTIONS = sphereDirections( 64 );

/** Casts 64 rays from a point and measures its clearance: see {@link PointReport}. */
export function examinePoint( bvh: TriangleBVH, x: number, y: number, z: number, directions = DIRECTIONS ): PointReport {

	let back = 0, escape = 0, odd = 0;
	for ( const direction of directions ) {

		const hits = bvh.raycastAll( [ x, y, z ], direction );
		if ( hits.length === 0 ) { escape ++; continue; }
		if ( hits[ 0 ].back ) back ++;
		// Parity: hits closer than 1e-5 apart are one crossing (a ray through a shared edge).
		let crossings = 0, last = - Infinity;
		for ( const hit of hits ) { if ( hit.t - last > 1e-5 ) crossings ++; last = hit.t; }
		if ( crossings % 2 === 1 ) odd ++;

	}

	const n = directions.length;
	const { distance, triangle } = bvh.nearest( x, y, z );
	return { clearance: distance, backFraction: back / n, escapeFraction: escape / n, oddFraction: odd / n, nearestMaterial: triangle >= 0 ? bvh.soup.materials[ bvh.soup.material[ triangle ] ] : '' };

}
