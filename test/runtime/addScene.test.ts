/**
 * `volume.add( scene )`, CPU side: the choice per mesh on a built level, the marks that override
 * it, what remove( scene ) restores, and that scenery is blended when added and again only when
 * it moves or the probes change — counted as interpolator calls, the cost of a blend.
 *
 * The probes lie on a 2 m grid, so the spacing the choice compares with is known exactly (2): a
 * mesh longer than 2 m is large; its triangles must be at most 1 m long to be lit per vertex.
 * Their SH are a linear function of position, which tetrahedral interpolation reproduces exactly
 * inside the hull: the light a mesh gets has an analytic value.
 */

import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { ProbeTextureLighting } from '../../src/runtime/ProbeTextureLighting.js';
import { medianProbeSpacing } from '../../src/runtime/probeSpacing.js';
import { getProbeVolumeUniforms } from '../../src/runtime/patchMaterial.js';
import type { ProbeVolumeUniforms } from '../../src/runtime/patchMaterial.js';

/** SH(p) = A + B·p: every coefficient and channel different. */
function linearSH( x: number, y: number, z: number ): number[] {

	return Array.from( { length: 27 }, ( _, k ) => ( k < 3 ? 1.5 : 0.2 * Math.sin( 1.7 * k ) )
		+ 0.03 * Math.cos( 0.9 * k ) * x + 0.05 * Math.sin( 1.3 * k ) * y + 0.02 * Math.cos( 2.1 * k ) * z );

}

/** Probes every 2 m over [−6, 6] × [0, 4] × [−6, 6]. */
function gridVolume(): LightProbeVolume {

	const positions: number[] = [], sh: number[] = [];
	for ( let x = - 6; x <= 6; x += 2 ) for ( let y = 0; y <= 4; y += 2 ) for ( let z = - 6; z <= 6; z += 2 ) {

		positions.push( x, y, z );
		sh.push( ...linearSH( x, y, z ) );

	}

	return new LightProbeVolume( { positions, sh } );

}

const standard = () => new THREE.MeshStandardMaterial( { roughness: 1 } );

/** A skinned cylinder with its bone, under a group: a character as GLTFLoader gives one. */
function character( name: string ): { root: THREE.Group; mesh: THREE.SkinnedMesh; bone: THREE.Bone } {

	const geometry = new THREE.CylinderGeometry( 0.3, 0.3, 1.6, 16, 8 );
	const count = geometry.getAttribute( 'position' ).count;
	const weights = new Float32Array( 4 * count );
	for ( let i = 0; i < count; i ++ ) weights[ 4 * i ] = 1;
	geometry.setAttribute( 'skinIndex', new THREE.Uint16BufferAttribute( new Uint16Array( 4 * count ), 4 ) );
	geometry.setAttribute( 'skinWeight', new THREE.Float32BufferAttribute( weights, 4 ) );
	const bone = new THREE.Bone();
	const mesh = new THREE.SkinnedMesh( geometry, standard() );
	const root = new THREE.Group();
	root.name = name;
	root.add( bone, mesh );
	mesh.bind( new THREE.Skeleton( [ bone ] ) );
	return { root, mesh, bone };

}

/** The level of the choice tests; every mesh named. */
function level() {

	const scene = new THREE.Scene();
	const mesh = ( name: string, geometry: THREE.BufferGeometry, material: THREE.Material = standard() ) => {

		const object = new THREE.Mesh( geometry, material );
		object.name = name;
		return object;

	};

	// 10 × 10 m of two triangles: large, and its triangles (14 m diagonal) far too long for per-vertex light.
	const floor = mesh( 'floor', new THREE.PlaneGeometry( 10, 10 ).rotateX( - Math.PI / 2 ) );
	// 10 × 3 m in 40 × 12 quads: triangles 0.35 m long at most, under half the 2 m spacing.
	const wall = mesh( 'wall', new THREE.PlaneGeometry( 10, 3, 40, 12 ) );
	wall.position.set( 0, 1.5, - 5 );
	// The same wall in 4 × 1 quads (3.2 m triangles): large but coarse.
	const coarseWall = mesh( 'coarseWall', new THREE.PlaneGeometry( 10, 3, 4, 1 ) );
	coarseWall.position.set( 0, 1.5, 5 );
	coarseWall.rotation.y = Math.PI;
	const crate = mesh( 'crate', new THREE.BoxGeometry( 0.5, 0.5, 0.5 ) );
	crate.position.set( 1, 0.25, 1 );
	const lamp = mesh( 'lamp', new THREE.SphereGeometry( 0.2 ), new THREE.MeshBasicMaterial() );
	lamp.position.set( 0, 3, 0 );
	// Large, but marked by the artist (glTF extras) to be one blend; and a helper not to be lit.
	const bigProp = mesh( 'bigProp', new THREE.BoxGeometry( 3, 1, 1 ) );
	bigProp.position.set( - 3, 0.5, - 2 );
	bigProp.userData.probeLighting = 'object';
	const gizmo = mesh( 'gizmo', new THREE.BoxGeometry( 0.2, 0.2, 0.2 ) );
	gizmo.userData.probeLighting = 'none';
	const statue = mesh( 'statue', new THREE.BoxGeometry( 0.5, 1.5, 0.5 ) );
	statue.position.set( 3, 0.75, 2 );
	const hero = character( 'hero' );
	hero.root.position.set( - 1, 0, 2 );
	// A sword in the hero's hand (below the bone): moves with the rig.
	const sword = mesh( 'sword', new THREE.BoxGeometry( 0.05, 0.8, 0.05 ) );
	hero.bone.add( sword );
	scene.add( floor, wall, coarseWall, crate, lamp, bigProp, gizmo, statue, hero.root );
	scene.updateMatrixWorld( true );
	return { scene, floor, wall, coarseWall, crate, lamp, bigProp, gizmo, statue, hero, sword };

}

/** Counts the interpolator calls of a volume (a blend locates once; a texture resample once per node). */
function countLocates( volume: LightProbeVolume ): { readonly calls: number; reset(): void } {

	const interpolator = volume.interpolator;
	const original = interpolator.interpolate.bind( interpolator );
	let calls = 0;
	interpolator.interpolate = ( ...args ) => { calls ++; return original( ...args ); };
	return { get calls() { return calls; }, reset() { calls = 0; } };

}

describe( 'LightProbeVolume.probeSpacing: the median nearest-probe distance', () => {

	/** Brute force: every pair. */
	function bruteForce( points: number[], active: ( i: number ) => boolean = () => true ): number {

		const ids = [ ...Array( points.length / 3 ).keys() ].filter( active );
		const nearest = ids.map( ( i ) => Math.min( ...ids.filter( ( j ) => j !== i ).map( ( j ) => Math.hypot(
			points[ 3 * i ] - points[ 3 * j ], points[ 3 * i + 1 ] - points[ 3 * j + 1 ], points[ 3 * i + 2 ] - points[ 3 * j + 2 ] ) ) ) );
		nearest.sort( ( a, b ) => a - b );
		const m = nearest.length >> 1;
		return nearest.length % 2 ? nearest[ m ] : ( nearest[ m - 1 ] + nearest[ m ] ) / 2;

	}

	it( 'equals brute force on random clouds, clusters, flat and collinear layouts, and with probes left out', () => {

		let seed = 7;
		const random = () => ( seed = ( seed * 16807 ) % 2147483647 ) / 2147483647;
		const layouts: number[][] = [];
		layouts.push( Array.from( { length: 3 * 500 }, () => 20 * random() - 10 ) ); // cloud
		layouts.push( Array.from( { length: 3 * 300 }, ( _, k ) => ( k % 3 === 1 ? 2 : 40 * random() ) ) ); // flat (y = 2)
		layouts.push( Array.from( { length: 3 * 101 }, ( _, k ) => ( k % 3 === 0 ? 7 * random() : 1 ) ) ); // a line
		// Two far clusters of very different density.
		const dense = Array.from( { length: 3 * 200 }, () => random() );
		const sparse = Array.from( { length: 3 * 50 }, () => 100 + 30 * random() );
		layouts.push( [ ...dense, ...sparse ] );
		for ( const points of layouts ) expect( medianProbeSpacing( points ) ).toBeCloseTo( bruteForce( points ), 12 );
		const odd = ( i: number ) => i % 3 !== 0;
		expect( medianProbeSpacing( layouts[ 0 ], odd ) ).toBeCloseTo( bruteForce( layouts[ 0 ], odd ), 12 );

	} );

	it( 'a 2 m grid gives 2; duplicates count once; fewer than two distinct probes give Infinity; edits recompute it', () => {

		const volume = gridVolume();
		expect( volume.probeSpacing ).toBeCloseTo( 2, 12 );
		expect( medianProbeSpacing( [ 0, 0, 0, 0, 0, 0, 3, 0, 0 ] ) ).toBe( 3 );
		expect( medianProbeSpacing( [ 1, 2, 3, 1, 2, 3 ] ) ).toBe( Infinity );
		expect( medianProbeSpacing( [ 1, 2, 3 ] ) ).toBe( Infinity );
		// Halving the grid step along x in one row of probes changes the median only when many move:
		// move every probe of x = 6 to x = 5, so 35 of 105 probes get a neighbour at 1 m.
		for ( let i = 0; i < volume.count; i ++ ) {

			const p = volume.positions;
			if ( p[ 3 * i ] === 6 ) volume.moveProbe( i, [ 5, p[ 3 * i + 1 ], p[ 3 * i + 2 ] ] );

		}

		expect( volume.probeSpacing ).toBeCloseTo( bruteForce( Array.from( volume.positions ) ), 12 );

	} );

} );

describe( 'volume.add( scene ): the choice per mesh', () => {

	it( 'floor quad → texture, tessellated wall → vertex, coarse wall → texture, crate → object, skinned rig → one dynamic entry', () => {

		const volume = gridVolume();
		const l = level();
		volume.add( l.scene );
		expect( volume.getLighting( l.floor ) ).toBe( 'texture' );
		expect( volume.getLighting( l.wall ) ).toBe( 'vertex' );
		expect( volume.getLighting( l.coarseWall ) ).toBe( 'texture' );
		expect( volume.getLighting( l.crate ) ).toBe( 'object' );
		// The rig (bone + skinned mesh + the sword on the bone) is one object, blended at its centre.
		expect( volume.getLighting( l.hero.root ) ).toBe( 'dynamic' );
		expect( volume.getLighting( l.hero.mesh ) ).toBe( 'dynamic' );
		expect( volume.getLighting( l.sword ) ).toBe( 'dynamic' );
		expect( volume.getUniforms( l.hero.root ) ).not.toBeNull();
		expect( volume.getUniforms( l.hero.mesh ) ).toBeNull(); // not an entry of its own
		expect( getProbeVolumeUniforms( l.sword.material as THREE.Material ) ).toBe( volume.getUniforms( l.hero.root ) );
		// What the modes really are: per-vertex attributes on the wall, a 3D texture on the floor.
		expect( l.wall.geometry.getAttribute( 'probeIrradiance' ) ).toBeDefined();
		expect( volume.getUniforms( l.floor )?.probeVolumeSH?.value ).toBeInstanceOf( THREE.Data3DTexture );
		expect( volume.getUniforms( l.crate )?.probeVolumeSH ).toBeUndefined();
		volume.dispose();

	} );

	it( 'MeshBasicMaterial is skipped (material untouched); userData.probeLighting and options.choose override the rule', () => {

		const volume = gridVolume();
		const l = level();
		const lampMaterial = l.lamp.material;
		volume.add( l.scene, { choose: ( object ) => ( object.name === 'statue' ? 'texture' : undefined ) } );
		expect( volume.getLighting( l.lamp ) ).toBeNull();
		expect( l.lamp.material ).toBe( lampMaterial );
		expect( getProbeVolumeUniforms( lampMaterial as THREE.Material ) ).toBeNull();
		// bigProp is 3 m long (large) but marked 'object'; the gizmo is marked 'none'.
		expect( volume.getLighting( l.bigProp ) ).toBe( 'object' );
		expect( volume.getLighting( l.gizmo ) ).toBeNull();
		expect( getProbeVolumeUniforms( l.gizmo.material as THREE.Material ) ).toBeNull();
		// The statue (1.5 m, smaller than the spacing: 'object' by the rule) chosen 'texture' by code.
		expect( volume.getLighting( l.statue ) ).toBe( 'texture' );
		volume.dispose();
		// Without choose, the rule: the statue is a prop.
		const again = gridVolume();
		again.add( l.scene );
		expect( again.getLighting( l.statue ) ).toBe( 'object' );
		again.dispose();

	} );

	it( 'a mark on a group lights the group as one object; choose() is asked before userData; \'dynamic\' marks a moving prop', () => {

		const volume = gridVolume();
		const l = level();
		const cart = new THREE.Group();
		cart.name = 'cart';
		const body = new THREE.Mesh( new THREE.BoxGeometry( 1, 0.5, 0.6 ), standard() );
		const wheel = new THREE.Mesh( new THREE.CylinderGeometry( 0.2, 0.2, 0.1 ), standard() );
		cart.add( body, wheel );
		cart.userData.probeLighting = 'dynamic';
		l.crate.userData.probeLighting = 'texture';
		l.scene.add( cart );
		volume.add( l.scene, { choose: ( object ) => ( object === l.crate ? 'object' : undefined ) } );
		expect( volume.getLighting( cart ) ).toBe( 'dynamic' );
		expect( volume.getLighting( body ) ).toBe( 'dynamic' );
		expect( volume.getUniforms( body ) ).toBeNull();
		expect( getProbeVolumeUniforms( wheel.material ) ).toBe( volume.getUniforms( cart ) );
		expect( volume.getLighting( l.crate ) ).toBe( 'object' ); // choose wins over userData
		volume.dispose();

	} );

	it( 'an already-added character stays one entry; add( scene ) again lights only what is new; add( mesh ) takes over from the rule', () => {

		const volume = gridVolume();
		const l = level();
		volume.add( l.hero.root ); // by hand, before the scene: one entry, as always
		const heroUniforms = volume.getUniforms( l.hero.root );
		volume.add( l.scene );
		expect( volume.getUniforms( l.hero.root ) ).toBe( heroUniforms );
		expect( volume.getUniforms( l.hero.mesh ) ).toBeNull();
		expect( getProbeVolumeUniforms( l.hero.mesh.material as THREE.Material ) ).toBe( heroUniforms );
		// New meshes after the first call: a second call lights them and leaves the others as they are.
		const floorUniforms = volume.getUniforms( l.floor );
		const barrel = new THREE.Mesh( new THREE.CylinderGeometry( 0.3, 0.3, 0.9 ), standard() );
		l.scene.add( barrel );
		expect( volume.getLighting( barrel ) ).toBeNull();
		volume.add( l.scene );
		expect( volume.getLighting( barrel ) ).toBe( 'object' );
		expect( volume.getUniforms( l.floor ) ).toBe( floorUniforms );
		// add( floor, { mode } ) replaces the automatic choice for it.
		volume.add( l.floor, { mode: 'vertex' } );
		expect( volume.getLighting( l.floor ) ).toBe( 'vertex' );
		expect( l.floor.geometry.getAttribute( 'probeIrradiance' ) ).toBeDefined();
		// remove( scene ) leaves what was added by hand.
		volume.remove( l.scene );
		expect( volume.getLighting( l.floor ) ).toBe( 'vertex' );
		expect( volume.getLighting( l.hero.root ) ).toBe( 'dynamic' );
		expect( volume.getLighting( l.wall ) ).toBeNull();
		volume.dispose();

	} );

	it( 'add( scene ) then remove( scene ) restores every material (the same objects, unpatched) and geometry', () => {

		const l = level();
		const meshes: THREE.Mesh[] = [];
		l.scene.traverse( ( object ) => { if ( ( object as THREE.Mesh ).isMesh ) meshes.push( object as THREE.Mesh ); } );
		// Two props sharing one material: the second gets a clone (uniforms are per material).
		const shared = standard();
		const a = new THREE.Mesh( new THREE.BoxGeometry( 0.3, 0.3, 0.3 ), shared );
		const b = new THREE.Mesh( new THREE.BoxGeometry( 0.3, 0.3, 0.3 ), shared );
		b.position.x = 2;
		l.scene.add( a, b );
		meshes.push( a, b );
		const attributes = ( mesh: THREE.Mesh ) => Object.keys( mesh.geometry.attributes ).sort();
		const before = meshes.map( ( mesh ) => ( { material: mesh.material, attributes: attributes( mesh ) } ) );
		const volume = gridVolume();
		volume.add( l.scene );
		expect( meshes.filter( ( mesh ) => mesh.material !== before[ meshes.indexOf( mesh ) ].material ).length ).toBeGreaterThan( 0 );
		expect( volume.getUniforms( a ) ).not.toBe( volume.getUniforms( b ) );
		volume.remove( l.scene );
		meshes.forEach( ( mesh, i ) => {

			expect( mesh.material, mesh.name ).toBe( before[ i ].material );
			for ( const material of [ mesh.material ].flat() ) expect( getProbeVolumeUniforms( material ), mesh.name ).toBeNull();
			expect( attributes( mesh ), mesh.name ).toEqual( before[ i ].attributes );
			expect( volume.getLighting( mesh ) ).toBeNull();

		} );
		// dispose() undoes it as well.
		volume.add( l.scene );
		volume.dispose();
		meshes.forEach( ( mesh, i ) => expect( mesh.material, mesh.name ).toBe( before[ i ].material ) );

	} );

	it( 'the texture a level mesh gets equals ProbeTextureLighting on it by hand, and the vertex light equals the analytic field', () => {

		const volume = gridVolume();
		const l = level();
		volume.add( l.scene );
		const auto = volume.getUniforms( l.coarseWall )!;
		const texture = auto.probeVolumeSH!.value!;
		// By hand on a copy of the wall at the same place (its own materials, its own texture).
		const copy = new THREE.Mesh( l.coarseWall.geometry, standard() );
		copy.position.copy( l.coarseWall.position );
		copy.rotation.copy( l.coarseWall.rotation );
		copy.updateMatrixWorld();
		const byHand = new ProbeTextureLighting( copy, volume );
		expect( auto.probeVolumeGridResolution!.value ).toEqual( byHand.uniforms.probeVolumeGridResolution!.value );
		expect( auto.probeVolumeGridMin!.value ).toEqual( byHand.uniforms.probeVolumeGridMin!.value );
		expect( auto.probeVolumeGridMax!.value ).toEqual( byHand.uniforms.probeVolumeGridMax!.value );
		const texels = ( t: THREE.Data3DTexture ) => Array.from( t.image.data as Uint16Array );
		expect( texels( texture ) ).toEqual( texels( byHand.volumeTexture.texture ) );
		byHand.dispose();
		// Per vertex: E(world normal) of SH(world position) at every vertex of the wall (it faces +z).
		const position = l.wall.geometry.getAttribute( 'position' );
		const irradiance = l.wall.geometry.getAttribute( 'probeIrradiance' );
		const p = new THREE.Vector3(), n = new THREE.Vector3( 0, 0, 1 );
		let worst = 0;
		for ( let i = 0; i < position.count; i ++ ) {

			p.fromBufferAttribute( position, i ).applyMatrix4( l.wall.matrixWorld );
			const sh = new THREE.SphericalHarmonics3().fromArray( linearSH( p.x, p.y, p.z ) );
			const expected = sh.getIrradianceAt( n, new THREE.Vector3() );
			worst = Math.max( worst, Math.abs( irradiance.getX( i ) - expected.x ), Math.abs( irradiance.getZ( i ) - expected.z ) );

		}

		expect( worst ).toBeLessThan( 1e-4 );
		volume.dispose();

	} );

	it( 'bad marks and options fail the call with nothing changed', () => {

		const volume = gridVolume();
		const l = level();
		const materials = new Map<THREE.Object3D, unknown>();
		l.scene.traverse( ( object ) => materials.set( object, ( object as THREE.Mesh ).material ) );
		l.statue.userData.probeLighting = 'dynamc';
		expect( () => volume.add( l.scene ) ).toThrow( /^LightProbeVolume\.add: userData\.probeLighting of "statue" is the string "dynamc"; expected/ );
		delete l.statue.userData.probeLighting;
		expect( () => volume.add( l.scene, { choose: () => 42 as never } ) ).toThrow( /^LightProbeVolume\.add: options\.choose of .* is 42/ );
		expect( () => volume.add( l.scene, { choose: 'wall' as never } ) ).toThrow( TypeError );
		expect( () => volume.add( l.scene, { hideInCaptures: false } ) ).toThrow( /^LightProbeVolume\.add: options\.hideInCaptures is not taken in mode 'auto'/ );
		expect( () => volume.add( l.scene, { anchor: new THREE.Vector3() } ) ).toThrow( RangeError );
		expect( () => volume.add( l.scene, { texelSize: - 1 } ) ).toThrow( /^LightProbeVolume\.add: options\.texelSize/ );
		// A failure half-way (a vertex-marked group holding a skinned mesh) rolls back what was already lit.
		l.hero.root.userData.probeLighting = 'vertex';
		expect( () => volume.add( l.scene ) ).toThrow( /is marked 'vertex', but .* is skinned/ );
		l.scene.traverse( ( object ) => expect( ( object as THREE.Mesh ).material ).toBe( materials.get( object ) ) );
		// A group marked as one object with something below it lit already.
		delete l.hero.root.userData.probeLighting;
		volume.add( l.hero.mesh );
		const group = new THREE.Group();
		group.userData.probeLighting = 'object';
		l.scene.add( group );
		group.add( l.hero.root );
		expect( () => volume.add( l.scene ) ).toThrow( /is marked 'object', but .* below it is already lit by this volume/ );
		expect( volume.getLighting( l.floor ) ).toBeNull();
		// add( object ) of a mesh that add( scene ) lights as part of a rig: an Error, nothing changed.
		volume.remove( l.hero.mesh );
		group.userData.probeLighting = 'auto';
		volume.add( l.scene );
		const heroUniforms = volume.getUniforms( l.hero.root );
		expect( () => volume.add( l.hero.mesh ) ).toThrow( /^LightProbeVolume\.add: \(SkinnedMesh .*\) is lit as part of "hero"/ );
		expect( volume.getUniforms( l.hero.root ) ).toBe( heroUniforms );
		expect( volume.getUniforms( l.hero.mesh ) ).toBeNull();
		const notObjects = [
			() => volume.getLighting( 5 as never ), () => volume.remove( null as never ), () => volume.add( {} as never ),
		];
		for ( const call of notObjects ) {

			expect( call ).toThrow( /^LightProbeVolume\.(getLighting|remove|add): object must be a three\.js Object3D/ );

		}

		volume.dispose();

	} );

} );

describe( 'volume.add( scene ): static entries are blended on change, not every frame', () => {

	it( '200 props cost no blend per frame; a moved prop, SH written, a probe edit or new occluders blend again; a dynamic one every frame', () => {

		const volume = gridVolume();
		const scene = new THREE.Scene();
		const props: THREE.Mesh[] = [];
		for ( let i = 0; i < 200; i ++ ) {

			const prop = new THREE.Mesh( new THREE.BoxGeometry( 0.3, 0.3, 0.3 ), standard() );
			prop.position.set( ( i % 20 ) * 0.5 - 5, 1, Math.floor( i / 20 ) - 5 );
			props.push( prop );
			scene.add( prop );

		}

		let counter = countLocates( volume );
		volume.add( scene );
		expect( counter.calls ).toBe( 200 ); // each blended once when added
		counter.reset();
		for ( let frame = 0; frame < 10; frame ++ ) volume.update();
		expect( counter.calls ).toBe( 0 );
		// A moved prop (its parent moved, even) blends once, at its new place.
		const before = Float32Array.from( volume.getUniforms( props[ 7 ] )!.probeVolumeMatrices.value );
		props[ 7 ].position.x += 1;
		volume.update();
		volume.update();
		expect( counter.calls ).toBe( 1 );
		expect( Array.from( volume.getUniforms( props[ 7 ] )!.probeVolumeMatrices.value ) ).not.toEqual( Array.from( before ) );
		// SH written directly: every prop once.
		counter.reset();
		volume.sh[ 0 ] += 0.5;
		volume.update();
		volume.update();
		expect( counter.calls ).toBe( 200 );
		// New occluders: the guard may drop probes, so every prop once.
		counter.reset();
		const ceiling = new THREE.Mesh( new THREE.PlaneGeometry( 1, 1 ), standard() );
		ceiling.position.y = 10;
		ceiling.updateMatrixWorld();
		volume.setOccluders( ceiling );
		volume.update();
		volume.update();
		expect( counter.calls ).toBe( 200 );
		volume.setOccluders( null );
		// A probe edit (the interpolator becomes incremental: count on the new one).
		volume.moveProbe( 0, [ - 6.5, 0, - 6 ] );
		counter = countLocates( volume );
		volume.update();
		volume.update();
		expect( counter.calls ).toBe( 200 );
		// A dynamic object is blended every frame (the counter sees it).
		const runner = new THREE.Mesh( new THREE.BoxGeometry( 0.3, 0.3, 0.3 ), standard() );
		scene.add( runner );
		volume.add( runner );
		counter.reset();
		for ( let frame = 0; frame < 10; frame ++ ) volume.update();
		expect( counter.calls ).toBe( 10 );
		volume.dispose();

	} );

	it( 'a moved prop gets the light of its new place (the analytic SH there), and large static meshes resample only on change', () => {

		const volume = gridVolume();
		const scene = new THREE.Scene();
		const prop = new THREE.Mesh( new THREE.BoxGeometry( 0.4, 0.4, 0.4 ), standard() );
		const floor = new THREE.Mesh( new THREE.PlaneGeometry( 8, 8 ).rotateX( - Math.PI / 2 ), standard() );
		scene.add( prop, floor );
		volume.add( scene );
		expect( volume.getLighting( floor ) ).toBe( 'texture' );
		const counter = countLocates( volume );
		prop.position.set( 1.3, 2.1, - 0.7 );
		volume.update();
		const expected = new THREE.Vector3();
		const uniforms: ProbeVolumeUniforms = volume.getUniforms( prop )!;
		// The matrices are irradianceMatrices( SH(p) ): E(n) = nᵀMn for n = +y, against three's LightProbe math.
		const m = uniforms.probeVolumeMatrices.value, n = [ 0, 1, 0, 1 ];
		const quadratic = ( c: number ) => {

			let sum = 0;
			for ( let i = 0; i < 4; i ++ ) for ( let j = 0; j < 4; j ++ ) sum += n[ i ] * m[ 16 * c + 4 * j + i ] * n[ j ];
			return sum;

		};

		new THREE.SphericalHarmonics3().fromArray( linearSH( 1.3, 2.1, - 0.7 ) ).getIrradianceAt( new THREE.Vector3( 0, 1, 0 ), expected );
		expect( quadratic( 0 ) ).toBeCloseTo( expected.x, 4 );
		expect( quadratic( 2 ) ).toBeCloseTo( expected.z, 4 );
		expect( counter.calls ).toBe( 1 ); // the prop; the floor did not move and the SH did not change
		counter.reset();
		volume.sh[ 5 ] += 0.1;
		volume.update();
		expect( counter.calls ).toBeGreaterThan( 8 ); // the prop and every node of the floor's texture
		counter.reset();
		volume.update();
		expect( counter.calls ).toBe( 0 );
		volume.dispose();

	} );

} );
