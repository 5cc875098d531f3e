/**
 * Browser side of bench/framesDecompose.ts: the frame part of the capture bench (bench/pages/capture.ts,
 * part 3) rebuilt with variants of its own, to find where a probe-lit frame's time goes. The Basic
 * room (unlit walls in the frames, so only the spheres pay for probe light), a PointLight, and 500
 * small spheres with a MeshStandardMaterial each, on the capture bench's Lissajous paths; one scene
 * per variant so frames of all variants interleave. A variant is one global THREE.LightProbe, no
 * probe, or the spheres added to a LightProbeVolume (per pixel or per vertex), optionally with the
 * probe function of the patched shader replaced by another (`fragment`, GLSL text), so shader
 * alternatives can be timed side by side before one goes into the library.
 */

import * as THREE from 'three';
import { LightProbeVolume } from '../../src/index.js';
import { FAR, HEIGHT, NEAR, ROOM_MIN, WIDTH, createBenchRoom } from './benchRoom.js';

const { renderer, gl, scene, camera, size, unlitWalls, room, lamp, light } = createBenchRoom();

// The capture bench's probes: LightProbeGridWebGL's 4 × 4 × 4 cell centres over the room.
const positions = new Float64Array( 3 * 64 );
for ( let iz = 0, k = 0; iz < 4; iz ++ ) for ( let iy = 0; iy < 4; iy ++ ) for ( let ix = 0; ix < 4; ix ++, k += 3 ) {

	positions[ k ] = ROOM_MIN[ 0 ] + ( ix + 0.5 ) * size.x / 4;
	positions[ k + 1 ] = ROOM_MIN[ 1 ] + ( iy + 0.5 ) * size.y / 4;
	positions[ k + 2 ] = ROOM_MIN[ 2 ] + ( iz + 0.5 ) * size.z / 4;

}

const syncPixel = new Uint8Array( 4 );

function syncCanvas(): void {

	renderer.setRenderTarget( null );
	gl.readPixels( 0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, syncPixel );

}

/** One frame variant. */
export interface FrameVariant {

	name: string;
	probe: 'none' | 'global' | 'ours';
	/** ours: `add( sphere, { perVertex } )`. */
	perVertex?: boolean;
	/** ours: GLSL replacing the patched shader's `vec3 probeVolumeIrradiance( … ) { … }` function. */
	fragment?: string;
	/** ours: skip volume.update() in the timed frame (the uniforms keep the first frame's blend). */
	noUpdate?: boolean;

}

interface Built {

	variant: FrameVariant;
	scene: THREE.Scene;
	spheres: THREE.Mesh[];
	volume: LightProbeVolume | null;

}

let built: Built[] = [];
let phases = new Float32Array( 0 );
let step = 0;

const FUNCTION = /vec3 probeVolumeIrradiance\([^)]*\) \{[\s\S]*?\n\}\n/;

/** Replaces the probe function of a patched material's shaders by `fragment`, in a program of its own. */
function overrideProbeFunction( material: THREE.Material, name: string, fragment: string ): void {

	const compile = material.onBeforeCompile, key = material.customProgramCacheKey;
	material.onBeforeCompile = function ( shader, r ) {

		compile.call( this, shader, r );
		for ( const stage of [ 'vertexShader', 'fragmentShader' ] as const ) {

			if ( FUNCTION.test( shader[ stage ] ) ) shader[ stage ] = shader[ stage ].replace( FUNCTION, `${fragment.trim()}\n` );

		}

		const head = fragment.trim().slice( 0, 40 );
		if ( ! shader.fragmentShader.includes( head ) && ! shader.vertexShader.includes( head ) ) {

			throw new Error( `frames: variant ${name}: no probeVolumeIrradiance function to replace` );

		}

	};

	material.customProgramCacheKey = () => `${key.call( material )}|frames:${name}`;
	material.needsUpdate = true;

}

/** Lissajous paths inside the probes' hull, as the capture bench's (not timed). */
function moveSpheres( list: THREE.Mesh[], at: number ): void {

	const t = at * 0.02;
	for ( let i = 0; i < list.length; i ++ ) {

		const f = phases.subarray( 6 * i, 6 * i + 6 );
		list[ i ].position.set(
			1.4 * Math.sin( ( 0.5 + f[ 0 ] ) * t + 6.283 * f[ 1 ] ),
			1.5 + 1.05 * Math.sin( ( 0.5 + f[ 2 ] ) * t + 6.283 * f[ 3 ] ),
			1.4 * Math.sin( ( 0.5 + f[ 4 ] ) * t + 6.283 * f[ 5 ] ),
		);

	}

}

/** Builds one scene per variant over one captured volume (SH shared), and compiles them. */
async function setup( variants: FrameVariant[], count = 500, cubeSize = 32 ): Promise<{ programs: number, tetrahedra: number }> {

	const captured = new LightProbeVolume( { positions } );
	await captured.capture( renderer, scene, { resolution: cubeSize, near: NEAR, far: FAR } );
	const globalProbe = new THREE.LightProbe();
	globalProbe.sh.fromArray( captured.sample( [ room.position.x, room.position.y, room.position.z ] ) );

	const geometry = new THREE.SphereGeometry( 0.08, 16, 12 );
	phases = new Float32Array( count * 6 );
	let seed = 12345;
	const random = () => ( seed = ( seed * 16807 ) % 2147483647 ) / 2147483647;
	for ( let i = 0; i < phases.length; i ++ ) phases[ i ] = random();
	const colors = Array.from( { length: count }, () => new THREE.Color().setHSL( random(), 0.3, 0.75 ) );

	built = variants.map( ( variant ) => {

		const frameScene = new THREE.Scene();
		const walls = new THREE.Mesh( room.geometry, unlitWalls );
		walls.position.copy( room.position );
		frameScene.add( walls, lamp.clone(), light.clone() );
		if ( variant.probe === 'global' ) frameScene.add( globalProbe.clone() );
		const spheres = colors.map( ( color ) => {

			const sphere = new THREE.Mesh( geometry, new THREE.MeshStandardMaterial( { color, roughness: 0.8, metalness: 0 } ) );
			frameScene.add( sphere );
			return sphere;

		} );
		moveSpheres( spheres, 0 );
		let volume: LightProbeVolume | null = null;
		if ( variant.probe === 'ours' ) {

			volume = new LightProbeVolume( { positions, sh: captured.sh } );
			for ( const sphere of spheres ) volume.add( sphere, { perVertex: variant.perVertex } );
			if ( variant.fragment !== undefined ) {

				for ( const sphere of spheres ) overrideProbeFunction( sphere.material as THREE.Material, variant.name, variant.fragment );

			}

			volume.update();

		}

		return { variant, scene: frameScene, spheres, volume };

	} );
	for ( const b of built ) renderer.compile( b.scene, camera );
	return { programs: renderer.info.programs?.length ?? 0, tetrahedra: captured.interpolator.cellCount };

}

/** One timed frame of variant `index` at animation step `at`: [ volume.update() ] + render + 1-pixel read-back. */
function frame( index: number, at: number ): number {

	const b = built[ index ];
	moveSpheres( b.spheres, at );
	const start = performance.now();
	if ( b.volume !== null && b.variant.noUpdate !== true ) b.volume.update();
	renderer.render( b.scene, camera );
	syncCanvas();
	return performance.now() - start;

}

/**
 * `warmUp` untimed steps, then `frames` timed ones; each step renders one frame of every variant,
 * in an order rotated per step. Returns the frame times, `times[ variant ][ step ]`.
 */
function runFrames( warmUp: number, frames: number ): number[][] {

	const times = built.map( (): number[] => [] );
	for ( let f = 0; f < warmUp + frames; f ++ ) {

		const at = step ++;
		for ( let v = 0; v < built.length; v ++ ) {

			const index = ( v + at ) % built.length;
			const ms = frame( index, at );
			if ( f >= warmUp ) times[ index ].push( ms );

		}

	}

	return times;

}

/** `frames` frames of variant `index` alone (for CPU accounting per process); total ms. */
function runOne( index: number, frames: number ): number {

	const start = performance.now();
	for ( let f = 0; f < frames; f ++ ) frame( index, step ++ );
	return performance.now() - start;

}

/** WebGL calls of one frame of variant `index`, by function name (uniform uploads among them). */
function countGL( index: number ): Record<string, number> {

	const counts: Record<string, number> = {};
	const context = gl as unknown as Record<string, unknown>;
	const wrapped: string[] = [];
	for ( const key of Object.getOwnPropertyNames( WebGL2RenderingContext.prototype ) ) {

		const original = context[ key ];
		if ( typeof original !== 'function' || key === 'constructor' ) continue;
		context[ key ] = function ( this: unknown, ...args: unknown[] ) {

			counts[ key ] = ( counts[ key ] ?? 0 ) + 1;
			return ( original as ( ...a: unknown[] ) => unknown ).apply( gl, args );

		};

		wrapped.push( key );

	}

	try {

		frame( index, step );

	} finally {

		for ( const key of wrapped ) delete context[ key ];

	}

	counts.drawCalls = renderer.info.render.calls;
	return counts;

}

/** The canvas of one frame of variant `index` at step `at`, RGBA bytes. */
function pixels( index: number, at: number ): Uint8Array {

	frame( index, at );
	const out = new Uint8Array( 4 * WIDTH * HEIGHT );
	gl.readPixels( 0, 0, WIDTH, HEIGHT, gl.RGBA, gl.UNSIGNED_BYTE, out );
	return out;

}

/** Largest channel difference and differing pixel count between variants `a` and `b` at one step. */
function compare( a: number, b: number, at = 37 ): { max: number, pixels: number, mean: number[] } {

	const pa = pixels( a, at ), pb = pixels( b, at );
	let max = 0, differing = 0;
	const mean = [ 0, 0, 0 ];
	for ( let i = 0; i < pa.length; i += 4 ) {

		let d = 0;
		for ( let c = 0; c < 3; c ++ ) {

			d = Math.max( d, Math.abs( pa[ i + c ] - pb[ i + c ] ) );
			mean[ c ] += pb[ i + c ] / ( WIDTH * HEIGHT );

		}

		if ( d > 0 ) differing ++;
		max = Math.max( max, d );

	}

	return { max, pixels: differing, mean };

}

/** The compiled fragment shader text of variant `index`'s first sphere (to check what runs). */
function fragmentSource( index: number ): string {

	const material = built[ index ].spheres[ 0 ].material as THREE.Material;
	const program = ( renderer.properties.get( material ) as { currentProgram?: { program: WebGLProgram } } ).currentProgram;
	if ( ! program ) return '';
	const shaders = gl.getAttachedShaders( program.program ) ?? [];
	return shaders.map( ( s ) => gl.getShaderSource( s ) ?? '' ).join( '\n//----\n' );

}

const api = { setup, runFrames, runOne, countGL, compare, fragmentSource };
Object.assign( window, { framesBench: api } );
export type FramesBenchApi = typeof api;

renderer.render( scene, camera );
syncCanvas();
Object.assign( window, { framesBenchReady: true } );
