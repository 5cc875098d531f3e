/**
 * Which materials take probe light, and what `add()` does with the others (no GL context: the
 * shading itself is checked against three's LightProbe in phongLambert.gpu.test.ts).
 *
 * - Standard, Physical, Phong, Lambert and Toon are patched, by `add( object )`, `add( scene )`
 *   and the large-object lightings alike.
 * - Node materials copy `isMeshStandardMaterial` from the material they mirror but never run
 *   onBeforeCompile: they must not be taken for patchable ones.
 * - `add( scene )` warns once per call for meshes whose shaders are their own (ShaderMaterial,
 *   RawShaderMaterial, node materials), and passes unlit built-ins (MeshBasicMaterial lamps) silently.
 * - `add( object )` of an object whose materials all take no probe light is a named TypeError.
 */

import { afterEach, describe, expect, it, vi } from 'vitest';
import * as THREE from 'three';
import { MeshBasicNodeMaterial, MeshStandardNodeMaterial } from 'three/webgpu';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { ProbeTextureLighting } from '../../src/runtime/ProbeTextureLighting.js';
import { ProbeVertexLighting } from '../../src/runtime/ProbeVertexLighting.js';
import { getProbeVolumeUniforms, patchMaterial, unpatchMaterial } from '../../src/runtime/patchMaterial.js';
import { isProbeLitMaterial } from '../../src/runtime/probeLitMaterials.js';

/** Probes on a 3 × 3 × 3 grid over [−4, 4]³ (spacing 4), a sky-like SH in each. */
function gridVolume(): LightProbeVolume {

	const positions: number[] = [];
	for ( const x of [ - 4, 0, 4 ] ) for ( const y of [ - 4, 0, 4 ] ) for ( const z of [ - 4, 0, 4 ] ) positions.push( x, y, z );
	const sh = new Float32Array( positions.length * 9 );
	for ( let i = 0; i < positions.length / 3; i ++ ) sh.set( [ 1, 0.9, 0.8, 0.3, 0.3, 0.4 ], 27 * i );
	return new LightProbeVolume( { positions, sh } );

}

function mesh<M extends THREE.Material | THREE.Material[]>( name: string, material: M, geometry?: THREE.BufferGeometry ) {

	const result = new THREE.Mesh( geometry ?? new THREE.BoxGeometry( 0.5, 0.5, 0.5 ), material );
	result.name = name;
	return result;

}

/** The uniforms of source 'texture' (patchMaterial needs them given). */
function textureUniforms() {

	return {
		probeVolumeMatrices: { value: new Float32Array( 48 ) }, probeVolumeIntensity: { value: 1 }, probeVolumeDirectScale: { value: 1 },
		probeVolumeSH: { value: null }, probeVolumeGridMin: { value: new THREE.Vector3() },
		probeVolumeGridMax: { value: new THREE.Vector3( 1, 1, 1 ) }, probeVolumeGridResolution: { value: new THREE.Vector3( 2, 2, 2 ) },
	};

}

const shader = () => new THREE.ShaderMaterial( { vertexShader: 'void main() { gl_Position = vec4( 0.0 ); }', fragmentShader: 'void main() {}' } );
const rawShader = () => new THREE.RawShaderMaterial( { vertexShader: 'void main() {}', fragmentShader: 'void main() {}' } );

afterEach( () => {

	vi.restoreAllMocks();

} );

describe( 'isProbeLitMaterial', () => {

	it( 'Standard, Physical, Phong, Lambert and Toon: yes; unlit built-ins, shader and node materials (which claim isMeshStandardMaterial): no', () => {

		const yes = [
			new THREE.MeshStandardMaterial(), new THREE.MeshPhysicalMaterial(), new THREE.MeshPhongMaterial(),
			new THREE.MeshLambertMaterial(), new THREE.MeshToonMaterial(),
		];
		const no = [
			new THREE.MeshBasicMaterial(), new THREE.MeshNormalMaterial(), new THREE.MeshMatcapMaterial(), new THREE.MeshDepthMaterial(),
			new THREE.MeshDistanceMaterial(), new THREE.ShadowMaterial(), shader(), rawShader(), new THREE.LineBasicMaterial(),
			new THREE.PointsMaterial(), new MeshStandardNodeMaterial(), new MeshBasicNodeMaterial(),
		];
		// The trap the node check is for: a node material looks like a MeshStandardMaterial.
		expect( ( new MeshStandardNodeMaterial() as unknown as { isMeshStandardMaterial: boolean } ).isMeshStandardMaterial ).toBe( true );
		const table = ( materials: THREE.Material[] ) => materials.map( ( material ) => [ material.type, isProbeLitMaterial( material ) ] );
		expect( table( yes ) ).toEqual( yes.map( ( material ) => [ material.type, true ] ) );
		expect( table( no ) ).toEqual( no.map( ( material ) => [ material.type, false ] ) );
		expect( [ null, undefined, {}, 3 ].some( ( value ) => isProbeLitMaterial( value ) ) ).toBe( false );

	} );

} );

describe( 'patchMaterial on Phong, Lambert and Toon', () => {

	it( 'patches them (program key per variant, uniforms returned) and refuses a node material with a named TypeError, leaving it untouched', () => {

		for ( const material of [ new THREE.MeshPhongMaterial(), new THREE.MeshLambertMaterial(), new THREE.MeshToonMaterial() ] ) {

			const key = material.customProgramCacheKey();
			const uniforms = patchMaterial( material, { perVertex: true } );
			expect( getProbeVolumeUniforms( material ) ).toBe( uniforms );
			expect( material.customProgramCacheKey() ).toBe( `${key}|three-capture-lighting:1:vertex` );
			unpatchMaterial( material );
			expect( material.customProgramCacheKey() ).toBe( key );

		}

		const node = new MeshStandardNodeMaterial();
		const hook = node.onBeforeCompile;
		expect( () => patchMaterial( node ) ).toThrow( /^patchMaterial: material must be a MeshStandardMaterial, MeshPhysicalMaterial, MeshPhongMaterial, MeshLambertMaterial or MeshToonMaterial, got MeshStandardNodeMaterial\.$/ );
		expect( node.onBeforeCompile ).toBe( hook );
		expect( getProbeVolumeUniforms( node ) ).toBeNull();

	} );

	it( 'the patch finds its chunks in three\'s own Phong, Lambert and Toon shaders, for every variant', () => {

		// What three hands onBeforeCompile: the ShaderLib sources with their #include lines.
		const libraries = { MeshPhongMaterial: 'phong', MeshLambertMaterial: 'lambert', MeshToonMaterial: 'toon' } as const;
		for ( const [ type, library ] of Object.entries( libraries ) ) {

			for ( const options of [ {}, { perVertex: true }, { source: 'vertexIrradiance' }, { source: 'vertexSH' }, { source: 'texture' } ] as const ) {

				const material = new ( THREE as unknown as Record<string, new () => THREE.Material> )[ type ]();
				const uniforms = patchMaterial( material, options.source === 'texture' ? { source: 'texture', uniforms: textureUniforms() } : options );
				const { vertexShader, fragmentShader } = THREE.ShaderLib[ library ];
				const shader = { vertexShader, fragmentShader, uniforms: {} } as unknown as THREE.WebGLProgramParametersWithUniforms;
				material.onBeforeCompile( shader, null as unknown as THREE.WebGLRenderer );
				const what = `${type} ${JSON.stringify( options )}`;
				expect( shader.uniforms.probeVolumeIntensity, what ).toBe( uniforms.probeVolumeIntensity );
				// The probe term is added to `irradiance` after lights_fragment_begin and before lights_fragment_end.
				const fragment = shader.fragmentShader;
				const begin = fragment.indexOf( '#include <lights_fragment_begin>' ), end = fragment.indexOf( '#include <lights_fragment_end>' );
				const added = fragment.indexOf( 'irradiance +=', begin );
				expect( begin, what ).toBeGreaterThan( 0 );
				expect( added > begin && added < end, what ).toBe( true );
				expect( fragment.indexOf( 'reflectedLight.directDiffuse *= probeVolumeDirectScale', begin ), what ).toBeGreaterThan( begin );

			}

		}

	} );

} );

describe( 'add( scene ): materials that take no probe light', () => {

	it( 'a level of Phong and Lambert meshes (as OBJLoader / MTLLoader make them) is lit; the MeshBasicMaterial bulb is skipped without a warning', () => {

		const warn = vi.spyOn( console, 'warn' ).mockImplementation( () => {} );
		const scene = new THREE.Scene();
		const floor = mesh( 'floor', new THREE.MeshPhongMaterial(), new THREE.PlaneGeometry( 10, 10 ).rotateX( - Math.PI / 2 ) );
		const crate = mesh( 'crate', new THREE.MeshLambertMaterial() );
		const statue = mesh( 'statue', new THREE.MeshToonMaterial() );
		const bulb = mesh( 'bulb', new THREE.MeshBasicMaterial(), new THREE.SphereGeometry( 0.1 ) );
		const bulbMaterial = bulb.material;
		scene.add( floor, crate, statue, bulb );
		const volume = gridVolume();
		volume.add( scene );
		expect( volume.getLighting( floor ) ).toBe( 'texture' );
		expect( volume.getLighting( crate ) ).toBe( 'object' );
		expect( getProbeVolumeUniforms( crate.material ) ).toBe( volume.getUniforms( crate ) );
		expect( volume.getLighting( statue ) ).toBe( 'object' );
		expect( volume.getLighting( bulb ) ).toBeNull();
		expect( bulb.material ).toBe( bulbMaterial );
		expect( getProbeVolumeUniforms( bulbMaterial ) ).toBeNull();
		expect( warn ).not.toHaveBeenCalled();
		volume.dispose();

	} );

	it( 'meshes with ShaderMaterial, RawShaderMaterial or a node material: one console.warn per call, with the count, the types and names, and what to do', () => {

		const warn = vi.spyOn( console, 'warn' ).mockImplementation( () => {} );
		const scene = new THREE.Scene();
		const lit = mesh( 'floor', new THREE.MeshPhongMaterial() );
		const sky = mesh( 'sky', shader() ), water = mesh( 'water', shader() ), terrain = mesh( 'terrain', rawShader() );
		const grass = mesh( 'grass', new MeshStandardNodeMaterial() as unknown as THREE.Material );
		const bulb = mesh( 'bulb', new THREE.MeshBasicMaterial() ); // meant to be unlit: not counted
		const decal = mesh( 'decal', [ new THREE.MeshLambertMaterial(), shader() ] ); // lit through its Lambert slot: not counted
		const gizmo = mesh( 'gizmo', shader() );
		gizmo.userData.probeLighting = 'none'; // marked: not counted
		scene.add( lit, sky, water, terrain, grass, bulb, decal, gizmo );
		const volume = gridVolume();
		volume.add( scene );
		expect( warn ).toHaveBeenCalledTimes( 1 );
		const message = String( warn.mock.calls[ 0 ][ 0 ] );
		expect( message ).toMatch( /^LightProbeVolume\.add: 4 meshes \("sky", "water", "terrain", …\) with ShaderMaterial ×2, RawShaderMaterial ×1, MeshStandardNodeMaterial ×1 get no probe light/ );
		expect( message ).toMatch( /only MeshStandardMaterial, MeshPhysicalMaterial, MeshPhongMaterial, MeshLambertMaterial or MeshToonMaterial take it/ );
		expect( message ).toMatch( /userData\.probeLighting = 'none'/ );
		expect( message ).not.toMatch( /MeshBasicMaterial|bulb|decal|gizmo/ );
		expect( volume.getLighting( lit ) ).toBe( 'object' );
		expect( volume.getLighting( decal ) ).toBe( 'object' );
		for ( const skipped of [ sky, water, terrain, grass, bulb, gizmo ] ) {

			expect( volume.getLighting( skipped ), skipped.name ).toBeNull();

		}

		// Another add( scene ) leaves them again: one more warning, for that call.
		volume.add( scene );
		expect( warn ).toHaveBeenCalledTimes( 2 );
		volume.dispose();

	} );

	it( 'one such mesh, unnamed, inside a group marked \'object\': counted, in the singular', () => {

		const warn = vi.spyOn( console, 'warn' ).mockImplementation( () => {} );
		const scene = new THREE.Scene();
		const cart = new THREE.Group();
		cart.userData.probeLighting = 'object';
		cart.add( mesh( 'body', new THREE.MeshPhongMaterial() ), new THREE.Mesh( new THREE.BoxGeometry(), shader() ) );
		scene.add( cart );
		const volume = gridVolume();
		volume.add( scene );
		expect( volume.getLighting( cart ) ).toBe( 'object' );
		expect( warn ).toHaveBeenCalledTimes( 1 );
		expect( String( warn.mock.calls[ 0 ][ 0 ] ) ).toMatch( /^LightProbeVolume\.add: 1 mesh with ShaderMaterial ×1 gets no probe light/ );
		volume.dispose();

	} );

	it( 'a bad mark fails the call before any warning', () => {

		const warn = vi.spyOn( console, 'warn' ).mockImplementation( () => {} );
		const scene = new THREE.Scene();
		const typo = mesh( 'typo', new THREE.MeshPhongMaterial() );
		typo.userData.probeLighting = 'vertx';
		scene.add( mesh( 'sky', shader() ), typo );
		const volume = gridVolume();
		expect( () => volume.add( scene ) ).toThrow( /^LightProbeVolume\.add: userData\.probeLighting of "typo"/ );
		expect( warn ).not.toHaveBeenCalled();
		volume.dispose();

	} );

} );

describe( 'add( object ) of what takes no probe light', () => {

	it( 'a mesh or group whose materials all take none: a TypeError naming it and its material types; nothing changed', () => {

		const volume = gridVolume();
		const bulb = mesh( 'bulb', new THREE.MeshBasicMaterial() );
		const material = bulb.material;
		expect( () => volume.add( bulb ) ).toThrow( /^LightProbeVolume\.add: "bulb" has only MeshBasicMaterial; probe light needs a mesh with a MeshStandardMaterial, MeshPhysicalMaterial, MeshPhongMaterial, MeshLambertMaterial or MeshToonMaterial/ );
		expect( volume.getLighting( bulb ) ).toBeNull();
		expect( bulb.material ).toBe( material );
		const effects = new THREE.Group().add( mesh( 'sky', shader() ), mesh( 'glow', new THREE.MeshBasicMaterial() ) );
		effects.name = 'effects';
		for ( const mode of [ 'object', 'vertex', 'texture' ] as const ) {

			expect( () => volume.add( effects, { mode } ), mode ).toThrow( /^LightProbeVolume\.add: "effects" has only ShaderMaterial, MeshBasicMaterial; / );

		}

		expect( volume.getLighting( effects ) ).toBeNull();
		volume.dispose();

	} );

	it( 'a group with a Phong body and a Basic bulb: the body is lit in every mode, the bulb left as it is', () => {

		for ( const mode of [ 'object', 'vertex', 'texture' ] as const ) {

			const volume = gridVolume();
			const body = mesh( 'body', new THREE.MeshPhongMaterial() );
			const bulb = mesh( 'bulb', new THREE.MeshBasicMaterial() );
			const lamp = new THREE.Group().add( body, bulb );
			const bodyMaterial = body.material, bulbMaterial = bulb.material;
			volume.add( lamp, { mode } );
			expect( volume.getLighting( lamp ), mode ).toBe( mode === 'object' ? 'dynamic' : mode );
			expect( getProbeVolumeUniforms( body.material as THREE.Material ), mode ).not.toBeNull();
			expect( bulb.material, mode ).toBe( bulbMaterial );
			expect( getProbeVolumeUniforms( bulbMaterial ), mode ).toBeNull();
			expect( bulb.geometry.getAttribute( 'probeIrradiance' ), mode ).toBeUndefined();
			volume.dispose();
			expect( body.material, mode ).toBe( bodyMaterial );
			expect( getProbeVolumeUniforms( bodyMaterial ), mode ).toBeNull();

		}

	} );

	it( 'ProbeVertexLighting and ProbeTextureLighting take Lambert and Phong; a Basic mesh is a named TypeError listing the materials', () => {

		const volume = gridVolume();
		const lambert = mesh( 'wall', new THREE.MeshLambertMaterial() );
		const vertex = new ProbeVertexLighting( lambert, volume );
		expect( getProbeVolumeUniforms( lambert.material as THREE.Material ) ).toBe( vertex.uniforms );
		vertex.dispose();
		const phong = mesh( 'floor', new THREE.MeshPhongMaterial() );
		const texture = new ProbeTextureLighting( phong, volume );
		expect( getProbeVolumeUniforms( phong.material as THREE.Material ) ).toBe( texture.uniforms );
		texture.dispose();
		const names = 'MeshStandardMaterial, MeshPhysicalMaterial, MeshPhongMaterial, MeshLambertMaterial or MeshToonMaterial';
		expect( () => new ProbeVertexLighting( mesh( 'bulb', new THREE.MeshBasicMaterial() ), volume ) ).toThrow( `ProbeVertexLighting: mesh has no ${names} to light.` );
		expect( () => new ProbeTextureLighting( mesh( 'bulb', new THREE.MeshBasicMaterial() ), volume ) ).toThrow( `ProbeTextureLighting: object has no mesh with a ${names} to light.` );
		volume.dispose();

	} );

} );
