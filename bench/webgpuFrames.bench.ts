/**
 * Frame cost of 500 moving probe-lit spheres on WebGPURenderer (issue 15), headless Chromium
 * 1280×720 with WebGPU on SwiftShader, on the WebGPU backend and the WebGL2 fallback: no probe,
 * one global LightProbe, three's LightProbeGrid (per pixel), ours (`volume.add()` + `update()`
 * through `three-capture-lighting/webgpu`). Page: bench/pages/webgpu.ts.
 *
 *   npm run bench -- webgpuFrames      (BENCH_QUICK=1: a smoke run; BENCH_WEBGPU_BACKENDS=webgpu: one backend)
 */

import { summarize } from './stats.js';
import type { BenchRow } from './types.js';
import type { BrowserSession } from '../test/helpers/browser.js';
import { openWebGPUBench, startWebGPUBench } from './webgpuSession.js';

const QUICK = process.env.BENCH_QUICK === '1';
const BACKENDS = ( process.env.BENCH_WEBGPU_BACKENDS ?? 'webgpu,webgl2' ).split( ',' ).map( ( b ) => b.trim() ) as ( 'webgpu' | 'webgl2' )[];
const PLAN = { cubeSize: 32, rounds: QUICK ? 1 : 5, warmUp: 3, steps: QUICK ? 4 : 9 };

export const title = 'WebGPURenderer frame, 500 probe-lit spheres, headless Chromium 1280×720 (ms per frame, lower is better)';

export const notes: string[] = [
	`Four scenes, one per variant: the Basic room with unlit walls, the ceiling panel, a PointLight and 500 spheres (radius 0.08 m, 16 × 12 segments), each with its own MeshStandardMaterial, moving on the same paths through the probe hull. none: no probe; global: one THREE.LightProbe holding ours' SH sampled at the room centre; grid: three's LightProbeGrid (WebGPU, per pixel) 4 × 4 × 4 baked at ${PLAN.cubeSize}², in the scene; ours: LightProbeVolume over the same 64 positions captured at ${PLAN.cubeSize}², the spheres added with volume.add. Timed per frame: [volume.update(), ours only] + renderer.render + a GPU sync (on WebGPU an awaited 1-texel readRenderTargetPixelsAsync, whose buffer map waits for every earlier submission; on WebGL2 a 1-pixel readPixels of the canvas); moving the spheres is not. Each step renders every variant once in an order rotated per step. ${PLAN.rounds} rounds of ${PLAN.warmUp} warm-up steps (pipeline compiles) + ${PLAN.steps} timed steps; figure = median of the round medians (min / max of the round medians); "paired" ratio = median over rounds of the median per-step ratio ours ÷ peer of the same step.`,
];

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const session = await startWebGPUBench();
	const rows: BenchRow[] = [];
	try {

		for ( const backend of BACKENDS ) {

			try {

				await frames( session, backend, rows, log );

			} catch ( error ) {

				const message = String( ( error as Error ).message ?? error ).slice( 0, 300 );
				log( `${backend} failed: ${message}` );
				rows.push( { case: `${backend}, 500 spheres`, subject: 'all variants', unit: 'ms', median: null, min: null, max: null, runs: 0, status: `failed: ${message}` } );

			}

		}

	} finally {

		await session.close().catch( () => undefined );

	}

	return rows;

}

/** Measures the four variants on one backend, pushing a row per variant. */
async function frames( session: BrowserSession, backend: 'webgpu' | 'webgl2', rows: BenchRow[], log: ( message: string ) => void ): Promise<void> {

	{

		{

			const bench = await openWebGPUBench( session, backend );
			const info = await bench.call( 'info' );
			log( `${backend}: ${JSON.stringify( info )}` );
			const names = await bench.call( 'setupFrames', PLAN.cubeSize );
			const rounds: number[][] = names.map( () => [] );
			const ratios: Record<string, number[]> = { none: [], global: [], grid: [] };
			for ( let round = 0; round < PLAN.rounds; round ++ ) {

				for ( let i = 0; i < PLAN.warmUp; i ++ ) await bench.call( 'frameStep' );
				const steps: number[][] = [];
				for ( let i = 0; i < PLAN.steps; i ++ ) steps.push( await bench.call( 'frameStep' ) );
				names.forEach( ( _, v ) => rounds[ v ].push( summarize( steps.map( ( s ) => s[ v ] ) ).median ) );
				const ours = names.indexOf( 'ours' );
				for ( const peer of Object.keys( ratios ) ) {

					const p = names.indexOf( peer );
					ratios[ peer ].push( summarize( steps.map( ( s ) => s[ ours ] / s[ p ] ) ).median );

				}

				log( `${backend} round ${round + 1}: ${names.map( ( n, v ) => `${n} ${rounds[ v ][ round ].toFixed( 1 )}` ).join( ', ' )} ms` );

			}

			const label = backend === 'webgpu' ? 'WebGPU backend' : 'WebGL2 fallback (forceWebGL)';
			names.forEach( ( name, v ) => {

				const s = summarize( rounds[ v ] );
				const row: BenchRow = { case: `${label}, 500 spheres`, subject: name === 'ours' ? 'ours (volume.update + render)' : name === 'grid' ? 'three LightProbeGrid' : name === 'global' ? 'one global LightProbe' : 'no probe', unit: 'ms', median: s.median, min: s.min, max: s.max, runs: s.runs };
				if ( name === 'ours' ) {

					const global = summarize( ratios.global ).median;
					row.peer = 'one global LightProbe (paired)';
					row.ratio = global;
					row.ratios = [ { peer: 'three LightProbeGrid (paired)', ratio: summarize( ratios.grid ).median }, { peer: 'no probe (paired)', ratio: summarize( ratios.none ).median } ];
					row.targets = [ { text: '≤ 1.05× the global probe', met: global <= 1.05 } ];

				}

				rows.push( row );

			} );

			const unique = [ ...new Set( bench.errors ) ];
			if ( unique.length ) notes.push( `${backend}: the page reported ${bench.errors.length} error(s): ${unique.slice( 0, 4 ).join( ' | ' ).slice( 0, 800 )}` );
			await bench.page.close();

		}

	}

}
