import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { prepareCaptureScene } from '../../src/capture/prepareCaptureScene.js';
import { CAPTURE_SCENE_DEFAULTS } from '../../src/capture/captureSceneDefaults.js';

// prepareCaptureScene only sets properties (three draws the shadow maps later), so a stand-in
// renderer with a shadowMap is enough: no GL context. What it must do to the scene is checked
// property by property, and restore() against a snapshot taken before.

interface FakeRenderer { isWebGLRenderer: true; getContext(): object; shadowMap: { enabled: boolean; needsUpdate: boolean } }

function fakeRenderer(): FakeRenderer {

	return { isWebGLRenderer: true, getContext: () => ( {} ), shadowMap: { enabled: false, needsUpdate: false } };

}

/** A room-sized scene: the three shadow-casting kinds, ambient and hemisphere, lit, emissive, unlit, hidden and instanced meshes. */
function buildScene() {

	const scene = new THREE.Scene();
	const sun = new THREE.DirectionalLight( 0xffffff, 3 );
	sun.position.set( 3, 10, 2 );
	sun.shadow.mapSize.set( 512, 512 );
	const lamp = new THREE.PointLight( 0xffeedd, 12 );
	lamp.position.set( 0, 2.5, 0 );
	const spot = new THREE.SpotLight( 0xffffff, 5 );
	spot.position.set( 1, 2, 1 );
	spot.shadow.bias = 0.01;
	const off = new THREE.PointLight( 0xffffff, 0 ); // gives no light
	const ambient = new THREE.AmbientLight( 0x404040, 1 );
	const sky = new THREE.HemisphereLight( 0x8080ff, 0x202020, 0.5 );
	const wall = new THREE.MeshStandardMaterial( { color: 0xcccccc } );
	const glow = new THREE.MeshStandardMaterial( { color: 0x000000, emissive: 0xffaa00 } );
	const floor = new THREE.Mesh( new THREE.BoxGeometry( 10, 0.2, 10 ), wall );
	floor.position.set( 2, - 0.1, 0 );
	const shade = new THREE.Mesh( new THREE.BoxGeometry( 0.5, 0.5, 0.5 ), [ glow, wall, wall, wall, wall, wall ] );
	shade.position.set( 0, 2.8, 0 );
	const bulb = new THREE.Mesh( new THREE.SphereGeometry( 0.05, 8, 4 ), new THREE.MeshBasicMaterial( { color: 0xffffff } ) );
	bulb.position.copy( lamp.position );
	const hidden = new THREE.Mesh( new THREE.BoxGeometry(), wall );
	hidden.visible = false;
	const crates = new THREE.InstancedMesh( new THREE.BoxGeometry( 0.4, 0.4, 0.4 ), new THREE.MeshPhongMaterial(), 3 );
	for ( let i = 0; i < 3; i ++ ) crates.setMatrixAt( i, new THREE.Matrix4().makeTranslation( - 2 + i, 0.2, 1 ) );
	scene.add( sun, sun.target, lamp, spot, spot.target, off, ambient, sky, floor, shade, bulb, hidden, crates );
	return { scene, sun, lamp, spot, off, floor, shade, bulb, hidden, crates, wall, glow };

}

/** Every property prepareCaptureScene may touch, as plain values. */
function snapshot( scene: THREE.Object3D, renderer: FakeRenderer ): unknown[] {

	const values: unknown[] = [ renderer.shadowMap.enabled ];
	scene.traverse( ( object ) => {

		const light = object as THREE.DirectionalLight;
		if ( light.isLight && light.shadow ) {

			const c = light.shadow.camera as THREE.OrthographicCamera;
			values.push( light.castShadow, light.shadow.bias, light.shadow.mapSize.x, light.shadow.mapSize.y );
			values.push( c.left, c.right, c.top, c.bottom, c.near, c.far );

		}

		const mesh = object as THREE.Mesh;
		if ( mesh.isMesh ) {

			values.push( mesh.castShadow, mesh.receiveShadow );
			for ( const material of [ mesh.material ].flat() ) values.push( material.shadowSide );

		}

	} );
	return values;

}

describe( 'prepareCaptureScene', () => {

	it( 'defaults: shadows on for every directional/point/spot light (1024², bias −0.0005) and every lit mesh; unlit bulb and hidden mesh left alone; facts counted', () => {

		const renderer = fakeRenderer();
		const s = buildScene();
		const prepared = prepareCaptureScene( renderer as unknown as THREE.WebGLRenderer, s.scene );
		for ( const light of [ s.sun, s.lamp, s.spot ] ) {

			expect( light.castShadow ).toBe( true );
			const size = CAPTURE_SCENE_DEFAULTS.shadowMapSize;
			expect( light.shadow.mapSize.toArray() ).toEqual( [ size, size ] );
			expect( light.shadow.bias ).toBe( - 0.0005 );

		}

		expect( s.off.castShadow ).toBe( false ); // intensity 0: not a light source
		for ( const mesh of [ s.floor, s.shade, s.crates ] ) expect( [ mesh.castShadow, mesh.receiveShadow ] ).toEqual( [ true, true ] );
		expect( [ s.bulb.castShadow, s.bulb.receiveShadow ] ).toEqual( [ false, false ] );
		expect( [ s.hidden.castShadow, s.hidden.receiveShadow ] ).toEqual( [ false, false ] );
		expect( s.wall.shadowSide ).toBe( null ); // doubleSidedShadows is off by default
		expect( renderer.shadowMap.enabled ).toBe( true );

		expect( prepared.meshes ).toBe( 4 ); // floor, shade, bulb, crates (hidden is not drawn)
		// Boxes have 12 triangles, the 8 × 4 sphere 8·4·2 − 2·8 = 48; the crates are 3 instances.
		expect( prepared.triangles ).toBe( 12 + 12 + 48 + 3 * 12 );
		expect( prepared.lights.map( ( entry ) => entry.kind ).sort() ).toEqual( [ 'ambient', 'directional', 'hemisphere', 'point', 'spot' ] );
		expect( prepared.lights.find( ( entry ) => entry.kind === 'point' )!.light ).toBe( s.lamp );
		expect( prepared.emissiveMaterials ).toBe( 1 );
		expect( prepared.unlitMaterials ).toBe( 1 );
		expect( prepared.shadowLights ).toBe( 3 );
		expect( prepared.shadowMeshes ).toBe( 3 );
		expect( prepared.doubleSidedMaterials ).toBe( 0 );
		expect( prepared.nonFiniteVertices ).toBe( 0 );

	} );

	it( 'restore() puts back every property it changed, asks for a shadow redraw, and does nothing the second time', () => {

		const renderer = fakeRenderer();
		const s = buildScene();
		const before = snapshot( s.scene, renderer );
		const prepared = prepareCaptureScene( renderer as unknown as THREE.WebGLRenderer, s.scene, { doubleSidedShadows: true } );
		expect( s.wall.shadowSide ).toBe( THREE.DoubleSide );
		expect( prepared.doubleSidedMaterials ).toBe( 3 ); // wall, glow, the crates' Phong material
		expect( snapshot( s.scene, renderer ) ).not.toEqual( before );
		prepared.restore();
		expect( snapshot( s.scene, renderer ) ).toEqual( before );
		expect( renderer.shadowMap.needsUpdate ).toBe( true );
		renderer.shadowMap.needsUpdate = false;
		s.sun.castShadow = true; // the game's own change after restore() must survive a second call
		prepared.restore();
		expect( s.sun.castShadow ).toBe( true );
		expect( renderer.shadowMap.needsUpdate ).toBe( false );

	} );

	it( 'the fitted directional shadow camera, placed by three\'s own LightShadow.updateMatrices, holds every lit mesh\'s bounds', () => {

		const renderer = fakeRenderer();
		const s = buildScene();
		prepareCaptureScene( renderer as unknown as THREE.WebGLRenderer, s.scene );
		s.sun.shadow.updateMatrices( s.sun );
		const camera = s.sun.shadow.camera;
		const box = new THREE.Box3();
		for ( const mesh of [ s.floor, s.shade, s.crates ] ) box.union( new THREE.Box3().setFromObject( mesh ) );
		const corner = new THREE.Vector3();
		for ( let i = 0; i < 8; i ++ ) {

			corner.set( i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z );
			corner.applyMatrix4( camera.matrixWorldInverse );
			expect( corner.x ).toBeGreaterThanOrEqual( camera.left - 1e-9 );
			expect( corner.x ).toBeLessThanOrEqual( camera.right + 1e-9 );
			expect( corner.y ).toBeGreaterThanOrEqual( camera.bottom - 1e-9 );
			expect( corner.y ).toBeLessThanOrEqual( camera.top + 1e-9 );
			expect( - corner.z ).toBeGreaterThanOrEqual( camera.near - 1e-9 );
			expect( - corner.z ).toBeLessThanOrEqual( camera.far + 1e-9 );

		}

		// Not the default ±5 frustum: the 10 m floor alone is wider than that.
		expect( camera.right - camera.left ).toBeGreaterThan( 10 );

	} );

	it( 'options switch each change off: shadows false changes nothing; null map size / bias keep the light\'s; fitShadowCameras false keeps the camera', () => {

		const renderer = fakeRenderer();
		const s = buildScene();
		s.sun.castShadow = true;
		const before = snapshot( s.scene, renderer );
		const off = prepareCaptureScene( renderer as unknown as THREE.WebGLRenderer, s.scene, { shadows: false } );
		expect( snapshot( s.scene, renderer ) ).toEqual( before );
		expect( off.shadowLights ).toBe( 1 ); // the sun, as the scene has it
		expect( off.shadowMeshes ).toBe( 0 );
		off.restore();
		expect( renderer.shadowMap.needsUpdate ).toBe( false );

		const camera = s.sun.shadow.camera;
		const frustum = [ camera.left, camera.right, camera.top, camera.bottom, camera.near, camera.far ];
		const r = renderer as unknown as THREE.WebGLRenderer;
		const kept = prepareCaptureScene( r, s.scene, { shadowMapSize: null, shadowBias: null, fitShadowCameras: false } );
		expect( s.sun.shadow.mapSize.x ).toBe( 512 );
		expect( s.spot.shadow.bias ).toBe( 0.01 );
		expect( [ camera.left, camera.right, camera.top, camera.bottom, camera.near, camera.far ] ).toEqual( frustum );
		expect( s.lamp.castShadow ).toBe( true );
		kept.restore();

		const custom = prepareCaptureScene( r, s.scene, { shadowMapSize: 256, shadowBias: - 0.002 } );
		expect( s.lamp.shadow.mapSize.toArray() ).toEqual( [ 256, 256 ] );
		expect( s.lamp.shadow.bias ).toBe( - 0.002 );
		custom.restore();

	} );

	it( 'a shadow map already drawn at another size is disposed (three would keep its old size), also on restore', () => {

		const renderer = fakeRenderer();
		const s = buildScene();
		let disposed = 0;
		const map = { dispose: () => { disposed ++; } } as unknown as THREE.WebGLRenderTarget;
		s.sun.shadow.map = map;
		const prepared = prepareCaptureScene( renderer as unknown as THREE.WebGLRenderer, s.scene );
		expect( disposed ).toBe( 1 );
		expect( s.sun.shadow.map ).toBe( null );
		s.sun.shadow.map = map; // what three draws during the capture
		prepared.restore();
		expect( disposed ).toBe( 2 );
		expect( s.sun.shadow.map ).toBe( null );
		expect( s.sun.shadow.mapSize.x ).toBe( 512 );

	} );

	it( 'counts vertices with a NaN or infinite coordinate; a scene without lights has no shadow changes', () => {

		const renderer = fakeRenderer();
		const scene = new THREE.Scene();
		const positions = [ 0, 0, 0, 1, 0, 0, 0, NaN, 1, Infinity, 0, 0, 0, 1, 0, 0, 0, 1 ];
		const geometry = new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( positions, 3 ) );
		scene.add( new THREE.Mesh( geometry, new THREE.MeshStandardMaterial() ) );
		const prepared = prepareCaptureScene( renderer as unknown as THREE.WebGLRenderer, scene );
		expect( prepared.nonFiniteVertices ).toBe( 2 );
		expect( prepared.triangles ).toBe( 2 );
		expect( prepared.lights ).toEqual( [] );
		expect( prepared.shadowMeshes ).toBe( 0 );
		expect( renderer.shadowMap.enabled ).toBe( false );

	} );

	it( 'bad renderer, scene or options throw naming prepareCaptureScene and change nothing', () => {

		const renderer = fakeRenderer();
		const s = buildScene();
		const before = snapshot( s.scene, renderer );
		const r = renderer as unknown as THREE.WebGLRenderer;
		const cases: [ () => unknown, RegExp ][] = [
			[ () => prepareCaptureScene( {} as THREE.WebGLRenderer, s.scene ), /^prepareCaptureScene: renderer must be a three\.js WebGLRenderer/ ],
			[ () => prepareCaptureScene( r, null as unknown as THREE.Scene ), /^prepareCaptureScene: scene must be a three\.js Scene/ ],
			[ () => prepareCaptureScene( r, s.scene, { shadowmapsize: 512 } as never ), /^prepareCaptureScene: unknown option "shadowmapsize"/ ],
			[ () => prepareCaptureScene( r, s.scene, { shadowMapSize: 0 } ), /^prepareCaptureScene: options\.shadowMapSize must be an integer in 1\.\.16384, got 0/ ],
			[ () => prepareCaptureScene( r, s.scene, { shadowMapSize: 1.5 } ), /options\.shadowMapSize must be an integer/ ],
			[ () => prepareCaptureScene( r, s.scene, { shadowBias: NaN } ), /^prepareCaptureScene: options\.shadowBias must be a finite number, got NaN/ ],
			[ () => prepareCaptureScene( r, s.scene, { shadows: 'yes' } as never ), /^prepareCaptureScene: options\.shadows must be true or false/ ],
			[ () => prepareCaptureScene( r, s.scene, [] as never ), /^prepareCaptureScene: options must be an object/ ],
		];
		for ( const [ call, message ] of cases ) {

			expect( call ).toThrow( message );
			expect( snapshot( s.scene, renderer ) ).toEqual( before );

		}

	} );

} );
