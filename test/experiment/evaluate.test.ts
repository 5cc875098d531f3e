import { describe, expect, it } from 'vitest';
import { placeGrid } from '../../src/index.js';
import { GridInterpolator } from '../../src/math.js';
import { evaluateLayout, gridValidSamples, predictSH, interpolatorOf, subsetPositions, subsetSH, verdictOf, type LayoutResult } from '../../scripts/experiment/evaluate.js';
import { parseArguments } from '../../scripts/experiment/cli.js';
import { layoutTable, logTicks, markdownReport, plotSVG, validateResult, type ExperimentResult } from '../../scripts/experiment/report.js';
import { mulberry32 } from '../../scripts/experiment/samples.js';

/** SH whose L00 is linear in position (grey), plus a fixed L1 term: a field every layout reproduces exactly inside its hull. */
function linearField( positions: ArrayLike<number> ): Float32Array {

	const count = positions.length / 3, sh = new Float32Array( 27 * count );
	for ( let p = 0; p < count; p ++ ) {

		const l00 = 2 + 0.3 * positions[ 3 * p ] - 0.2 * positions[ 3 * p + 1 ] + 0.1 * positions[ 3 * p + 2 ];
		sh.fill( l00, 27 * p, 27 * p + 3 );
		sh.fill( 0.4, 27 * p + 3, 27 * p + 6 ); // L1,-1 (y)

	}

	return sh;

}

const BOX = { min: [ - 2, 0, - 2 ], max: [ 2, 3, 2 ] };

function samplesIn( count: number, seed: number ): Float64Array {

	const random = mulberry32( seed ), out = new Float64Array( 3 * count );
	for ( let i = 0; i < 3 * count; i ++ ) out[ i ] = BOX.min[ i % 3 ] + random() * ( BOX.max[ i % 3 ] - BOX.min[ i % 3 ] );
	return out;

}

function row( name: string, kind: LayoutResult[ 'kind' ], interpolation: LayoutResult[ 'interpolation' ], probes: number, meanError: number, counts?: number[] ): LayoutResult {

	return {
		name, kind, interpolation, probes, cells: Math.max( 1, probes - 3 ), meanError, p95Error: 2 * meanError, maxError: 3 * meanError,
		captureMs: probes, probesNotInOpenSpace: 0, ...( counts ? { counts } : {} )
	};

}

const ROWS: LayoutResult[] = [
	row( 'grid 2x2x2', 'grid', 'trilinear', 8, 0.6, [ 2, 2, 2 ] ),
	row( 'grid 4x4x4', 'grid', 'trilinear', 64, 0.08, [ 4, 4, 4 ] ),
	row( 'grid 2x2x2, tetrahedralized', 'grid', 'tetrahedral', 8, 0.62, [ 2, 2, 2 ] ),
	row( 'grid 4x4x4, tetrahedralized', 'grid', 'tetrahedral', 64, 0.1, [ 4, 4, 4 ] ),
	row( 'hand-made', 'hand', 'tetrahedral', 13, 0.29 ),
	row( 'automatic 8', 'auto', 'tetrahedral', 8, 0.6 ),
	row( 'automatic 12', 'auto', 'tetrahedral', 12, 0.37 ),
	row( 'automatic 40', 'auto', 'tetrahedral', 40, 0.07 ),
];
const PAPER = { gridCounts: [ 4, 4, 4 ], gridProbes: 64, handProbes: 13, boxes: 8, tetrahedra: 14 };

describe( 'experiment: error aggregation', () => {

	it( 'a field linear in position has no error, trilinear or tetrahedral; a 10 % too bright layout has 10 %', () => {

		const samples = samplesIn( 300, 5 ), truth = linearField( samples );
		const grid = { min: BOX.min, max: BOX.max, counts: [ 3, 3, 3 ] };
		const positions = placeGrid( grid.min, grid.max, grid.counts );
		const trilinear = evaluateLayout( { name: 'g', kind: 'grid', interpolation: 'trilinear', positions, sh: linearField( positions ), captureMs: 5, grid }, samples, truth );
		expect( trilinear.meanError ).toBeLessThan( 1e-5 );
		expect( trilinear.cells ).toBe( 8 );
		expect( trilinear.probes ).toBe( 27 );
		expect( trilinear.counts ).toEqual( [ 3, 3, 3 ] );
		const tetrahedral = evaluateLayout( { name: 't', kind: 'grid', interpolation: 'tetrahedral', positions, sh: linearField( positions ), captureMs: 5 }, samples, truth );
		expect( tetrahedral.meanError ).toBeLessThan( 1e-5 );
		expect( tetrahedral.cells ).toBeGreaterThanOrEqual( 8 * 5 );

		const bright = linearField( positions ).map( ( v ) => 1.1 * v );
		// Per point the error is 0.1 · E(p) / Ē: its mean over points is 0.1.
		const off = evaluateLayout( { name: 'b', kind: 'grid', interpolation: 'trilinear', positions, sh: bright, captureMs: 5, grid }, samples, truth );
		expect( off.meanError ).toBeCloseTo( 0.1, 4 );
		expect( off.p95Error ).toBeGreaterThan( off.meanError );

	} );

	it( 'predicts by blending the probes of the cell around each sample, as the runtime does', () => {

		const positions = [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 ];
		const sh = new Float32Array( 4 * 27 );
		[ 1, 2, 3, 4 ].forEach( ( v, p ) => sh.fill( v, 27 * p, 27 * p + 27 ) );
		const predicted = predictSH( interpolatorOf( { interpolation: 'tetrahedral', positions } ), sh, [ 0.25, 0.25, 0.25 ] );
		expect( predicted[ 0 ] ).toBeCloseTo( 0.25 * ( 1 + 2 + 3 + 4 ), 6 );
		expect( () => interpolatorOf( { interpolation: 'trilinear', positions } ) ).toThrow( /needs its grid/ );
		expect( Array.from( subsetPositions( positions, [ 2, 0 ] ) ) ).toEqual( [ 0, 1, 0, 0, 0, 0 ] );
		expect( subsetSH( sh, [ 3 ] )[ 26 ] ).toBe( 4 );

	} );

	it( 'restricts to the samples whose grid cell has only usable probes, and measures the errors there too', () => {

		const samples = samplesIn( 400, 9 ), truth = linearField( samples );
		const grid = new GridInterpolator( BOX.min, BOX.max, [ 3, 3, 3 ] );
		const usable = new Array( 27 ).fill( true );
		expect( gridValidSamples( grid, usable, samples ).length ).toBe( 400 );
		usable[ 0 ] = false; // the corner (−2, 0, −2): only the first of the 8 cells uses it
		const valid = gridValidSamples( grid, usable, samples );
		for ( let i = 0; i < 400; i ++ ) {

			const inFirstCell = samples[ 3 * i ] < 0 && samples[ 3 * i + 1 ] < 1.5 && samples[ 3 * i + 2 ] < 0;
			expect( valid.includes( i ) ).toBe( ! inFirstCell );

		}

		const positions = grid.positions, sh = linearField( positions );
		sh.fill( 50, 0, 27 ); // the unusable probe captured garbage
		const rowResult = evaluateLayout( { name: 'g', kind: 'grid', interpolation: 'trilinear', positions, sh, captureMs: 1, grid: { min: BOX.min, max: BOX.max, counts: [ 3, 3, 3 ] } }, samples, truth, valid );
		expect( rowResult.meanError ).toBeGreaterThan( 0.1 );
		expect( rowResult.meanErrorGridValid ).toBeLessThan( 1e-5 );
		expect( rowResult.p95ErrorGridValid ).toBeLessThan( 1e-5 );

	} );

	it( 'judges the claim on the largest automatic layout within 20 % of the paper\'s grid', () => {

		const v = verdictOf( ROWS, PAPER );
		expect( v.budget ).toBe( 12 );
		expect( v.grid.probes ).toBe( 64 );
		expect( v.auto?.name ).toBe( 'automatic 12' );
		expect( v.holds ).toBe( false );
		expect( v.ratio ).toBeCloseTo( 0.37 / 0.08, 12 );
		expect( v.fewestAutoMatchingGrid ).toBe( 40 );
		expect( v.hand?.ratio ).toBeCloseTo( 0.29 / 0.08, 12 );
		expect( v.text ).toMatch( /^Does not hold: 12 .*\(4\.63× the grid's error\).*from 40 probes/ );

		const better = ROWS.map( ( r ) => r.name === 'automatic 12' ? { ...r, meanError: 0.05 } : r );
		const w = verdictOf( better, PAPER );
		expect( w.holds ).toBe( true );
		expect( w.text ).toMatch( /^Holds: 12 automatically placed probes \(18\.8 % of the grid's 64\)/ );
		expect( () => verdictOf( ROWS.filter( ( r ) => r.kind !== 'grid' ), PAPER ) ).toThrow( /no trilinear grid 4x4x4/ );

	} );

} );

describe( 'experiment: output', () => {

	const result: ExperimentResult = {
		scene: 'basic', samples: 500, layouts: ROWS, verdict: verdictOf( ROWS, PAPER ), paper: PAPER,
		groundTruth: {
			seed: 1, region: BOX, minDistance: 0.1, maxSky: 1, drawn: 510, rejectedNear: 10, rejectedInside: 0, rejectedOutside: 0,
			captureMs: 1000, normals: 26, gridValidSamples: 500
		},
		dense: {
			seed: 2, probes: 700, fromGrid: 690, fromVertices: 10, captureMs: 2000, reduceMs: 100, selectMs: 100,
			denseMeanError: { 12: 0.38 }, recaptureMaxDifference: 0
		},
		capture: { resolution: 32, near: 0.02, far: 20, type: 'HalfFloat', solidAngle: 'exact' },
		environment: { browser: 'Chrome', renderer: 'SwiftShader' }, runMs: 10000,
	};

	it( 'has the JSON shape the issue asks for', () => {

		const json = JSON.parse( JSON.stringify( result ) );
		expect( validateResult( json ) ).toEqual( [] );
		expect( Object.keys( json ) ).toEqual( expect.arrayContaining( [ 'scene', 'samples', 'layouts' ] ) );
		for ( const layout of json.layouts ) expect( Object.keys( layout ) ).toEqual( expect.arrayContaining( [ 'name', 'interpolation', 'probes', 'cells', 'meanError', 'p95Error', 'captureMs' ] ) );
		expect( validateResult( { ...json, layouts: [ { ...json.layouts[ 0 ], interpolation: 'box' } ] } ) ).toEqual( [ 'layouts[0].interpolation must be "trilinear" or "tetrahedral"' ] );
		expect( validateResult( { ...json, samples: 0, layouts: [] } ) ).toHaveLength( 2 );

	} );

	it( 'writes the table, the report and a plot with every curve', () => {

		const table = layoutTable( ROWS );
		expect( table.split( '\n' ) ).toHaveLength( 2 + ROWS.length );
		expect( table ).toContain( '| grid 4x4x4 | trilinear | 64 | 61 boxes | 64 | 8.0 % | 16.0 % | 0 |' );
		const md = markdownReport( result, 'basic.png' );
		expect( md ).toContain( '**Verdict: Does not hold' );
		expect( md ).toContain( '![Basic' );
		const svg = plotSVG( result, { title: 'Basic' } );
		expect( svg.startsWith( '<svg' ) && svg.endsWith( '</svg>' ) ).toBe( true );
		expect( svg.match( /<polyline/g ) ).toHaveLength( 2 * 3 ); // 3 curves × 2 panels
		expect( svg ).toContain( "20 % of paper's grid (12)" );
		expect( logTicks( 0.05, 0.6 ) ).toEqual( [ 0.05, 0.1, 0.2, 0.5 ] );
		expect( logTicks( 5, 250 ) ).toEqual( [ 5, 10, 20, 50, 100, 200 ] );

	} );

	it( 'parses the command line', () => {

		expect( parseArguments( [ '--scene', 'sponza' ] ) ).toEqual( { scene: 'sponza', out: 'experiment/results', seed: 1, denseSeed: 2, samples: 500, resolution: 32, saveCaptures: false } );
		expect( parseArguments( [ '--scene=basic', '--out', 'x', '--seed', '7' ] ) ).toMatchObject( { scene: 'basic', out: 'x', seed: 7 } );
		expect( parseArguments( [ '--scene', 'basic', '--save-captures' ] ) ).toMatchObject( { saveCaptures: true } );
		expect( parseArguments( [ '--help' ] ) ).toBe( 'help' );
		expect( () => parseArguments( [] ) ).toThrow( /--scene is required/ );
		expect( () => parseArguments( [ '--scene', 'kyoto' ] ) ).toThrow( /one of basic, sponza, sibenik/ );
		expect( () => parseArguments( [ '--scene', 'basic', '--seed', '2' ] ) ).toThrow( /must differ/ );
		expect( () => parseArguments( [ '--scene', 'basic', '--frobnicate' ] ) ).toThrow( /unknown argument/ );

	} );

} );
