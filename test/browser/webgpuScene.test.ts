import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

// The scene paths of WebGPURenderer (issue 15) in Chromium, on its WebGPU backend (SwiftShader's
// adapter) and its WebGL2 fallback: LightProbeVolume.fromScene, a capture with shadows, bounces off
// node-material and built-in scenery, recaptureDirty after a move, and a lost device or context in a
// bounce pass. test/browser/pages/webgpu-scene.ts runs every check on one backend; its independent
// truth is WebGLRenderer capturing the same scene in the same page, the shadow map switched off, and
// a fresh capture at the moved probe's place.

interface Run { passes: number; statics: number; lighting: string | null; meanL00: number[]; errors: number[] }

interface SceneResult {

	error?: string;
	isWebGPUBackend: boolean;
	fromScene: { count: number; inside: boolean; stages: string[]; error: number; meanL00: number };
	shadows: { draws: number[]; open: number[]; shadowed: number[]; repeat: number; autoUpdate: boolean };
	bounces: {
		webgl: Run; node: Run; plain: Run; webglAdded: Run; nodeAdded: Run; webglSH: Run; nodeSH: Run;
		irradianceVersusSH: number[];
	};
	recapture: {
		dirty: number[]; totals: number[]; othersSame: boolean; dirtyAfter: number[];
		movedVersusFresh: number; movedVersusBefore: number; redOverGreen: number[];
	};
	lossError: string;
	lossPasses: number;
	shKept: boolean;
	sceneryBack: boolean;

}

describe.skipIf( browserSkipReason !== '' )( `WebGPURenderer scene paths (Chromium)${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser( { webgpu: true } ); }, 60_000 );
	afterAll( async () => { await session?.close(); } );

	const results: Record<string, Promise<{ result: SceneResult; errors: string[] }>> = {};
	/** The page's result on one backend, loaded once for all its tests. */
	function resultOn( backend: string ): Promise<{ result: SceneResult; errors: string[] }> {

		results[ backend ] ??= ( async () => {

			const { page, errors } = await session.open( `test/browser/pages/webgpu-scene.html?backend=${backend}`, { width: 64, height: 64 } );
			await page.waitForFunction( 'window.__result !== undefined', { timeout: 280_000, polling: 500 } );
			const result = await page.evaluate( 'window.__result' ) as SceneResult;
			if ( process.env.DUMP ) console.log( 'DUMP', backend, JSON.stringify( result.bounces ) );
			await page.close();
			return { result, errors };

		} )();
		return results[ backend ];

	}

	for ( const backend of [ 'webgpu', 'webgl2' ] ) {

		it( `${backend}: the page runs on the ${backend === 'webgpu' ? 'WebGPU' : 'WebGL2'} backend without errors`, async () => {

			const { result, errors } = await resultOn( backend );
			expect( result.error ).toBeUndefined();
			expect( result.isWebGPUBackend ).toBe( backend === 'webgpu' );
			// The lost device or context at the end logs its loss; nothing else may.
			expect( errors.filter( ( e ) => ! /lost|CONTEXT_LOST|destroyed/i.test( e ) ) ).toEqual( [] );

		}, 300_000 );

		it( `${backend}: fromScene (budget 8, candidates at 8², probes at 16², unfitted) gives 8 probes in the room whose SH are WebGLRenderer's captures there`, async () => {

			const { fromScene } = ( await resultOn( backend ) ).result;
			expect( fromScene.count ).toBe( 8 );
			expect( fromScene.inside ).toBe( true );
			expect( fromScene.stages ).toEqual( [ 'candidates', 'capture', 'reduce', 'recapture', 'fit' ] );
			expect( fromScene.meanL00 ).toBeGreaterThan( 0.05 );
			// The 1e-4 of L00 (HalfFloat targets). The Basic room has no box edge that falls on a texel's
			// tie (the 1.5 % of docs/webgpu-capture.md): 5e-6 measured on the WebGPU backend, 5e-8 on WebGL2 (session 22).
			expect( fromScene.error ).toBeLessThan( 1e-4 );

		}, 300_000 );

		it( `${backend}: with shadows the map is drawn once per capture, the probe under the slab gets less light, the open one the same`, async () => {

			const { shadows } = ( await resultOn( backend ) ).result;
			expect( shadows.draws ).toEqual( [ 0, 1, 1 ] );
			expect( shadows.shadowed[ 0 ] / shadows.open[ 0 ], 'probe in shadow' ).toBeLessThan( 0.8 );
			// The slab's shadow is in the open probe's view too, 3.5 m away, low on its horizon: 1.1 % measured.
			expect( Math.abs( shadows.shadowed[ 1 ] / shadows.open[ 1 ] - 1 ), 'probe in the open' ).toBeLessThan( 0.03 );
			expect( shadows.repeat, 'a second capture with shadows' ).toBeLessThan( 1e-6 );
			expect( shadows.autoUpdate ).toBe( true );

		}, 300_000 );

		it( `${backend}: two bounces off node-material and built-in scenery (per-vertex irradiance or SH, or lit by the volume) add the light WebGLRenderer's bounces add`, async () => {

			const { bounces } = ( await resultOn( backend ) ).result;
			const { webgl, node, plain, webglAdded, nodeAdded, webglSH, nodeSH, irradianceVersusSH } = bounces;
			for ( const run of [ webgl, node, plain, webglAdded, nodeAdded, webglSH, nodeSH ] ) {

				expect( run.passes ).toBe( 3 );
				// Bounce scenery lit per vertex for the passes, or (added) lit by the volume itself.
				expect( run.statics ).toBe( run === webglAdded || run === nodeAdded ? 0 : 1 );
				// Each bounce adds light, less than the pass before (albedo < 1).
				const added = [ run.meanL00[ 1 ] - run.meanL00[ 0 ], run.meanL00[ 2 ] - run.meanL00[ 1 ] ];
				expect( added[ 0 ] ).toBeGreaterThan( 0.1 * run.meanL00[ 0 ] );
				expect( added[ 1 ] ).toBeGreaterThan( 0 );
				expect( added[ 1 ] ).toBeLessThan( added[ 0 ] );

			}

			// The room's walls are BackSide: per-vertex irradiance is E of the flipped normal, as the walls are shaded
			// (before session 22 it took the geometry's outward normal: pass 1 8 % brighter than with SH, pass 2 13 %).
			irradianceVersusSH.forEach( ( error, pass ) => expect( error, `irradiance against SH, pass ${pass}` ).toBeLessThan( 1e-4 ) );
			expect( nodeAdded.lighting ).toBe( webglAdded.lighting );
			expect( webglAdded.lighting ).not.toBe( null );
			// Every pass within the 1e-4 of L00 of WebGLRenderer's (HalfFloat targets: shading that differs
			// below half-float precision gives the same texels); ≤ 2.5e-6 measured (session 22). Node-material scenery that
			// took no bounce light would stay at pass 0's light, 22 % below pass 1's.
			for ( const [ run, truth ] of [ [ node, webgl ], [ plain, webgl ], [ nodeAdded, webglAdded ], [ nodeSH, webglSH ] ] ) {

				run.errors.forEach( ( error, pass ) => expect( error, `pass ${pass}` ).toBeLessThan( 1e-4 ) );
				const added = run.meanL00[ 1 ] - run.meanL00[ 0 ], truthAdded = truth.meanL00[ 1 ] - truth.meanL00[ 0 ];
				expect( Math.abs( added / truthAdded - 1 ), 'first bounce against WebGLRenderer\'s' ).toBeLessThan( 1e-3 );

			}

		}, 300_000 );

		it( `${backend}: recaptureDirty after moving a probe captures it alone, to what a fresh capture there gives`, async () => {

			const { recapture } = ( await resultOn( backend ) ).result;
			expect( recapture.dirty ).toEqual( [ 1 ] );
			expect( recapture.totals.every( ( total ) => total === 1 ) && recapture.totals.length > 0 ).toBe( true );
			expect( recapture.othersSame ).toBe( true );
			expect( recapture.dirtyAfter ).toEqual( [] );
			expect( recapture.movedVersusFresh ).toBeLessThan( 1e-6 );
			expect( recapture.movedVersusBefore ).toBeGreaterThan( 0.05 );
			expect( recapture.redOverGreen[ 1 ] ).toBeGreaterThan( recapture.redOverGreen[ 0 ] );

		}, 300_000 );

		it( `${backend}: a ${backend === 'webgpu' ? 'device' : 'context'} lost between bounce passes gives the named error, keeps the SH and restores the scenery`, async () => {

			const { result } = await resultOn( backend );
			expect( result.lossError ).toMatch( backend === 'webgpu' ? /^WebGPUProbeCapturer\.capture: the WebGPU device was lost/ : /^WebGPUProbeCapturer\.capture: the WebGL context was lost/ );
			expect( result.lossPasses ).toBe( 1 );
			expect( result.shKept ).toBe( true );
			expect( result.sceneryBack ).toBe( true );

		}, 300_000 );

	}

} );
