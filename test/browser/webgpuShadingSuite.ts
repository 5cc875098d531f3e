import type { Page } from 'puppeteer-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

/** The two backends of WebGPURenderer. */
export type ShadingBackend = 'webgpu' | 'webgl2';

// Node-material shading on WebGPURenderer, both backends (WebGPU on SwiftShader's adapter and
// `forceWebGL: true`), against independent truth: three's own LightProbe holding the volume's SH,
// the average of two probes, and WebGLRenderer drawing the same volume with the WebGL patch. The
// page (pages/webgpu-shading.ts) renders 64² linear RGBA8 targets and returns differences.

type Diff = { max: number; count: number; covered: number };

/** The shading tests on one backend (a file each: each stays near a minute on a loaded machine). */
export function shadingSuite( backend: ShadingBackend ): void {

	describe.skipIf( browserSkipReason !== '' )( `node-material shading on WebGPURenderer, backend ${backend} (Chromium)${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

		let session: BrowserSession;
		let page: Page;
		let errors: string[];
		let webgpu = false;

		beforeAll( async () => {

			session = await startBrowser( { webgpu: true } );
			// Opened here rather than with session.open: on a loaded machine the first transform of three's
			// node system can take longer than puppeteer's default 30 s navigation timeout.
			page = await session.browser.newPage();
			errors = [];
			page.on( 'pageerror', ( error ) => errors.push( ( error as Error ).message ) );
			page.on( 'console', ( message ) => { if ( message.type() === 'error' ) errors.push( message.text() ); } );
			await page.goto( `${session.baseUrl}test/browser/pages/webgpu-shading.html`, { waitUntil: 'load', timeout: 120_000 } );
			await page.waitForFunction( 'window.shadingReady === true', { timeout: 60_000 } );
			webgpu = await page.evaluate( 'window.shading.hasWebGPU()' ) as boolean;

		}, 180_000 );

		afterAll( async () => {

			await session?.close();

		} );

		function call<T>( name: string, ...args: unknown[] ): Promise<T> {

			return page.evaluate( `window.shading.${name}( ...${JSON.stringify( args )} )` ) as Promise<T>;

		}

		it.runIf( backend === 'webgpu' )( 'the page has a WebGPU adapter (SwiftShader)', () => {

			expect( webgpu ).toBe( true );

		} );

		for ( const mode of [ 'object', 'perVertex', 'vertex', 'vertexSH', 'texture' ] as const ) {

			it( `mode ${mode}: Standard + Physical node materials lit by a volume of SKY probes look as lit by a LightProbe with SKY (≤ 2/255)`, async () => {

				const result = await call<Diff & { unlitCovered: number; lighting: string[] }>( 'versusLightProbe', backend, mode, 'mixed' );
				expect( result.covered ).toBeGreaterThan( 400 );
				// Without the volume the spheres are black: the light compared is the probe light.
				expect( result.unlitCovered ).toBe( 0 );
				expect( result.count, `max ${result.max}` ).toBe( 0 );
				const lighting = mode === 'object' || mode === 'perVertex' ? 'dynamic' : mode === 'texture' ? 'texture' : 'vertex';
				expect( result.lighting ).toEqual( [ lighting, lighting ] );

			}, 60_000 );

		}

		it( 'plain MeshStandardMaterial / MeshPhysicalMaterial (converted by three) are lit as by a LightProbe (≤ 2/255)', async () => {

			const result = await call<Diff & { unlitCovered: number }>( 'versusLightProbe', backend, 'object', 'plain' );
			expect( result.covered ).toBeGreaterThan( 400 );
			expect( result.unlitCovered ).toBe( 0 );
			expect( result.count, `max ${result.max}` ).toBe( 0 );

		}, 60_000 );

		it( 'an object halfway between two probes gets their average (≤ 2/255), not one of them', async () => {

			const result = await call<Diff & { versusRed: number }>( 'halfway', backend );
			expect( result.covered ).toBeGreaterThan( 400 );
			expect( result.count, `max ${result.max}` ).toBe( 0 );
			expect( result.versusRed ).toBeGreaterThan( 20 );

		}, 60_000 );

		for ( const mode of [ 'object', 'vertex', 'texture' ] as const ) {

			for ( const kind of [ 'node', 'plain' ] as const ) {

				it( `mode ${mode}, ${kind} materials: the same picture as WebGLRenderer drawing the same volume (≤ 2/255)`, async () => {

					const result = await call<Diff & { control: Diff }>( 'versusWebGL', backend, mode, kind );
					expect( result.covered ).toBeGreaterThan( 400 );
					expect( result.count, `max ${result.max} (LightProbe control: max ${result.control.max})` ).toBe( 0 );

				}, 60_000 );

			}

		}

		for ( const kind of [ 'node', 'plain' ] as const ) {

			it( `10 probe-lit spheres sharing one ${kind} material add ≤ 1 pipeline (each has its own clone and uniforms)`, async () => {

				const result = await call<{ added: number; materials: number; restored: boolean; litCovered: number }>( 'sharing', backend, kind );
				expect( result.materials ).toBe( 10 );
				expect( result.litCovered ).toBeGreaterThan( 50 );
				// One new pipeline: the probe-lit graph (none would mean the light is not in the shader).
				expect( result.added ).toBe( 1 );
				expect( result.restored ).toBe( true );

			}, 60_000 );

			it( `${kind} materials: direct scale 0 shows the probe light alone, intensity ½ halves it (each = its LightProbe picture, ≤ 2/255)`, async () => {

				const result = await call<{ full: Diff; indirect: Diff; half: Diff; fullVersusIndirect: number }>( 'views', backend, kind );
				expect( result.full.count, `full: max ${result.full.max}` ).toBe( 0 );
				expect( result.indirect.count, `indirect only: max ${result.indirect.max}` ).toBe( 0 );
				expect( result.half.count, `half: max ${result.half.max}` ).toBe( 0 );
				expect( result.fullVersusIndirect ).toBeGreaterThan( 20 );

			}, 60_000 );

			it( `${kind} materials: add / remove / dispose cycles restore the material (own properties, picture) and light it the same each time`, async () => {

				const result = await call<{ report: { extraKeys: string; litMax: number; unlitMax: number; keysRestored: boolean; sameMaterial: boolean }[]; litVersusUnlit: number }>( 'cycles', backend, kind );
				expect( result.litVersusUnlit ).toBeGreaterThan( 20 );
				for ( const cycle of result.report ) {

					expect( cycle.keysRestored, cycle.extraKeys ).toBe( true );
					expect( cycle.sameMaterial ).toBe( true );
					expect( cycle.unlitMax ).toBe( 0 );
					expect( cycle.litMax ).toBeLessThanOrEqual( 2 );

				}

			}, 60_000 );

		}

		it( 'no page errors', () => {

			expect( errors ).toEqual( [] );

		} );

	} );

}
