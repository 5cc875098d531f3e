import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { Color, SphericalHarmonics3, Vector3 } from 'three';
import { LightProbeVolume, LightProbeVolumeHelper } from '../../src/index.js';
import { helperMaterials } from '../../src/runtime/helperHooks.js';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

/*
 * LightProbeVolumeHelper on WebGPURenderer (issue 15): with the node material the webgpu entry
 * installs (src/webgpu/installHelper.ts), a probe sphere holding known SH draws, at its centre
 * pixel, the colour three's own SphericalHarmonics3.getIrradianceAt predicts — max( E(n), 0 ) / π,
 * sRGB-encoded — within 2/255, on the WebGPU backend and on the WebGL2 backend (forceWebGL).
 * Four probes with every SH coefficient nonzero, each seen along three directions at vertices of
 * the sphere mesh (so the pixel's normal is that direction exactly, and all nine basis functions
 * count): a wrong coefficient order, packing or instance stride would show.
 */

interface HelperPixels {

	backend: string;
	material: string;
	nodeMaterial: boolean;
	sh: number[];
	pixels: { probe: number; normal: number[]; rgb: number[] }[];
	error?: string;

}

/** The sRGB byte three's output stage writes for a linear value (its transfer function, unrounded). */
function srgbByte( linear: number ): number {

	return 255 * new Color( linear, 0, 0 ).convertLinearToSRGB().r;

}

/** What the helper should draw: three's irradiance for the probe's SH and the normal, / π, encoded. */
function expectedRGB( sh: number[], probe: number, normal: number[] ): number[] {

	const harmonics = new SphericalHarmonics3().fromArray( sh, 27 * probe );
	const e = harmonics.getIrradianceAt( new Vector3( ...normal ), new Vector3() );
	return [ e.x, e.y, e.z ].map( ( v ) => srgbByte( Math.min( 1, Math.max( 0, v ) / Math.PI ) ) );

}

describe( 'LightProbeVolumeHelper without the webgpu entry', () => {

	it( 'uses the GLSL material, and a WebGPURenderer drawing it gets a named error before three fails on its own', () => {

		expect( helperMaterials() ).toBeNull();
		const volume = new LightProbeVolume( { positions: [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 ] } );
		const helper = new LightProbeVolumeHelper( volume );
		expect( helper.probes.material.type ).toBe( 'ShaderMaterial' );
		const { probes } = helper;
		const camera = { parent: null } as never;
		const draw = ( renderer: object ) => probes.onBeforeRender(
			renderer as never, null as never, camera, probes.geometry, probes.material, null as never );
		expect( () => draw( { isWebGPURenderer: true } ) ).toThrow( /^LightProbeVolumeHelper: drawn by a WebGPURenderer.*three-capture-lighting\/webgpu/ );
		expect( () => draw( { isWebGLRenderer: true } ) ).not.toThrow();
		helper.dispose();

	} );

} );

describe.skipIf( browserSkipReason !== '' )( `LightProbeVolumeHelper on WebGPURenderer (Chromium)${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser( { webgpu: true } ); }, 60_000 );
	afterAll( async () => { await session?.close(); } );

	for ( const backend of [ 'webgpu', 'webgl2' ] ) {

		it( `${backend} backend: each probe sphere's centre pixel is max( E(n), 0 ) / π of its own SH, within 2/255`, async () => {

			const url = `test/browser/pages/webgpu-helper.html?backend=${backend}`;
			const { page, errors } = await session.open( url, { width: 100, height: 100 } );
			await page.waitForFunction( 'window.__result !== undefined', { timeout: 120_000 } );
			const result = await page.evaluate( () => ( window as unknown as { __result: HelperPixels } ).__result );
			await page.close();
			expect( result.error ).toBeUndefined();
			expect( errors ).toEqual( [] );
			expect( result.backend ).toBe( backend );
			expect( result.nodeMaterial, result.material ).toBe( true );
			expect( result.pixels.length ).toBe( 12 );
			let worst = 0;
			for ( const { probe, normal, rgb } of result.pixels ) {

				const expected = expectedRGB( result.sh, probe, normal );
				for ( let c = 0; c < 3; c ++ ) worst = Math.max( worst, Math.abs( rgb[ c ] - expected[ c ] ) );
				// Lit, not clipped: the comparison means something in every channel.
				for ( const value of expected ) expect( value ).toBeGreaterThan( 20 );
				for ( const value of expected ) expect( value ).toBeLessThan( 250 );

			}

			console.log( `${backend}: largest difference from three's getIrradianceAt ${worst.toFixed( 2 )} / 255 over ${result.pixels.length} pixels` );
			expect( worst ).toBeLessThanOrEqual( 2 );

		}, 150_000 );

	}

} );
