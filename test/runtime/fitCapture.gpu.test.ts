/**
 * The capture option `fit` on a real GL context (headless-gl, WebGL2): probes captured in a light
 * field known in closed form — an environment whose SH at every point is a smooth, non-linear
 * function of the position — then fitted to extra captured points. Judged on held-out points
 * against the analytic SH: fitting lowers the error of the same probes, gradients lower it more;
 * the fit record is stored; an edit and `recaptureDirty` refit the edited layout to the stored
 * samples (as a fresh fit with the same λ would), and a volume loaded from a file (no samples) loses its fit
 * record and the captured probes' gradients instead; a capture that fails while capturing the fit
 * points changes nothing; a capture without `fit` makes the volume plain again; bad options get
 * named errors before anything is captured.
 *
 * Needs an X display for headless-gl: `xvfb-run -a npx vitest run test/runtime/fitCapture.gpu.test.ts`.
 */

import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume, type LightProbeVolumeCaptureOptions } from '../../src/runtime/LightProbeVolume.js';
import type { LightProbeVolumeFitOptions } from '../../src/runtime/fitVolume.js';
import { decodeBakedVolume } from '../../src/io/decodeBakedVolume.js';
import { encodeBakedVolume } from '../../src/io/encodeBakedVolume.js';
import { placeGrid } from '../../src/placement/placeGrid.js';
import { irradianceError } from '../../src/placement/irradianceError.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { analyticSH, directionEnvironment } from '../helpers/gpuScenes.js';
import { seededRandom } from '../helpers/pointSets.js';

const ctx = await createHeadlessRenderer( 16, 16 );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/**
 * The field: radiance Σ c_k(p) Y_k(d) with c_0 (constant over directions) and c_1 (along y) smooth
 * non-linear functions of the capture point p, so the SH at p is analyticSH( c( p ) ) — positive
 * irradiance everywhere, and far from linear across a cell of 2 m.
 */
function coefficients( x: number, y: number, z: number ): number[][] {

	const c0 = [
		1 + 0.6 * Math.sin( 1.3 * x ) * Math.cos( 0.9 * z ) + 0.15 * y * y,
		0.8 + 0.4 * Math.cos( 1.1 * y + 0.4 * x ),
		0.9 + 0.5 * Math.sin( 0.8 * z ),
	];
	const c1 = [ 0.15 + 0.15 * Math.sin( x ), 0.2, 0.25 * Math.cos( z ) ];
	return [ c0, c1, ...Array.from( { length: 7 }, () => [ 0, 0, 0 ] ) ];

}

const FIELD_GLSL = /* glsl */`
	vec3 c0 = vec3( 1.0 + 0.6 * sin( 1.3 * probe.x ) * cos( 0.9 * probe.z ) + 0.15 * probe.y * probe.y,
		0.8 + 0.4 * cos( 1.1 * probe.y + 0.4 * probe.x ), 0.9 + 0.5 * sin( 0.8 * probe.z ) );
	vec3 c1 = vec3( 0.15 + 0.15 * sin( probe.x ), 0.2, 0.25 * cos( probe.z ) );
	gl_FragColor = vec4( c0 * 0.282095 + c1 * ( 0.488603 * d.y ), 1.0 );
`;

/** The analytic SH at each point (27 floats each). */
function truthAt( points: ArrayLike<number> ): Float32Array {

	const out = new Float32Array( 9 * points.length );
	for ( let i = 0; i < points.length / 3; i ++ ) {

		out.set( analyticSH( coefficients( points[ 3 * i ], points[ 3 * i + 1 ], points[ 3 * i + 2 ] ) ), 27 * i );

	}

	return out;

}

/** The volume's blend at each point (what an object there is lit with). */
function sampled( volume: LightProbeVolume, points: ArrayLike<number> ): Float32Array {

	const out = new Float32Array( 9 * points.length );
	for ( let i = 0; i < points.length / 3; i ++ ) {

		volume.sample( [ points[ 3 * i ], points[ 3 * i + 1 ], points[ 3 * i + 2 ] ], out.subarray( 27 * i, 27 * i + 27 ) );

	}

	return out;

}

/** Points uniform in the cube [ −h, h ]³. */
function randomPoints( count: number, h: number, seed: number ): Float64Array {

	const random = seededRandom( seed ), out = new Float64Array( 3 * count );
	for ( let i = 0; i < out.length; i ++ ) out[ i ] = h * ( 2 * random() - 1 );
	return out;

}

describe.skipIf( ! ctx.renderer )( `capture option fit: probes fitted to extra captured points${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const scene = new THREE.Scene();
	scene.add( directionEnvironment( FIELD_GLSL ) );
	// 27 probes, a 3 × 3 × 3 grid 2 m apart: cells far larger than the field's features.
	const positions = placeGrid( [ - 2, - 2, - 2 ], [ 2, 2, 2 ], [ 3, 3, 3 ] );
	const held = randomPoints( 200, 1.9, 7 );
	const truth = truthAt( held );
	const error = ( volume: LightProbeVolume ) => irradianceError( sampled( volume, held ), truth ).mean;
	const captureWith = ( volume: LightProbeVolume, options: LightProbeVolumeCaptureOptions ) => volume.capture( renderer, scene, options );
	let plainError = 0, fittedError = 0;
	beforeAll( async () => {

		const plain = new LightProbeVolume( { positions } );
		await plain.capture( renderer, scene, { resolution: 16 } );
		plainError = error( plain );

	} );
	afterAll( () => ctx.dispose() );

	it( 'the captured probes hold the analytic SH (the field is what the test says it is)', async () => {

		const volume = new LightProbeVolume( { positions } );
		await volume.capture( renderer, scene, { resolution: 16 } );
		const expected = truthAt( positions );
		const scale = Math.max( ...expected.map( Math.abs ) );
		for ( let k = 0; k < expected.length; k ++ ) expect( Math.abs( volume.sh[ k ] - expected[ k ] ) ).toBeLessThan( 2e-3 * scale );

	} );

	it( 'fit: { spacing } lowers the held-out error of the same probes, and records how', async () => {

		const volume = new LightProbeVolume( { positions } );
		const stages: string[] = [];
		await captureWith( volume, {
			resolution: 16, fit: { spacing: 0.5 }, onProgress: ( done: number, total: number, stage?: string ) => {

				if ( done === total ) stages.push( `${stage} ${total}` );

			},
		} );
		fittedError = error( volume );
		console.log( `held-out mean irradiance error: captured ${plainError.toFixed( 4 )}, fitted ${fittedError.toFixed( 4 )}` );
		expect( fittedError ).toBeLessThan( 0.7 * plainError );
		// 8 × 8 × 8 cell centres 0.5 apart over the probes' box, all inside the hull and in open space.
		expect( stages ).toEqual( [ 'probes 27', 'fit 512' ] );
		expect( volume.gradients ).toBeNull();
		const record = volume.fitSettings!;
		expect( record ).toMatchObject( { samples: 512, gradients: false, gradientLambda: 0, source: 'dense captures at spacing 0.5' } );
		expect( record.lambda ).toBeGreaterThan( 0 );
		expect( record.crossValidationError ).toBeGreaterThan( 0 );
		expect( record.crossValidationError ).toBeLessThan( plainError );

	} );

	it( 'fit: { samples, gradients: true } — gradient probes fitted jointly lower the error further', async () => {

		const volume = new LightProbeVolume( { positions } );
		const samples = randomPoints( 400, 2, 11 ); // another seed than the held-out points
		await captureWith( volume, { resolution: 16, fit: { samples, gradients: true } } );
		const gradientError = error( volume );
		console.log( `held-out mean irradiance error with gradient probes: ${gradientError.toFixed( 4 )} (plain fit ${fittedError.toFixed( 4 )})` );
		expect( volume.gradients ).toBeInstanceOf( Float32Array );
		expect( volume.gradients!.length ).toBe( 81 * 27 );
		expect( gradientError ).toBeLessThan( 0.8 * fittedError );
		expect( volume.fitSettings ).toMatchObject( { samples: 400, gradients: true, source: '400 given points' } );
		expect( volume.fitSettings!.gradientLambda ).toBeGreaterThan( 0 );

	} );

	it( 'λ given: the record says so (no cross-validation error), and the same λ gives the same fit', async () => {

		const samples = randomPoints( 100, 2, 13 );
		const first = new LightProbeVolume( { positions } ), second = new LightProbeVolume( { positions } );
		await captureWith( first, { resolution: 16, fit: { samples, lambda: 0.05 } } );
		await captureWith( second, { resolution: 16, fit: { samples, lambda: 0.05 } } );
		expect( first.fitSettings ).toMatchObject( { lambda: 0.05, crossValidationError: null, samples: 100 } );
		expect( Array.from( second.sh ) ).toEqual( Array.from( first.sh ) );

	} );

	it( 'a capture without fit makes a fitted volume plain again: captured SH, no gradients, no record', async () => {

		const volume = new LightProbeVolume( { positions } );
		await captureWith( volume, { resolution: 16, fit: { samples: randomPoints( 100, 2, 17 ), gradients: true } } );
		await volume.capture( renderer, scene, { resolution: 16 } );
		const plain = new LightProbeVolume( { positions } );
		await plain.capture( renderer, scene, { resolution: 16 } );
		expect( volume.gradients ).toBeNull();
		expect( volume.fitSettings ).toBeNull();
		expect( Array.from( volume.sh ) ).toEqual( Array.from( plain.sh ) );

	} );

	it( 'all or nothing: a capture that fails while capturing the fit points leaves SH, gradients, record and dirty set as they were', async () => {

		const volume = new LightProbeVolume( { positions } );
		await captureWith( volume, { resolution: 16, fit: { samples: randomPoints( 60, 2, 19 ), gradients: true } } );
		volume.moveProbe( 13, [ 0.1, 0.2, 0.1 ] ); // the centre probe: dirty
		const state = () => JSON.stringify( {
			sh: Array.from( volume.sh ), gradients: Array.from( volume.gradients ?? [] ), fit: volume.fitSettings,
			dirty: volume.dirtyProbes(), settings: volume.captureSettings,
		} );
		const before = state();
		// Render calls: 6 per probe; the fit points come after the 27 probes.
		const original = renderer.render;
		let calls = 0;
		renderer.render = function ( ...args: Parameters<typeof original> ) {

			calls ++;
			if ( calls === 6 * 27 + 6 * 10 ) throw new Error( 'injected failure in the fit points' );
			return original.apply( this, args );

		};

		try {

			await expect( captureWith( volume, { resolution: 16, fit: { samples: randomPoints( 40, 2, 23 ) } } ) )
				.rejects.toThrow( 'injected failure in the fit points' );

		} finally {

			renderer.render = original;

		}

		expect( calls ).toBe( 6 * 27 + 6 * 10 );
		expect( state() ).toBe( before );

	} );

	it( 'an edit and recaptureDirty refit the edited layout to the stored fit points, as a fresh fit with the same λ does', async () => {

		const samples = randomPoints( 300, 2, 29 );
		const volume = new LightProbeVolume( { positions } );
		await captureWith( volume, { resolution: 16, fit: { samples, gradients: true } } );
		const first = { ...volume.fitSettings! };
		volume.moveProbe( 13, [ 0.4, - 0.3, 0.2 ] ); // the centre probe
		await volume.recaptureDirty( renderer, scene, { resolution: 16 } );
		expect( volume.dirtyProbes() ).toEqual( [] );
		// The same samples captured again, the same interpolator (the edited volume's own), the λ chosen before.
		const fresh = new LightProbeVolume( { positions: volume.positions, interpolator: volume.interpolator } );
		const { lambda, gradientLambda } = first;
		await captureWith( fresh, { resolution: 16, fit: { samples, gradients: true, lambda, gradientLambda } } );
		const scale = Math.max( ...fresh.sh.map( Math.abs ) );
		for ( let k = 0; k < fresh.sh.length; k ++ ) expect( Math.abs( volume.sh[ k ] - fresh.sh[ k ] ) ).toBeLessThan( 1e-5 * scale );
		const gradientScale = Math.max( ...fresh.gradients!.map( Math.abs ) );
		for ( let k = 0; k < fresh.gradients!.length; k ++ ) {

			expect( Math.abs( volume.gradients![ k ] - fresh.gradients![ k ] ) ).toBeLessThan( 1e-5 * gradientScale );

		}

		expect( volume.fitSettings ).toEqual( {
			samples: 300, gradients: true, lambda: first.lambda, gradientLambda: first.gradientLambda, crossValidationError: null,
			source: '300 given points; refitted after probe edits',
		} );

		// Removing a probe needs no capture, but the layout changed: recaptureDirty refits it.
		const before = volume.sh.slice();
		volume.removeProbe( 4 );
		await volume.recaptureDirty( renderer, scene, { resolution: 16 } );
		expect( Array.from( volume.sh.subarray( 27 * 4, 27 * 5 ) ).every( ( v ) => v === 0 ) ).toBe( true );
		expect( Array.from( volume.gradients!.subarray( 81 * 4, 81 * 5 ) ).every( ( v ) => v === 0 ) ).toBe( true );
		expect( Array.from( volume.sh ) ).not.toEqual( Array.from( before ) );
		// Nothing changed since: recaptureDirty does nothing.
		const after = volume.sh.slice();
		await volume.recaptureDirty( renderer, scene, { resolution: 16 } );
		expect( Array.from( volume.sh ) ).toEqual( Array.from( after ) );

	} );

	it( 'loaded from a file (a fit record, no samples): a partial capture zeroes the captured probes\' gradients and drops the record', async () => {

		const samples = randomPoints( 300, 2, 31 );
		const fitted = new LightProbeVolume( { positions } );
		await captureWith( fitted, { resolution: 16, fit: { samples, gradients: true } } );
		const loaded = LightProbeVolume.fromBakedData( decodeBakedVolume( encodeBakedVolume( fitted.toBakedData() ) ) );
		expect( loaded.fitSettings ).toEqual( fitted.fitSettings );
		const sh = loaded.sh.slice(), gradients = loaded.gradients!.slice();
		// Probe 5 is not moved: before the fix it would have kept its fitted gradient beside its captured SH.
		expect( gradients.subarray( 81 * 5, 81 * 6 ).some( ( v ) => v !== 0 ) ).toBe( true );
		await captureWith( loaded, { resolution: 16, indices: [ 5 ] } );
		expect( loaded.fitSettings ).toBeNull();
		expect( Array.from( loaded.gradients!.subarray( 81 * 5, 81 * 6 ) ).every( ( v ) => v === 0 ) ).toBe( true );
		// Its SH are the captured ones (the analytic field there, as the first test checks), the other probes untouched.
		const expected = truthAt( positions.subarray( 15, 18 ) );
		const scale = Math.max( ...expected.map( Math.abs ) );
		for ( let k = 0; k < 27; k ++ ) expect( Math.abs( loaded.sh[ 135 + k ] - expected[ k ] ) ).toBeLessThan( 2e-3 * scale );
		for ( let i = 0; i < 27; i ++ ) {

			if ( i === 5 ) continue;
			expect( Array.from( loaded.sh.subarray( 27 * i, 27 * i + 27 ) ) ).toEqual( Array.from( sh.subarray( 27 * i, 27 * i + 27 ) ) );
			const gradient = Array.from( gradients.subarray( 81 * i, 81 * i + 81 ) );
			expect( Array.from( loaded.gradients!.subarray( 81 * i, 81 * i + 81 ) ) ).toEqual( gradient );

		}

		// The same after an edit: recaptureDirty of a moved probe of another loaded copy.
		const edited = LightProbeVolume.fromBakedData( decodeBakedVolume( encodeBakedVolume( fitted.toBakedData() ) ) );
		edited.moveProbe( 13, [ 0.4, - 0.3, 0.2 ] );
		await edited.recaptureDirty( renderer, scene, { resolution: 16 } );
		expect( edited.fitSettings ).toBeNull();
		expect( Array.from( edited.gradients!.subarray( 81 * 13, 81 * 14 ) ).every( ( v ) => v === 0 ) ).toBe( true );
		// A capture of nothing (no dirty probe) keeps a loaded record.
		const untouched = LightProbeVolume.fromBakedData( decodeBakedVolume( encodeBakedVolume( fitted.toBakedData() ) ) );
		await untouched.recaptureDirty( renderer, scene, { resolution: 16 } );
		expect( untouched.fitSettings ).toEqual( fitted.fitSettings );

	} );

	it( 'bad fit options get named errors before anything is captured', async () => {

		const volume = new LightProbeVolume( { positions } );
		const capture = ( fit: unknown ) => captureWith( volume, { resolution: 16, fit: fit as LightProbeVolumeFitOptions } );
		const where = 'LightProbeVolume.capture';
		await expect( capture( 5 ) ).rejects.toThrow( new RegExp( `^${where}: options.fit must be an object` ) );
		await expect( capture( {} ) ).rejects.toThrow( new RegExp( `^${where}: options.fit needs either samples .* or spacing .*, got neither` ) );
		await expect( capture( { samples: [ 0, 0, 0 ], spacing: 1 } ) ).rejects.toThrow( /options.fit needs either .*got both/ );
		await expect( capture( { spacing: 0 } ) ).rejects.toThrow( new RegExp( `^${where}: options.fit.spacing must be > 0, got 0` ) );
		await expect( capture( { spacing: 1e-3 } ) ).rejects.toThrow( /options.fit.spacing 0.001 lays 4000 × 4000 × 4000 = .* fit points/ );
		await expect( capture( { samples: [ 0, NaN, 0 ] } ) ).rejects.toThrow( new RegExp( `^${where}: options.fit.samples` ) );
		await expect( capture( { samples: [ 0, 0 ] } ) ).rejects.toThrow( new RegExp( `^${where}: options.fit.samples` ) );
		await expect( capture( { spacing: 1, lambda: - 1 } ) )
			.rejects.toThrow( new RegExp( `^${where}: options.fit.lambda must be 'auto' or a finite number ≥ 0, got -1` ) );
		await expect( capture( { spacing: 1, gradients: 'yes' } ) ).rejects.toThrow( new RegExp( `^${where}: options.fit.gradients` ) );
		await expect( capture( { spacing: 1, step: 2 } ) ).rejects.toThrow( new RegExp( `^${where}: options.fit has the unknown option "step"` ) );
		await expect( capture( { spacing: 1, region: { boxes: [ { min: [ 10, 10, 10 ], max: [ 11, 11, 11 ] } ] } } ) )
			.rejects.toThrow( new RegExp( `^${where}: options.fit.region contains none of the` ) );
		const zoned = new LightProbeVolume( { positions, zones: [ { name: 'all', probes: Array.from( { length: 27 }, ( _, i ) => i ) } ] } );
		await expect( captureWith( zoned, { fit: { spacing: 1 } } ) )
			.rejects.toThrow( new RegExp( `^${where}: options.fit is not taken for a volume with lighting zones` ) );
		expect( Array.from( volume.sh ).every( ( v ) => v === 0 ) ).toBe( true ); // nothing was captured
		expect( volume.fitSettings ).toBeNull();

	} );

} );
