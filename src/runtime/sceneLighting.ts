import type { BufferGeometry, Material, Mesh, Object3D, SkinnedMesh } from 'three';
import { automaticLighting, describeObject, readLightingMark } from './chooseLighting.js';
import type { AddOptions, ProbeLighting } from './LightProbeVolumeOptions.js';
import type { LitObject } from './litObjects.js';
import { probeUniformsOf } from './nodeMaterialHooks.js';
import { describeUnlitMeshes, hasProbeLitMaterial, missesProbeLight } from './probeLitMaterials.js';

/*
 * What `LightProbeVolume.add( scene )` (mode 'auto') registers: a walk over the scene graph that
 * turns marks, rigs and the per-mesh automatic choice into a list of objects to light, before
 * anything is patched (so a bad mark fails the call with nothing changed).
 */

/** One object `add( scene )` lights, and how. */
export interface LightingPlan {

	object: Object3D;
	lighting: ProbeLighting;

	/** Whether the entry covers everything below the object (a marked group, a rig) or the object alone (a mesh). */
	subtree: boolean;

}

type Mark = ProbeLighting | 'none' | undefined;

/**
 * The objects below `root` to light, parents before children. Skipped: objects already lit by
 * an entry of `lit` (with everything below when that entry covers its subtree), objects marked
 * `'none'` (with everything below), meshes without a material that takes probe light (see
 * `isProbeLitMaterial`), and meshes whose material another volume or the user patched. A marked
 * object is one plan covering its subtree (`'vertex'`: one per mesh below it, per-vertex lighting
 * being per mesh); a rig — skinned meshes and their bones under one root with nothing static
 * below it — is one `'dynamic'` plan for that root; every other mesh gets the automatic choice
 * for itself alone. Meshes left unlit because their shaders are their own (`ShaderMaterial`, node
 * materials: see `missesProbeLight`) get one `console.warn` for the call, once the plan is made;
 * unlit built-in materials (`MeshBasicMaterial` lamps) are taken as meant and pass silently.
 * @throws RangeError for a bad mark; Error when a marked object has an object lit already below it.
 */
export function planSceneLighting(
	where: string, root: Object3D, options: AddOptions, lit: readonly LitObject[], spacing: number,
): LightingPlan[] {

	const entries = new Map<Object3D, LitObject>();
	for ( const entry of lit ) entries.set( entry.object, entry );
	let moving = false;
	for ( let node = root.parent; node !== null; node = node.parent ) {

		if ( entries.get( node )?.subtree === true ) return [];
		if ( ( node as { isBone?: boolean } ).isBone === true ) moving = true;

	}

	const marks = new Map<Object3D, Mark>();
	const markOf = ( object: Object3D ): Mark => {

		if ( ! marks.has( object ) ) marks.set( object, readLightingMark( where, object, options.choose ) );
		return marks.get( object );

	};

	// Materials this volume patched in place: a mesh sharing one gets a clone; others patched are not ours.
	const owned = new Set<Material>();
	for ( const entry of lit ) for ( const material of entry.patched ) owned.add( material );
	const uses = new Map<BufferGeometry, number>();
	root.traverse( ( node ) => {

		const geometry = ( node as Mesh ).isMesh === true ? ( node as Mesh ).geometry : undefined;
		if ( geometry ) uses.set( geometry, ( uses.get( geometry ) ?? 0 ) + 1 );

	} );
	const rigs = findRigRoots( root, entries, markOf );
	const plans: LightingPlan[] = [];
	const unlit: Mesh[] = [];

	const visit = ( node: Object3D, underBone: boolean ): void => {

		const entry = entries.get( node );
		if ( entry?.subtree === true ) return;
		if ( entry === undefined ) {

			const mark = markOf( node );
			if ( mark === 'none' ) return;
			if ( mark === 'vertex' ) {

				assertNothingLitBelow( where, node, mark, entries );
				planVertexMeshes( where, node, plans, unlit );
				return;

			}

			if ( mark !== undefined || rigs.has( node ) ) {

				if ( mark !== undefined ) assertNothingLitBelow( where, node, mark, entries );
				plans.push( { object: node, lighting: mark ?? 'dynamic', subtree: true } );
				node.traverse( ( child ) => noteUnlit( child, unlit ) );
				return;

			}

			const mesh = node as Mesh;
			if ( mesh.isMesh === true && isLightable( mesh, owned ) ) {

				const skinned = ( mesh as SkinnedMesh ).isSkinnedMesh === true;
				const context = { spacing, moving: underBone || skinned, sharedGeometry: ( uses.get( mesh.geometry ) ?? 0 ) > 1 };
				plans.push( { object: mesh, lighting: automaticLighting( mesh, context ), subtree: false } );

			} else {

				noteUnlit( node, unlit );

			}

		}

		const below = underBone || ( node as { isBone?: boolean } ).isBone === true;
		for ( const child of node.children ) visit( child, below );

	};

	visit( root, moving );
	if ( unlit.length > 0 ) console.warn( describeUnlitMeshes( where, unlit ) );
	return plans;

}

/**
 * A mesh `add( scene )` may light: a position attribute, a material that takes probe light, none patched by
 * someone else (by either path: `probeUniformsOf` sees node materials the webgpu entry patched too).
 */
function isLightable( mesh: Mesh, owned: ReadonlySet<Material> ): boolean {

	if ( mesh.geometry?.getAttribute( 'position' ) === undefined || ! hasProbeLitMaterial( mesh ) ) return false;
	const materials = Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ];
	return ! materials.some( ( material ) => material && probeUniformsOf( material ) !== null && ! owned.has( material ) );

}

/** Adds `node` to `unlit` when it is a mesh whose own shaders keep the probe light out ({@link missesProbeLight}). */
function noteUnlit( node: Object3D, unlit: Mesh[] ): void {

	if ( ( node as Mesh ).isMesh === true && missesProbeLight( node as Mesh ) ) unlit.push( node as Mesh );

}

/** `'vertex'` on an object: each mesh below it with a material that takes probe light, per vertex (skinned ones cannot be). */
function planVertexMeshes( where: string, object: Object3D, plans: LightingPlan[], unlit: Mesh[] ): void {

	object.traverse( ( node ) => {

		const mesh = node as Mesh & { isSkinnedMesh?: boolean; isInstancedMesh?: boolean };
		noteUnlit( mesh, unlit );
		if ( mesh.isMesh !== true || ! hasProbeLitMaterial( mesh ) ) return;
		if ( mesh.isSkinnedMesh === true || mesh.isInstancedMesh === true ) {

			throw new RangeError( `${where}: ${describeObject( object )} is marked 'vertex', but ${describeObject( mesh )} below it is `
				+ 'skinned or instanced (its vertices move on the GPU); mark it \'dynamic\' or \'object\'.' );

		}

		plans.push( { object: mesh, lighting: 'vertex', subtree: false } );

	} );

}

/** A marked object is lit as one: nothing below it may be lit by this volume already. */
function assertNothingLitBelow( where: string, object: Object3D, mark: ProbeLighting, entries: ReadonlyMap<Object3D, LitObject> ): void {

	object.traverse( ( node ) => {

		if ( node !== object && entries.has( node ) ) {

			throw new Error( `${where}: ${describeObject( object )} is marked '${mark}', but ${describeObject( node )} below it is already lit `
				+ 'by this volume; remove it first (volume.remove( object )) or mark the objects below instead.' );

		}

	} );

}

/**
 * The roots of the rigs below `root`: for each skeleton, the lowest common ancestor of its skinned
 * meshes and bones, when every mesh below it is one of those meshes or hangs from a bone (an
 * attachment), nothing below it is marked or lit already, and it is not the root `Scene` itself
 * (hiding that in captures would hide the level).
 */
function findRigRoots( root: Object3D, entries: ReadonlyMap<Object3D, LitObject>, markOf: ( object: Object3D ) => Mark ): Set<Object3D> {

	const skeletons = new Map<object, Object3D[]>();
	root.traverse( ( node ) => {

		const mesh = node as SkinnedMesh;
		if ( mesh.isSkinnedMesh !== true || ! mesh.skeleton ) return;
		const members = skeletons.get( mesh.skeleton ) ?? [ ...mesh.skeleton.bones ];
		members.push( mesh );
		skeletons.set( mesh.skeleton, members );

	} );

	const rigs = new Set<Object3D>();
	for ( const [ skeleton, members ] of skeletons ) {

		const top = lowestCommonAncestor( members );
		if ( top === null || ! isWithin( top, root ) || ( top === root && ( root as { isScene?: boolean } ).isScene === true ) ) continue;
		let clean = true;
		const check = ( node: Object3D, underBone: boolean ) => {

			if ( ! clean ) return;
			if ( ( node !== top && entries.has( node ) ) || markOf( node ) !== undefined ) { clean = false; return; }
			const mesh = node as SkinnedMesh;
			if ( mesh.isMesh === true && ! underBone && mesh.skeleton !== skeleton ) { clean = false; return; }
			const below = underBone || ( node as { isBone?: boolean } ).isBone === true;
			for ( const child of node.children ) check( child, below );

		};

		check( top, false );
		if ( clean ) rigs.add( top );

	}

	return rigs;

}

/** The deepest object that is an ancestor-or-self of all `nodes`, or null when they are in different trees. */
function lowestCommonAncestor( nodes: readonly Object3D[] ): Object3D | null {

	let chain: Object3D[] = [];
	for ( let node: Object3D | null = nodes[ 0 ]; node !== null; node = node.parent ) chain.push( node );
	for ( const other of nodes.slice( 1 ) ) {

		const ancestors = new Set<Object3D>();
		for ( let node: Object3D | null = other; node !== null; node = node.parent ) ancestors.add( node );
		chain = chain.filter( ( node ) => ancestors.has( node ) );
		if ( chain.length === 0 ) return null;

	}

	return chain[ 0 ] ?? null;

}

/** Whether `object` is `ancestor` or below it. */
export function isWithin( object: Object3D, ancestor: Object3D ): boolean {

	for ( let node: Object3D | null = object; node !== null; node = node.parent ) if ( node === ancestor ) return true;
	return false;

}
