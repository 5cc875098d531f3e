import type { Material, Mesh } from 'three';
import { isLitNodeMaterial, nodeMaterialShading } from './nodeMaterialHooks.js';

/*
 * Which materials take probe light. three's Standard, Physical, Phong, Lambert and Toon WebGL
 * shaders all run lights_fragment_begin and hand its `irradiance` to their RE_IndirectDiffuse
 * (a Lambertian term in every one), which is where patchMaterial adds the probe term — the place
 * of a LightProbe's. Node materials copy `isMeshStandardMaterial` and the like from the built-in
 * material they mirror, but never run onBeforeCompile: `isProbeLitMaterial` excludes them, and
 * {@link takesProbeLight} admits the lit ones once node shading is installed
 * (`three-capture-lighting/webgpu`, see nodeMaterialHooks.ts).
 */

/** The material types that take probe light, for messages. */
export const PROBE_LIT_MATERIALS = 'MeshStandardMaterial, MeshPhysicalMaterial, MeshPhongMaterial, MeshLambertMaterial or MeshToonMaterial';

/** How many meshes a warning names at most. */
const NAMED_MESHES = 3;

interface MaterialFlags {

	isMeshStandardMaterial?: boolean;
	isMeshPhongMaterial?: boolean;
	isMeshLambertMaterial?: boolean;
	isMeshToonMaterial?: boolean;
	isShaderMaterial?: boolean;
	isNodeMaterial?: boolean;

}

/**
 * Whether `patchMaterial` can add probe light to a material: a `MeshStandardMaterial`,
 * `MeshPhysicalMaterial`, `MeshPhongMaterial`, `MeshLambertMaterial` or `MeshToonMaterial`.
 */
export function isProbeLitMaterial( material: unknown ): material is Material {

	const m = material as MaterialFlags | null | undefined;
	if ( ! m || m.isNodeMaterial === true ) return false;
	return m.isMeshStandardMaterial === true || m.isMeshPhongMaterial === true || m.isMeshLambertMaterial === true
		|| m.isMeshToonMaterial === true;

}

/**
 * Whether a material takes probe light in this build: {@link isProbeLitMaterial}, or a lit node
 * material (`MeshStandardNodeMaterial`, `MeshPhysicalNodeMaterial`, Phong, Lambert, Toon) when
 * node shading is installed.
 */
export function takesProbeLight( material: unknown ): material is Material {

	if ( isProbeLitMaterial( material ) ) return true;
	const shading = nodeMaterialShading();
	return shading !== null && isLitNodeMaterial( material ) && shading.lights( material as Material );

}

/**
 * Whether a material is shaded by code the probe light cannot reach — a `ShaderMaterial`,
 * `RawShaderMaterial` or node material (one {@link takesProbeLight} does not admit) — so a mesh
 * wearing it misses the light unnoticed. Unlit built-ins (Basic, Normal, Matcap, Depth, Distance, Shadow) are taken as meant to be unlit.
 */
export function isUnpatchableMaterial( material: unknown ): boolean {

	const m = material as MaterialFlags | null | undefined;
	return !! m && ( m.isShaderMaterial === true || m.isNodeMaterial === true ) && ! takesProbeLight( m );

}

/** A mesh's material slots, empty ones left out. */
export function meshMaterials( mesh: Mesh ): Material[] {

	const materials: ( Material | null | undefined )[] = Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ];
	return materials.filter( ( material ): material is Material => !! material );

}

/** Whether a mesh has a material that takes probe light ({@link takesProbeLight}). */
export function hasProbeLitMaterial( mesh: Mesh ): boolean {

	return meshMaterials( mesh ).some( takesProbeLight );

}

/** Whether a mesh gets no probe light although a material of it looks lit ({@link isUnpatchableMaterial}). */
export function missesProbeLight( mesh: Mesh ): boolean {

	const materials = meshMaterials( mesh );
	return ! materials.some( takesProbeLight ) && materials.some( isUnpatchableMaterial );

}

/**
 * The warning for meshes `add( scene )` left without probe light ({@link missesProbeLight}): how
 * many, their material types with counts, the first few names, and what to do.
 */
export function describeUnlitMeshes( where: string, meshes: readonly Mesh[] ): string {

	const types = new Map<string, number>();
	for ( const mesh of meshes ) {

		const names = new Set( meshMaterials( mesh ).filter( isUnpatchableMaterial ).map( ( material ) => material.type ) );
		for ( const type of names ) types.set( type, ( types.get( type ) ?? 0 ) + 1 );

	}

	const counts = [ ...types ].map( ( [ type, count ] ) => `${type} ×${count}` ).join( ', ' );
	const named = meshes.filter( ( mesh ) => mesh.name ).slice( 0, NAMED_MESHES ).map( ( mesh ) => `"${mesh.name}"` );
	const examples = named.length > 0 ? ` (${named.join( ', ' )}${meshes.length > named.length ? ', …' : ''})` : '';
	const count = meshes.length === 1 ? '1 mesh' : `${meshes.length} meshes`;
	const nodes = nodeMaterialShading() === null && [ ...types.keys() ].some( ( type ) => type.endsWith( 'NodeMaterial' ) )
		? ' Node materials are lit when the library is imported from \'three-capture-lighting/webgpu\'.' : '';
	return `${where}: ${count}${examples} with ${counts} ${meshes.length === 1 ? 'gets' : 'get'} no probe light: their shaders are their own, and only `
		+ `${PROBE_LIT_MATERIALS} take it. Give them one of those to light them, or mark them `
		+ `userData.probeLighting = 'none' to leave them unlit without this warning.${nodes}`;

}
