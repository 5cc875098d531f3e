/**
 * `LightProbeVolume.fromScene`'s argument checks and the errors that come before any capture: a
 * stand-in renderer is enough (the pipeline itself: fromScene.gpu.test.ts). Also which objects it
 * hides as moving.
 */
import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { movingObjects, volumeFromScene, type FromSceneOptions } from '../../src/runtime/volumeFromScene.js';
import { createBasicRoom } from '../../scenes/basic.js';

const renderer = { isWebGLRenderer: true, getContext() {} } as unknown as THREE.WebGLRenderer;
const where = 'LightProbeVolume.fromScene';

describe( 'LightProbeVolume.fromScene (checks before the capture)', () => {

	const scene = new THREE.Scene();
	scene.add( createBasicRoom().room );
	const call = ( options: unknown, target: unknown = scene, r: unknown = renderer ) => volumeFromScene(
		r as THREE.WebGLRenderer, target as THREE.Scene, options as FromSceneOptions,
	);

	it( 'names fromScene and the bad argument', async () => {

		await expect( call( { budget: 8 }, scene, {} ) ).rejects.toThrow( new RegExp( `^${where}: renderer must be a three.js WebGLRenderer` ) );
		await expect( call( { budget: 8 }, {} ) ).rejects.toThrow( new RegExp( `^${where}: scene must be a three.js Scene` ) );
		await expect( call( null ) ).rejects.toThrow( new RegExp( `^${where}: options must be \\{ budget \\| spacing` ) );
		await expect( call( {} ) ).rejects.toThrow( new RegExp( `^${where}: options needs either budget .* or spacing .*, got neither` ) );
		await expect( call( { budget: 8, spacing: 1 } ) ).rejects.toThrow( /got both/ );
		await expect( call( { budget: 3 } ) ).rejects.toThrow( new RegExp( `^${where}: options.budget must be an integer ≥ 4, got 3` ) );
		await expect( call( { budget: 8.5 } ) ).rejects.toThrow( new RegExp( `^${where}: options.budget must be an integer` ) );
		await expect( call( { spacing: - 1 } ) ).rejects.toThrow( new RegExp( `^${where}: options.spacing must be > 0, got -1` ) );
		await expect( call( { budget: 8, size: 2 } ) ).rejects.toThrow( new RegExp( `^${where}: unknown option "size"` ) );
		await expect( call( { budget: 8, resolution: 0 } ) ).rejects.toThrow( new RegExp( `^${where}: options.resolution must be an integer in 1\\.\\.4096` ) );
		await expect( call( { budget: 8, gradients: true, fit: false } ) ).rejects.toThrow( new RegExp( `^${where}: options.gradients needs options.fit` ) );
		await expect( call( { budget: 8, fit: { lambda: - 2 } } ) ).rejects.toThrow( new RegExp( `^${where}: options.fit.lambda must be 'auto' or a finite number ≥ 0` ) );
		await expect( call( { budget: 8, fit: { gradients: true } } ) ).rejects.toThrow( new RegExp( `^${where}: options.fit has the unknown option "gradients"` ) );
		await expect( call( { budget: 8, clearance: - 1 } ) ).rejects.toThrow( new RegExp( `^${where}: options.clearance must be ≥ 0` ) );
		await expect( call( { budget: 8, where: 5 } ) ).rejects.toThrow( new RegExp( `^${where}: options.where must be an object` ) );
		await expect( call( { budget: 8, walkable: { height: 1 } } ) ).rejects.toThrow( new RegExp( `^${where}: options.walkable is taken only with where: 'walkable'` ) );
		await expect( call( { budget: 8, capture: { resolution: 8 } } ) ).rejects.toThrow( new RegExp( `^${where}: options.capture.resolution is not taken; pass options.resolution` ) );
		await expect( call( { budget: 8, exclude: 5 } ) ).rejects.toThrow( new RegExp( `^${where}: options.exclude must be an iterable` ) );
		await expect( call( { budget: 8, reachableFrom: [ 0, 1 ] } ) ).rejects.toThrow( new RegExp( `^${where}: options.reachableFrom must hold x, y, z` ) );
		await expect( call( { budget: 8, onProgress: 1 } ) ).rejects.toThrow( new RegExp( `^${where}: options.onProgress must be a function` ) );

	} );

	it( 'an empty scene, a level too small for the budget, a spacing too large, a region that holds no candidate', async () => {

		await expect( call( { budget: 8 }, new THREE.Scene() ) ).rejects.toThrow( new RegExp( `^${where}: scene has no triangles to place probes in` ) );
		// The room alone, everything hidden: nothing left.
		const room = createBasicRoom().room;
		const hiddenLevel = new THREE.Scene().add( room );
		await expect( call( { budget: 8, exclude: [ room ] }, hiddenLevel ) ).rejects.toThrow( new RegExp( `^${where}: scene has no triangles` ) );
		await expect( call( { budget: 1000, candidates: 256, reachableFrom: [ 0, 1.6, 0 ] } ) )
			.rejects.toThrow( new RegExp( `^${where}: only \\d+ of \\d+ candidates are in open space .*fewer than the budget \\(1000\\)` ) );
		// The room's open space is about 3.5 × 2.5 × 3.5 m (a quarter cell clear of the walls): at 3 m spacing, one or two probes.
		await expect( call( { spacing: 3 } ) ).rejects.toThrow( new RegExp( `^${where}: the level's open space \\(about .* units³\\) holds [0-3] probes at options.spacing 3` ) );
		await expect( call( { budget: 8, where: { boxes: [ { min: [ 10, 10, 10 ], max: [ 11, 11, 11 ] } ] } } ) )
			.rejects.toThrow( new RegExp( `^${where}: options.where contains none of the` ) );
		// A level of four walls and no floor (a square tube of quads facing in): where: 'walkable' finds no floor to walk on.
		const tube = new THREE.Scene();
		for ( let side = 0; side < 4; side ++ ) {

			const wall = new THREE.Mesh( new THREE.PlaneGeometry( 4, 3 ), new THREE.MeshStandardMaterial() );
			wall.rotation.y = side * Math.PI / 2;
			wall.position.set( - 2 * Math.sin( side * Math.PI / 2 ), 1.5, - 2 * Math.cos( side * Math.PI / 2 ) );
			tube.add( wall );

		}

		await expect( call( { budget: 4, where: 'walkable' }, tube ) ).rejects.toThrow( new RegExp( `^${where}: none of the 8 triangles faces up` ) );

	} );

	it( 'hides what add( scene ) would light as moving: marked dynamic, skinned meshes, what hangs from bones', () => {

		const scene = new THREE.Scene();
		const prop = new THREE.Mesh( new THREE.BoxGeometry(), new THREE.MeshStandardMaterial() );
		const marked = new THREE.Group();
		marked.userData.probeLighting = 'dynamic';
		marked.add( new THREE.Mesh( new THREE.BoxGeometry(), new THREE.MeshStandardMaterial() ) );
		const bone = new THREE.Bone();
		const sword = new THREE.Mesh( new THREE.BoxGeometry(), new THREE.MeshStandardMaterial() );
		bone.add( sword );
		const skinned = new THREE.SkinnedMesh( new THREE.BoxGeometry(), new THREE.MeshStandardMaterial() );
		const rig = new THREE.Group().add( bone, skinned );
		scene.add( prop, marked, rig );
		expect( movingObjects( scene ) ).toEqual( [ marked, sword, skinned ] );

	} );

} );
