import { Box3, Vector3, type BufferAttribute, type Mesh, type Object3D } from 'three';
import { describeValue } from '../validate.js';
import type { AddOptions, ProbeLighting, ProbeLightingChoice } from './LightProbeVolumeOptions.js';

/*
 * The per-mesh choice of `LightProbeVolume.add( scene )`: how each mesh of a level is lit when
 * nothing marks it — one blend per object for what moves and for small props, per vertex or from a
 * 3D SH texture for static meshes larger than the probe spacing — and the marks that override it
 * (`userData.probeLighting`, the `choose` option).
 */

/** The `userData` key (a glTF node's `extras` key) that marks how an object is lit by `add( scene )`. */
export const PROBE_LIGHTING_KEY = 'probeLighting';

const CHOICES: readonly ProbeLightingChoice[] = [ 'auto', 'dynamic', 'object', 'vertex', 'texture', 'none' ];

/** Triangles measured per mesh for its tessellation: a strided sample, so a million-triangle mesh costs as much as a small one. */
const EDGE_SAMPLES = 4096;

const _box = new Box3();
const _size = new Vector3();
const _a = new Vector3(), _b = new Vector3(), _c = new Vector3();

/** What the automatic choice knows of a mesh besides the mesh itself. */
export interface MeshContext {

	/** The typical probe distance (`LightProbeVolume.probeSpacing`). */
	spacing: number;

	/** The mesh moves with an animated rig (it is skinned or below a `Bone`). */
	moving: boolean;

	/** Its geometry is used by other meshes too (vertex lighting writes attributes into the geometry). */
	sharedGeometry: boolean;

}

/**
 * The mark on an object: `choose( object )` if it returns something, else
 * `object.userData.probeLighting`, else undefined (`'auto'` counts as unmarked).
 * @throws RangeError naming the object when the mark is not one of the known values.
 */
export function readLightingMark( where: string, object: Object3D, choose: AddOptions[ 'choose' ] ): ProbeLighting | 'none' | undefined {

	let mark: unknown = choose !== undefined ? choose( object ) : undefined;
	let source = 'options.choose';
	if ( mark === undefined ) {

		mark = object.userData?.[ PROBE_LIGHTING_KEY ];
		source = `userData.${PROBE_LIGHTING_KEY}`;

	}

	if ( mark === undefined || mark === 'auto' ) return undefined;
	if ( ! CHOICES.includes( mark as ProbeLightingChoice ) ) {

		throw new RangeError( `${where}: ${source} of ${describeObject( object )} is ${describeValue( mark )}; expected `
			+ `${CHOICES.map( ( choice ) => `'${choice}'` ).join( ', ' )} or undefined.` );

	}

	return mark as ProbeLighting | 'none';

}

/**
 * How an unmarked mesh is lit: `'dynamic'` when it moves with a rig; `'object'` (one blend, kept
 * until it moves or the probes change) for instanced and batched meshes and for meshes whose world
 * bounds are no longer than the probe spacing; else `'vertex'` when its triangles are at most half
 * the spacing long (two vertices or more between probes: the per-vertex field then follows the
 * probes) and its geometry is its own with normals, and `'texture'` otherwise (a floor made of two
 * triangles gets per-pixel light from a 3D texture, not the colours of its 4 corners).
 */
export function automaticLighting( mesh: Mesh, context: MeshContext ): ProbeLighting {

	const candidate = mesh as Mesh & { isInstancedMesh?: boolean; isBatchedMesh?: boolean };
	if ( context.moving ) return 'dynamic';
	if ( candidate.isInstancedMesh === true || candidate.isBatchedMesh === true ) return 'object';
	const box = meshWorldBox( mesh, _box );
	if ( box.isEmpty() || ! ( box.getSize( _size ).x > context.spacing || _size.y > context.spacing || _size.z > context.spacing ) ) {

		return 'object';

	}

	const geometry = mesh.geometry;
	const ownGeometry = ! context.sharedGeometry && geometry.getAttribute( 'probeIrradiance' ) === undefined;
	if ( ownGeometry && geometry.getAttribute( 'normal' ) !== undefined && medianTriangleEdge( mesh ) <= 0.5 * context.spacing ) {

		return 'vertex';

	}

	return 'texture';

}

/** The world bounding box of a mesh alone (not its children), as `Box3.expandByObject` computes it. */
export function meshWorldBox( mesh: Mesh, target: Box3 ): Box3 {

	const own = mesh as Mesh & { boundingBox?: Box3 | null; computeBoundingBox?: () => void };
	target.makeEmpty();
	if ( mesh.geometry?.getAttribute( 'position' ) === undefined ) return target;
	mesh.updateWorldMatrix( true, false );
	if ( own.boundingBox !== undefined ) {

		// Skinned, instanced and batched meshes have bounds of their own (bones, instances).
		if ( own.boundingBox === null ) own.computeBoundingBox!();
		target.copy( own.boundingBox! );

	} else {

		if ( mesh.geometry.boundingBox === null ) mesh.geometry.computeBoundingBox();
		target.copy( mesh.geometry.boundingBox! );

	}

	return target.applyMatrix4( mesh.matrixWorld );

}

/**
 * The median, over the mesh's triangles (a strided sample of at most 4096), of each triangle's
 * longest edge in world space: how far apart the vertices that per-vertex lighting samples are.
 * Infinity for a mesh without triangles.
 */
export function medianTriangleEdge( mesh: Mesh ): number {

	const geometry = mesh.geometry;
	const position = geometry.getAttribute( 'position' ) as BufferAttribute;
	const index = geometry.getIndex();
	const triangles = Math.floor( ( index ? index.count : position.count ) / 3 );
	if ( triangles === 0 ) return Infinity;
	mesh.updateWorldMatrix( true, false );
	const matrix = mesh.matrixWorld;
	const step = Math.max( 1, Math.floor( triangles / EDGE_SAMPLES ) );
	const edges: number[] = [];
	const vertex = ( corner: number ) => ( index ? index.getX( corner ) : corner );
	for ( let t = 0; t < triangles; t += step ) {

		_a.fromBufferAttribute( position, vertex( 3 * t ) ).applyMatrix4( matrix );
		_b.fromBufferAttribute( position, vertex( 3 * t + 1 ) ).applyMatrix4( matrix );
		_c.fromBufferAttribute( position, vertex( 3 * t + 2 ) ).applyMatrix4( matrix );
		edges.push( Math.max( _a.distanceTo( _b ), _b.distanceTo( _c ), _c.distanceTo( _a ) ) );

	}

	edges.sort( ( x, y ) => x - y );
	return edges[ edges.length >> 1 ];

}

/** An object as messages name it: `"name"`, or its type and uuid. */
export function describeObject( object: Object3D ): string {

	return object.name ? `"${object.name}"` : `(${object.type} ${object.uuid})`;

}
