import * as THREE from 'three';
import { LightProbeVolume } from 'three-capture-lighting';

// Loses the WebGL context (WEBGL_lose_context) at several points of a capture — during the first
// role pass, at its end before its read-back, during the second role pass, during a bounce pass —
// and checks after each that the volume is exactly as before (SH, dirty set, capture settings);
// restores the context each time, and finally captures undisturbed. The outcome is left in
// window.__result for test/browser/atomicCapture.test.ts.

const renderer = new THREE.WebGLRenderer();
renderer.setSize( 64, 64 );
document.body.appendChild( renderer.domElement );
const gl = renderer.getContext();

const scene = new THREE.Scene();
const roomMaterial = new THREE.MeshStandardMaterial( { color: 0x808080, emissive: 0x204060, side: THREE.BackSide, roughness: 1 } );
const room = new THREE.Mesh( new THREE.BoxGeometry( 10, 10, 10 ), roomMaterial );
scene.add( room );
const visitor = new THREE.Mesh( new THREE.SphereGeometry( 0.3 ), new THREE.MeshStandardMaterial() );
scene.add( visitor );

const positions = [ - 1, - 1, - 1, 1, - 1, - 1, - 1, 1, - 1, 1, 1, - 1, - 1, - 1, 1, 1, - 1, 1, - 1, 1, 1, 1, 1, 1.2 ];
// Probes 0, 2, 4, 6 (sky, own settings) are captured first, then 1, 3, 5, 7: progress 1..4, then 5..8.
const volume = new LightProbeVolume( { positions, roles: [ 'sky', 'fill', 'sky', 'fill', 'sky', 'fill', 'sky', 'fill' ] } );
volume.add( visitor );
const options = { resolution: 8, far: 50, roles: { sky: { far: 40 } } };

function state(): string {

	const { sh, captureSettings: settings } = volume;
	return JSON.stringify( { sh: Array.from( sh ), dirty: volume.dirtyProbes(), settings, visitor: visitor.visible } );

}

const extension = gl.getExtension( 'WEBGL_lose_context' );

/** Loses the context now; the returned promise resolves once it is restored (three has rebuilt its state). */
function lose(): Promise<void> {

	const lost = new Promise( ( resolve ) => renderer.domElement.addEventListener( 'webglcontextlost', resolve, { once: true } ) );
	extension!.loseContext();
	return ( async () => {

		await lost;
		// Chromium allows restoreContext() only once the lost event has been dispatched (and three
		// has called preventDefault on it), i.e. from a later task.
		await new Promise( ( resolve ) => setTimeout( resolve, 0 ) );
		const restored = new Promise( ( resolve ) => renderer.domElement.addEventListener( 'webglcontextrestored', resolve, { once: true } ) );
		extension!.restoreContext();
		await restored;

	} )();

}

async function attempt( point: string, run: ( loseNow: () => void ) => Promise<unknown> ): Promise<Record<string, unknown>> {

	const before = state();
	let restored: Promise<void> | null = null;
	let error = '';
	try {

		await run( () => { restored ??= lose(); } );

	} catch ( caught ) {

		error = ( caught as Error ).message;

	}

	const unchanged = state() === before;
	const lost = restored !== null;
	if ( restored ) await restored;
	return { point, lost, error, unchanged };

}

async function run(): Promise<Record<string, unknown>> {

	if ( ! extension ) return { error: 'WEBGL_lose_context is not available' };
	await volume.capture( renderer, scene, { resolution: 8 } );
	volume.moveProbe( 7, [ 1, 1, 1.1 ] ); // a dirty probe
	roomMaterial.emissive.setHex( 0x603010 ); // a capture now gives other SH
	const initial = state();
	const attempts = [];
	for ( const [ point, at ] of [ [ 'during the first role pass', 1 ], [ 'at the end of the first role pass', 4 ], [ 'during the second role pass', 6 ] ] as const ) {

		const capture = ( loseNow: () => void ) => volume.capture( renderer, scene, {
			...options, onProgress: ( done ) => { if ( done === at ) loseNow(); },
		} );
		attempts.push( await attempt( point, capture ) );

	}

	attempts.push( await attempt( 'during a bounce pass', ( loseNow ) => {

		let pass = 0;
		return volume.capture( renderer, scene, {
			...options, bounces: 2, staticMeshes: [ room ],
			onPass: ( done ) => { pass = done + 1; },
			onProgress: ( done ) => { if ( pass === 1 && done === 3 ) loseNow(); },
		} );

	} ) );
	attempts.push( await attempt( 'before recaptureDirty', ( loseNow ) => {

		loseNow();
		return volume.recaptureDirty( renderer, scene, options );

	} ) );

	const keptThroughout = state() === initial;
	await volume.capture( renderer, scene, options );
	const after = JSON.parse( state() );
	return {
		attempts, keptThroughout,
		finalChanged: JSON.stringify( after.sh ) !== JSON.stringify( JSON.parse( initial ).sh ), finalDirty: after.dirty,
		finalFinite: after.sh.every( Number.isFinite ), finalSkyFar: after.settings.roles?.sky?.far,
	};

}

run().then(
	( result ) => Object.assign( window, { __result: result } ),
	( error ) => Object.assign( window, { __result: { error: String( error?.stack ?? error ) } } ),
);
