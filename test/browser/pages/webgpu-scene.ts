import * as THREE from 'three';
import { MeshStandardNodeMaterial, WebGPURenderer } from 'three/webgpu';
// The webgpu entry (node shading and WebGPU capture installed); the main entry's modules are the same ones.
import { LightProbeVolume, captureBounces, type FromSceneProgress } from '../../../src/webgpu.js';
import { createBasicRoom } from '../../../scenes/basic.js';

// The scene paths of WebGPURenderer on one backend (?backend=webgpu | webgl2), for
// test/browser/webgpuScene.test.ts: fromScene, a capture with shadows, bounces off node-material
// and built-in scenery against WebGLRenderer's, recaptureDirty after a move, and a lost device or
// context in a bounce pass. Nothing is drawn to the canvas (captures render into targets only).
// Results go to window.__result.

const backend = new URLSearchParams( location.search ).get( 'backend' ) === 'webgl2' ? 'webgl2' : 'webgpu';
const result: Record<string, unknown> = { backend };
const SIZE = 16;
/** Four probes in the Basic room: centre, by the red wall, by the green wall, under the lamp. */
const PROBES = [ 0, 1.2, 0, - 1.4, 1, 0.5, 1.4, 0.8, - 0.6, 0.3, 2.4, 1.2 ];

/** Largest |a − b| over the 27 floats of each probe, relative to that probe's L00 of the channel in `b`. */
function worstError( a: Float32Array, b: Float32Array ): number {

	let worst = 0;
	for ( let i = 0; i < a.length; i ++ ) {

		const l00 = Math.abs( b[ 27 * Math.floor( i / 27 ) + ( i % 3 ) ] );
		worst = Math.max( worst, Math.abs( a[ i ] - b[ i ] ) / l00 );

	}

	return worst;

}

/** Mean L00 over probes and channels. */
function meanL00( sh: Float32Array ): number {

	let sum = 0;
	for ( let p = 0; p < sh.length / 27; p ++ ) sum += sh[ 27 * p ] + sh[ 27 * p + 1 ] + sh[ 27 * p + 2 ];
	return sum / ( 3 * sh.length / 27 );

}

/** The Basic room (each side subdivided, for the bounce's per-vertex light), with node materials when `node`. */
function basicRoom( node: boolean ): { scene: THREE.Scene; room: THREE.Mesh } {

	const scene = new THREE.Scene();
	const { room: group } = createBasicRoom( 6 );
	scene.add( group );
	const room = group.getObjectByName( 'room' ) as THREE.Mesh;
	if ( node ) {

		room.material = ( room.material as THREE.MeshStandardMaterial[] ).map( ( material ) => new MeshStandardNodeMaterial( {
			color: material.color, roughness: material.roughness, metalness: material.metalness, side: material.side,
		} ) );

	}

	return { scene, room };

}

interface Bounced { passes: Float32Array[]; statics: number; lighting: string | null }

/**
 * Each pass's SH of a capture with two bounces. The room is bounce scenery (lit per vertex for the
 * passes), or with `add` the volume lights it itself (`volume.add( scene )`: its own mode, from
 * the previous pass's probes).
 */
async function bouncedSH(
	renderer: THREE.WebGLRenderer | WebGPURenderer, scene: THREE.Scene, add = false, output: 'irradiance' | 'sh' = 'irradiance',
): Promise<Bounced> {

	const volume = new LightProbeVolume( { positions: PROBES } );
	if ( add ) volume.add( scene );
	const passes: Float32Array[] = [];
	const { staticMeshes } = await captureBounces( volume, renderer, scene, {
		bounces: 2, resolution: SIZE, output, onPass: ( _pass, sh ) => passes.push( sh.slice() ),
	} );
	const lighting = volume.getLighting( scene.getObjectByName( 'room' )! );
	volume.dispose();
	return { passes, statics: staticMeshes.length, lighting };

}

/** A floor lit from above by a shadow-casting sun, a slab over one probe; probe 0 in its shadow, probe 1 in the open. */
function shadowScene(): { scene: THREE.Scene; sun: THREE.DirectionalLight } {

	const scene = new THREE.Scene();
	const floor = new THREE.Mesh( new THREE.PlaneGeometry( 12, 12 ), new THREE.MeshStandardMaterial( { color: 0xbbbbbb, roughness: 1 } ) );
	floor.rotation.x = - Math.PI / 2;
	floor.receiveShadow = true;
	const slab = new THREE.Mesh( new THREE.BoxGeometry( 3, 0.2, 3 ), new THREE.MeshStandardMaterial( { color: 0x888888 } ) );
	slab.position.set( - 2.5, 1.5, 0 );
	slab.castShadow = slab.receiveShadow = true;
	const sun = new THREE.DirectionalLight( 0xffffff, 3 );
	sun.position.set( 0, 8, 0 );
	sun.castShadow = true;
	sun.shadow.mapSize.set( 256, 256 );
	Object.assign( sun.shadow.camera, { left: - 7, right: 7, top: 7, bottom: - 7, near: 1, far: 12 } );
	scene.add( floor, slab, sun, sun.target );
	return { scene, sun };

}

async function run(): Promise<void> {

	const renderer = new WebGPURenderer( { forceWebGL: backend === 'webgl2' } );
	renderer.setSize( 32, 32 );
	document.body.appendChild( renderer.domElement );
	await renderer.init();
	result.isWebGPUBackend = ( renderer.backend as { isWebGPUBackend?: boolean } ).isWebGPUBackend === true;
	const gl = new THREE.WebGLRenderer();

	// fromScene: 8 probes chosen from about 64 candidates at 8², captured again at 16², unfitted, so
	// their SH are those captures — which WebGLRenderer, capturing the same positions, must reproduce.
	{

		const { scene } = basicRoom( false );
		const stages: string[] = [];
		const volume = await LightProbeVolume.fromScene( renderer, scene, {
			budget: 8, resolution: SIZE, candidateResolution: 8, candidates: 64, fit: false, reachableFrom: [ [ 0, 1.5, 0 ] ],
			onProgress: ( { stage }: FromSceneProgress ) => { if ( stages[ stages.length - 1 ] !== stage ) stages.push( stage ); },
		} );
		const positions = Array.from( volume.positions );
		const inside = positions.every( ( v, i ) => i % 3 === 1 ? v > 0 && v < 3 : v > - 2 && v < 2 );
		const check = new LightProbeVolume( { positions } );
		await check.capture( gl, scene, { resolution: SIZE } );
		result.fromScene = { count: volume.count, inside, stages, error: worstError( volume.sh, check.sh ), meanL00: meanL00( volume.sh ) };
		volume.dispose();
		check.dispose();

	}

	// Shadows: the same two probes with the shadow map off and on; the map is drawn once per capture call.
	{

		const { scene, sun } = shadowScene();
		const positions = [ - 2.5, 0.4, 0, 2.5, 0.4, 0, 0, 3, - 3, 0, 3, 3 ];
		const draws: number[] = [];
		const render = renderer.render.bind( renderer );
		let count = 0;
		renderer.render = ( ( object: THREE.Object3D, camera: THREE.Camera ) => {

			if ( camera === sun.shadow.camera ) count ++;
			return render( object, camera );

		} ) as typeof renderer.render;
		const capture = async ( enabled: boolean ) => {

			renderer.shadowMap.enabled = enabled;
			const volume = new LightProbeVolume( { positions } );
			count = 0;
			await volume.capture( renderer, scene, { resolution: SIZE } );
			draws.push( count );
			const sh = volume.sh.slice();
			volume.dispose();
			return sh;

		};

		const open = await capture( false );
		const shadowed = await capture( true );
		const again = await capture( true );
		renderer.render = render;
		renderer.shadowMap.enabled = false;
		result.shadows = {
			draws,
			// L00, green channel: probe 0 (under the slab) and probe 1 (in the open), without and with the map.
			open: [ open[ 1 ], open[ 27 + 1 ] ],
			shadowed: [ shadowed[ 1 ], shadowed[ 27 + 1 ] ],
			repeat: worstError( again, shadowed ),
			autoUpdate: sun.shadow.autoUpdate,
		};

	}

	// Bounces: the Basic room with node materials and with built-in ones on this renderer, against
	// WebGLRenderer's built-in room, pass by pass.
	{

		const truth = await bouncedSH( gl, basicRoom( false ).scene );
		const truthAdded = await bouncedSH( gl, basicRoom( false ).scene, true );
		const truthSH = await bouncedSH( gl, basicRoom( false ).scene, false, 'sh' );
		const summary = ( run: Bounced, against: Bounced ) => ( {
			passes: run.passes.length, statics: run.statics, lighting: run.lighting,
			meanL00: run.passes.map( meanL00 ),
			errors: run.passes.map( ( sh, i ) => against.passes[ i ] ? worstError( sh, against.passes[ i ] ) : - 1 ),
		} );
		result.bounces = {
			webgl: summary( truth, truth ),
			node: summary( await bouncedSH( renderer, basicRoom( true ).scene ), truth ),
			plain: summary( await bouncedSH( renderer, basicRoom( false ).scene ), truth ),
			webglAdded: summary( truthAdded, truthAdded ),
			nodeAdded: summary( await bouncedSH( renderer, basicRoom( true ).scene, true ), truthAdded ),
			// output 'sh': the bounce scenery stores the blended SH per vertex (the vertexSH variant).
			webglSH: summary( truthSH, truthSH ),
			nodeSH: summary( await bouncedSH( renderer, basicRoom( true ).scene, false, 'sh' ), truthSH ),
			// Per-vertex irradiance against per-vertex SH evaluated per pixel with the normal the (BackSide)
			// walls are shaded with: equal on flat walls, where E is linear in the SH across a triangle.
			irradianceVersusSH: truth.passes.map( ( sh, i ) => worstError( sh, truthSH.passes[ i ] ) ),
		};

	}

	// recaptureDirty: probe 1 moves towards the red wall; only it is captured again, to what a fresh capture there gives.
	{

		const { scene } = basicRoom( true );
		const volume = new LightProbeVolume( { positions: PROBES.concat( [ 0.5, 0.6, - 1 ] ) } );
		await volume.capture( renderer, scene, { resolution: SIZE } );
		const before = volume.sh.slice();
		const moved = [ - 1.8, 1.4, 0.2 ];
		volume.moveProbe( 1, moved );
		const dirty = volume.dirtyProbes();
		const totals: number[] = [];
		const onProgress = ( _done: number, total: number ) => { totals.push( total ); };
		await volume.recaptureDirty( renderer, scene, { resolution: SIZE, onProgress } );
		const fresh = new LightProbeVolume( { positions: [ ...moved, 0, 1.2, 0, 1.4, 0.8, - 0.6, 0.3, 2.4, 1.2 ] } );
		await fresh.capture( renderer, scene, { resolution: SIZE } );
		const probe = ( sh: Float32Array, p: number ) => sh.slice( 27 * p, 27 * p + 27 );
		let othersSame = true;
		for ( let i = 0; i < before.length; i ++ ) if ( Math.floor( i / 27 ) !== 1 && volume.sh[ i ] !== before[ i ] ) othersSame = false;
		result.recapture = {
			dirty, totals, othersSame, dirtyAfter: volume.dirtyProbes(),
			movedVersusFresh: worstError( probe( volume.sh, 1 ), probe( fresh.sh, 0 ) ),
			movedVersusBefore: worstError( probe( volume.sh, 1 ), probe( before, 1 ) ),
			// The red wall is at −x: the moved probe gets more red than green, relative to before.
			redOverGreen: [ before[ 27 ] / before[ 28 ], volume.sh[ 27 ] / volume.sh[ 28 ] ],
		};
		volume.dispose();
		fresh.dispose();

	}

	gl.dispose();

	// A lost device or context between pass 0 and pass 1 of a bounced capture: the named error,
	// the SH kept, the scenery's materials and geometries back.
	{

		const { scene, room } = basicRoom( true );
		const volume = new LightProbeVolume( { positions: PROBES } );
		await volume.capture( renderer, scene, { resolution: 8 } );
		const held = volume.sh.slice();
		const material = room.material, geometry = room.geometry;
		const lose = () => {

			if ( backend === 'webgpu' ) ( renderer.backend as unknown as { device: { destroy(): void } } ).device.destroy();
			else ( renderer.backend as unknown as { gl: WebGL2RenderingContext } ).gl.getExtension( 'WEBGL_lose_context' )!.loseContext();

		};

		let passes = 0;
		try {

			const onPass = ( pass: number ) => { passes ++; if ( pass === 0 ) lose(); };
			await volume.capture( renderer, scene, { resolution: 8, bounces: 1, onPass } );
			result.lossError = 'no error';

		} catch ( error ) {

			result.lossError = ( error as Error ).message;

		}

		result.lossPasses = passes;
		result.shKept = volume.sh.every( ( value, i ) => value === held[ i ] );
		result.sceneryBack = room.material === material && room.geometry === geometry;

	}

}

run().then( () => {

	( window as unknown as { __result: unknown } ).__result = result;

}, ( error: Error ) => {

	result.error = `${error.message}\n${error.stack}`;
	( window as unknown as { __result: unknown } ).__result = result;

} );
