import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

// WebGPURenderer capture (issue 15) in Chromium, on its WebGPU backend (SwiftShader's adapter) and
// its WebGL2 fallback: test/browser/pages/webgpu-capture.ts runs each check on one backend.
describe.skipIf( browserSkipReason !== '' )( `WebGPURenderer capture (Chromium)${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser( { webgpu: true } ); } );
	afterAll( async () => { await session?.close(); } );

	for ( const backend of [ 'webgpu', 'webgl2' ] ) {

		it( `${backend}: analytic SH, the WebGLRenderer's SH, panoramas, freed resources, a lost ${backend === 'webgpu' ? 'device' : 'context'}`, async () => {

			const { page, errors } = await session.open( `test/browser/pages/webgpu-capture.html?backend=${backend}`, { width: 64, height: 64 } );
			await page.waitForFunction( 'window.__result !== undefined', { timeout: 120_000 } );
			const result = await page.evaluate( 'window.__result' ) as Record<string, unknown>;
			expect( result.error ).toBeUndefined();
			expect( result.adapter ).toBe( true );
			expect( result.isWebGPUBackend ).toBe( backend === 'webgpu' );
			expect( result.analyticError, 'painted SH environment' ).toBeLessThan( 5e-3 );
			expect( result.progressCalls ).toBe( 4 );
			expect( result.projectionError, 'projection = CPU projection of the read-back faces' ).toBeLessThan( 1e-5 );
			expect( result.projectionErrorOdd, 'the same at 15²' ).toBeLessThan( 1e-5 );
			// Both backends lay the faces out texel for texel as WebGLRenderer's CubeCamera (the WebGPU backend
			// through its own cameras with a y-negated projection and mirrored front faces, docs/webgpu-capture.md):
			// every texel of every face of the four probes equal to WebGL's (walls, boxes and a sprite), hence the
			// same SH to float rounding. (With three's WebGPU CubeCamera, mirrored faces, 3-8 box-edge texels
			// differed: 1.5 % of L00; with the sprite's side not swapped it is culled, 4-24 texels.)
			expect( result.faceDiffs, 'face texels differing from WebGLRenderer\'s, per probe' ).toEqual( [ 0, 0, 0, 0 ] );
			const perProbe = result.webglPerProbe as number[];
			expect( perProbe ).toHaveLength( 4 );
			for ( const [ p, error ] of perProbe.entries() ) expect( error, `probe ${p}: same room, WebGLRenderer` ).toBeLessThan( 1e-4 );
			expect( result.webglError, 'same room, WebGLRenderer' ).toBeLessThan( 1e-4 );
			// Ordinary draws of the same meshes after the captures are unchanged (walls and box both drawn), and no
			// mesh keeps the capture's mirrored determinant.
			expect( result.viewUnchanged, 'a view drawn before and after the captures' ).toBe( true );
			expect( result.viewColours as string[] ).toHaveLength( 2 );
			expect( result.ownDeterminants ).toBe( 0 );
			// A shadow map drawn inside a face's draw (from the light's camera) keeps the mesh's own winding; the face
			// cameras' draws see it mirrored on the WebGPU backend only.
			const draws = result.shadowDraws as { face: number, faceFlipped: number, other: number, otherFlipped: number };
			expect( draws.face, 'draws of the caster by the face cameras' ).toBeGreaterThan( 0 );
			expect( draws.other, 'draws of the caster into the shadow map' ).toBeGreaterThan( 0 );
			expect( draws.faceFlipped ).toBe( backend === 'webgpu' ? draws.face : 0 );
			expect( draws.otherFlipped ).toBe( 0 );
			// A double-sided Lambert plane seen and lit from its back: lit as on WebGLRenderer (a wrong `frontFacing`
			// in the face cameras' draws turns its normal away: L00 0; measured equal to WebGLRenderer's, session 22).
			const [ backGPU, backGL ] = result.backLitL00 as number[];
			expect( backGL, 'WebGLRenderer sees the lit back' ).toBeGreaterThan( 0.1 );
			expect( Math.abs( backGPU - backGL ) / backGL, 'double-sided plane seen from its back' ).toBeLessThan( 1e-3 );
			// Panoramas at 64 × 32 and 100 × 49: directions and row solid angles from a float64 table (with the
			// shader's float32 sin / cos, SwiftShader's, the quadratic coefficients were 3.3e-4 of L00 off).
			expect( result.panoramaError, 'panorama against the CPU projection' ).toBeLessThan( 1e-4 );
			expect( result.memoryAfter ).toEqual( result.memoryBefore );
			expect( result.lossError ).toMatch( backend === 'webgpu' ? /^WebGPUProbeCapturer\.capture: the WebGPU device was lost/ : /^WebGPUProbeCapturer\.capture: the WebGL context was lost/ );
			expect( result.shKept ).toBe( true );
			expect( result.lostError ).toMatch( /was lost/ );
			expect( errors.filter( ( e ) => ! /lost|CONTEXT_LOST|destroyed/i.test( e ) ) ).toEqual( [] );

		} );

	}

} );
