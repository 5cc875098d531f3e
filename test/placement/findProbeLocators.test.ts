import { describe, expect, it } from 'vitest';
import { BoxGeometry, Group, Mesh, MeshBasicMaterial, Object3D, Vector3 } from 'three';
import { GLTFLoader, type GLTF } from 'three/addons/loaders/GLTFLoader.js';
import { findProbeLocators } from '../../src/placement/findProbeLocators.js';

/** Parses a glTF given as JSON with three's GLTFLoader (no buffers or textures: runs without a DOM). */
function parseGLTF( json: object ): Promise<GLTF> {

	return new Promise( ( resolve, reject ) => new GLTFLoader().parse( JSON.stringify( json ), '', resolve, reject ) );

}

describe( 'findProbeLocators', () => {

	it( 'finds objects named probe* or tagged userData.probe, at world positions, with roles from userData, name or default', () => {

		// A rotated, translated, scaled parent: world = T · R · S · local, worked out by hand below.
		const root = new Group();
		const rig = new Group();
		rig.position.set( 10, 0, 0 );
		rig.rotation.y = Math.PI / 2; // (x, y, z) → (z, y, −x)
		rig.scale.setScalar( 2 );
		root.add( rig );

		const sky = new Object3D(); sky.name = 'probe_sky_01'; sky.position.set( 1, 2, 3 ); rig.add( sky );
		const lamp = new Object3D(); lamp.name = 'Lamp'; lamp.userData.probe = { role: 'bounce' }; lamp.position.set( 0, 1, 0 ); root.add( lamp );
		const bleed = new Object3D(); bleed.name = 'PROBE-Bleed.003'; root.add( bleed );
		const camel = new Object3D(); camel.name = 'probeBounceLow'; root.add( camel );
		const plain = new Object3D(); plain.name = 'probe'; root.add( plain );
		const overridden = new Object3D(); overridden.name = 'probe_sky_02'; overridden.userData.probe = { role: 'fill' }; root.add( overridden );
		const shorthand = new Object3D(); shorthand.name = 'marker'; shorthand.userData.probe = 'Sky'; root.add( shorthand );
		const excluded = new Object3D(); excluded.name = 'probe_disabled'; excluded.userData.probe = false; root.add( excluded );
		const unrelated = new Mesh( new BoxGeometry(), new MeshBasicMaterial() ); unrelated.name = 'wall'; root.add( unrelated );
		const notPrefix = new Object3D(); notPrefix.name = 'myprobe'; root.add( notPrefix );
		// A helper mesh under a locator, itself named probe…: the locator's descendants are not searched.
		const helper = new Mesh( new BoxGeometry(), new MeshBasicMaterial() ); helper.name = 'probe_sky_01_helper'; sky.add( helper );

		const found = findProbeLocators( root );
		expect( found.names ).toEqual( [ 'probe_sky_01', 'Lamp', 'PROBE-Bleed.003', 'probeBounceLow', 'probe', 'probe_sky_02', 'marker' ] );
		expect( found.roles ).toEqual( [ 'sky', 'bounce', 'bleed', 'bounce', 'fill', 'fill', 'sky' ] );
		expect( found.positions ).toBeInstanceOf( Float64Array );
		// sky: local (1, 2, 3) · 2 = (2, 4, 6), rotated → (6, 4, −2), + (10, 0, 0) → (16, 4, −2).
		expect( found.positions[ 0 ] ).toBeCloseTo( 16, 12 );
		expect( found.positions[ 1 ] ).toBeCloseTo( 4, 12 );
		expect( found.positions[ 2 ] ).toBeCloseTo( - 2, 12 );
		expect( Array.from( found.positions.subarray( 3, 6 ) ) ).toEqual( [ 0, 1, 0 ] );

	} );

	it( 'reads world matrices even when they were never updated (a scene just built)', () => {

		const root = new Group(); root.position.set( 0, 5, 0 );
		const probe = new Object3D(); probe.name = 'probe_a'; probe.position.set( 1, 0, 0 ); root.add( probe );
		// No updateMatrixWorld() call: a stale identity matrixWorld would give (0, 0, 0).
		expect( Array.from( findProbeLocators( root ).positions ) ).toEqual( [ 1, 5, 0 ] );

	} );

	it( 'returns empty arrays for a scene without locators', () => {

		const found = findProbeLocators( new Group().add( new Object3D() ) );
		expect( found.positions.length ).toBe( 0 );
		expect( found.names ).toEqual( [] );
		expect( found.roles ).toEqual( [] );

	} );

	it( 'rejects an unknown role in userData and a non-Object3D root, naming the function', () => {

		const root = new Group();
		const typo = new Object3D(); typo.name = 'probe_7'; typo.userData.probe = { role: 'skylight' }; root.add( typo );
		expect( () => findProbeLocators( root ) ).toThrow( /^findProbeLocators: object "probe_7" has userData.probe role "skylight"; expected one of sky, bounce, bleed, fill/ );
		expect( () => findProbeLocators( {} as Object3D ) ).toThrow( /^findProbeLocators: root must be a three.js Object3D/ );

	} );

	it( 'finds locators in a glTF parsed by GLTFLoader: node extras arrive as userData, transforms compose', async () => {

		// What Blender exports for empties with custom properties ("Include → Custom Properties"):
		// nodes with names, TRS and `extras`. The parent is translated and rotated 90° about y
		// (quaternion [0, sin 45°, 0, cos 45°]).
		const s = Math.SQRT1_2;
		const gltf = await parseGLTF( {
			asset: { version: '2.0', generator: 'three-capture-lighting test' },
			scene: 0,
			scenes: [ { nodes: [ 0, 1, 2, 3 ] } ],
			nodes: [
				{ name: 'probe_sky_01', translation: [ 0, 12, 0 ] },
				{ name: 'Room', translation: [ 5, 0, 0 ], rotation: [ 0, s, 0, s ], children: [ 4, 5 ] },
				{ name: 'Lamp', translation: [ 1, 1, 1 ], extras: { probe: { role: 'bleed' }, note: 'red wall' } },
				{ name: 'Camera target', translation: [ 0, 0, 0 ] },
				{ name: 'Probe Bounce.001', translation: [ 2, 0.5, 0 ] },
				{ name: 'tagged', translation: [ 0, 1, - 3 ], extras: { probe: {} } },
			],
		} );

		const lamp = gltf.scene.getObjectByName( 'Lamp' )!;
		// (GLTFLoader also keeps the unsanitized node name in userData.name.)
		expect( lamp.userData ).toMatchObject( { probe: { role: 'bleed' }, note: 'red wall' } );

		const found = findProbeLocators( gltf.scene );
		// GLTFLoader sanitizes names for animation bindings: spaces → "_", "." removed.
		expect( found.names ).toEqual( [ 'probe_sky_01', 'Probe_Bounce001', 'tagged', 'Lamp' ] );
		expect( found.roles ).toEqual( [ 'sky', 'bounce', 'fill', 'bleed' ] );
		// Children of Room: (x, y, z) → (z, y, −x) + (5, 0, 0).
		const expected = [ new Vector3( 0, 12, 0 ), new Vector3( 5, 0.5, - 2 ), new Vector3( 2, 1, 0 ), new Vector3( 1, 1, 1 ) ];
		expected.forEach( ( v, i ) => {

			expect( found.positions[ 3 * i ] ).toBeCloseTo( v.x, 6 );
			expect( found.positions[ 3 * i + 1 ] ).toBeCloseTo( v.y, 6 );
			expect( found.positions[ 3 * i + 2 ] ).toBeCloseTo( v.z, 6 );

		} );

	} );

} );
