import { describe, expect, it } from 'vitest';
import { placeGrid } from '../../src/index.js';
import { GridInterpolator } from '../../src/math.js';
import { evaluateLayout, gridValidSamples, predictSH, interpolatorOf, subsetPositions, subsetSH, verdictOf, type LayoutResult } from '../../scripts/experiment/evaluate.js';
import { parseArguments } from '../../scripts/experiment/cli.js';
import { logTicks, plotSVG } from '../../scripts/experiment/plot.js';
import { layoutTable, markdownReport, validateResult, type ExperimentResult } from '../../scripts/experiment/report.js';
import { checkTargets, equalStorage } from '../../scripts/experiment/targets.js';
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
		captureMs: probes, probesNotInOpenSpace: 0, fitted: false, gradients: false, shFloats: 27 * probes, bakeCaptures: probes,
		...( counts ? { counts } : {} ),
		...( kind === 'auto' ? { method: 'reduceProbes' as const } : {} ),
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

	it( 'blends gradient probes with the runtime formula (exact for a linear field, outside the hull too), and stores 108 floats each', () => {

		// L00 = 2 + 0.3 x − 0.2 y + 0.1 z: probes carrying the field's value and its gradient reproduce it anywhere.
		const positions = Float64Array.from( [ - 1, 0.5, - 1, 1, 0.5, - 1, 0, 2.5, 0, 0, 0.5, 1 ] );
		const sh = linearField( positions );
		const gradients = new Float32Array( 81 * 4 );
		for ( let p = 0; p < 4; p ++ ) [ 0.3, - 0.2, 0.1 ].forEach( ( g, a ) => gradients.fill( g, 81 * p + 27 * a, 81 * p + 27 * a + 3 ) );
		const samples = samplesIn( 200, 3 ), truth = linearField( samples );
		const layout = { name: 'g', kind: 'auto' as const, interpolation: 'tetrahedral' as const, positions, sh, captureMs: 0 };
		const withGradients = evaluateLayout( { ...layout, gradients }, samples, truth );
		expect( withGradients.meanError ).toBeLessThan( 1e-5 );
		expect( withGradients.gradients ).toBe( true );
		expect( withGradients.shFloats ).toBe( 4 * 108 );
		// The same probes without gradients: exact inside their hull only (most samples are outside it).
		const plain = evaluateLayout( layout, samples, truth );
		expect( plain.meanError ).toBeGreaterThan( 0.01 );
		expect( plain.shFloats ).toBe( 4 * 27 );
		expect( plain.fitted ).toBe( false );

	} );

	it( 'measures the walkable samples alone, with their own normaliser', () => {

		const samples = samplesIn( 300, 7 ), truth = linearField( samples );
		const grid = { min: BOX.min, max: BOX.max, counts: [ 3, 3, 3 ] };
		const positions = placeGrid( grid.min, grid.max, grid.counts );
		const low: number[] = [];
		for ( let i = 0; i < 300; i ++ ) if ( samples[ 3 * i + 1 ] < 1 ) low.push( i );
		// 10 % too bright everywhere: 10 % over any subset, whatever its own mean irradiance.
		const bright = linearField( positions ).map( ( v ) => 1.1 * v );
		const row10 = evaluateLayout( { name: 'b', kind: 'grid', interpolation: 'trilinear', positions, sh: bright, captureMs: 0, grid }, samples, truth, { walkable: low } );
		expect( row10.meanErrorWalkable ).toBeCloseTo( 0.1, 4 );
		// Wrong only at the walkable samples' height: the whole volume sees a fraction of it, the walkable column all of it.
		const shifted = linearField( positions );
		for ( let p = 0; p < 27; p ++ ) if ( positions[ 3 * p + 1 ] === 0 ) for ( let k = 0; k < 3; k ++ ) shifted[ 27 * p + k ] += 0.5;
		const rowLow = evaluateLayout( { name: 's', kind: 'grid', interpolation: 'trilinear', positions, sh: shifted, captureMs: 0, grid }, samples, truth, { walkable: low } );
		expect( rowLow.meanErrorWalkable! ).toBeGreaterThan( 1.5 * rowLow.meanError );
		expect( evaluateLayout( { name: 'n', kind: 'grid', interpolation: 'trilinear', positions, sh: bright, captureMs: 0, grid }, samples, truth ).meanErrorWalkable ).toBeUndefined();

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
		const rowResult = evaluateLayout( { name: 'g', kind: 'grid', interpolation: 'trilinear', positions, sh, captureMs: 1, grid: { min: BOX.min, max: BOX.max, counts: [ 3, 3, 3 ] } }, samples, truth, { gridValid: valid } );
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
		expect( w.text ).toMatch( /^Holds: 12 automatically placed probes \(reduceProbes, 18\.8 % of the grid's 64\)/ );
		expect( () => verdictOf( ROWS.filter( ( r ) => r.kind !== 'grid' ), PAPER ) ).toThrow( /no trilinear grid 4x4x4/ );

	} );

} );

describe( 'experiment: output', () => {

	const targets = checkTargets( ROWS, PAPER, { autoProbes: 12, autoError: 'grid', gridCountRatio: 0.8 } );
	const result: ExperimentResult = {
		scene: 'basic', samples: 500, layouts: ROWS, verdict: verdictOf( ROWS, PAPER ), paper: PAPER,
		targets, seeds: [ { seed: 1, walkableSamples: 400, targets, meanError: {}, meanErrorWalkable: {} } ],
		equalStorage: equalStorage( ROWS, [ [ 12, 48 ] ] ),
		groundTruth: {
			seed: 1, region: BOX, minDistance: 0.1, maxSky: 1, drawn: 510, rejectedNear: 10, rejectedInside: 0, rejectedOutside: 0,
			captureMs: 1000, normals: 26, gridValidSamples: 500, walkableSamples: 400,
		},
		fit: { seed: 101, points: 0, drawn: 0, captureMs: 0, samples: 700 },
		walkable: { height: 2, floorTriangles: 2 },
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
		expect( table ).toContain( '| grid 4x4x4 | trilinear | 64 | 61 boxes | 1728 | 64 | 64 | 8.0 % | 16.0 % | 0 |' );
		const md = markdownReport( result, 'basic.png' );
		expect( md ).toContain( '**Verdict, captured probes (the paper\'s method): Does not hold' );
		expect( md ).toContain( '![Basic' );
		const svg = plotSVG( result, { title: 'Basic' } );
		expect( svg.startsWith( '<svg' ) && svg.endsWith( '</svg>' ) ).toBe( true );
		expect( svg.match( /<polyline/g ) ).toHaveLength( 2 * 3 ); // 3 curves × 2 panels
		expect( svg ).toContain( "20 % of paper's grid (12)" );
		expect( logTicks( 0.05, 0.6 ) ).toEqual( [ 0.05, 0.1, 0.2, 0.5 ] );
		expect( logTicks( 5, 250 ) ).toEqual( [ 5, 10, 20, 50, 100, 200 ] );

	} );

	it( 'parses the command line', () => {

		expect( parseArguments( [ '--scene', 'sponza' ] ) ).toEqual( {
			scene: 'sponza', out: 'experiment/results', seed: 1, checkSeeds: [ 3, 4 ], denseSeed: 2, fitPoints: null, fitPointsPerProbe: null, fitSeed: 101, samples: 500, resolution: 32,
			captures: null, offline: false, captureOnly: false,
		} );
		expect( parseArguments( [ '--scene=basic', '--out', 'x', '--seed', '7' ] ) ).toMatchObject( { scene: 'basic', out: 'x', seed: 7 } );
		expect( parseArguments( [ '--scene', 'basic', '--save-captures' ] ) ).toMatchObject( { captures: 'experiment/results/basic.captures.json' } );
		expect( parseArguments( [ '--offline', '--out', 'o', '--scene', 'basic' ] ) ).toMatchObject( { offline: true, captures: 'o/basic.captures.json' } );
		expect( parseArguments( [ '--scene', 'basic', '--captures', 'c.json', '--capture-only' ] ) ).toMatchObject( { captureOnly: true, captures: 'c.json' } );
		expect( parseArguments( [ '--scene', 'basic', '--fit-points', '800', '--fit-seed', '9', '--check-seeds', 'none' ] ) ).toMatchObject( { fitPoints: 800, fitSeed: 9, checkSeeds: [] } );
		expect( parseArguments( [ '--scene', 'basic', '--fit-points-per-probe', '2.5' ] ) ).toMatchObject( { fitPointsPerProbe: 2.5 } );
		expect( () => parseArguments( [ '--scene', 'basic', '--fit-points-per-probe', '-1' ] ) ).toThrow( /--fit-points-per-probe/ );
		// The reported seed is not checked twice.
		expect( parseArguments( [ '--scene', 'basic', '--seed', '3', '--check-seeds', '3,5,5' ] ) ).toMatchObject( { seed: 3, checkSeeds: [ 5 ] } );
		expect( () => parseArguments( [ '--scene', 'basic', '--fit-seed', '1' ] ) ).toThrow( /--fit-seed must differ/ );
		expect( () => parseArguments( [ '--scene', 'basic', '--check-seeds', '4,2' ] ) ).toThrow( /--dense-seed must differ/ );
		expect( () => parseArguments( [ '--scene', 'basic', '--check-seeds', '101' ] ) ).toThrow( /--fit-seed must differ/ );
		expect( () => parseArguments( [ '--scene', 'basic', '--fit-seed', '2' ] ) ).toThrow( /--dense-seed and --fit-seed must differ/ );
		expect( () => parseArguments( [ '--scene', 'basic', '--check-seeds', 'x' ] ) ).toThrow( /--check-seeds must be integers/ );
		expect( () => parseArguments( [ '--scene', 'basic', '--save-captures', '--captures', 'c' ] ) ).toThrow( /name two files/ );
		expect( () => parseArguments( [ '--scene', 'basic', '--offline', '--capture-only' ] ) ).toThrow( /exclude each other/ );
		expect( parseArguments( [ '--help' ] ) ).toBe( 'help' );
		expect( () => parseArguments( [] ) ).toThrow( /--scene is required/ );
		expect( () => parseArguments( [ '--scene', 'kyoto' ] ) ).toThrow( /one of basic, sponza, sibenik/ );
		expect( () => parseArguments( [ '--scene', 'basic', '--seed', '2' ] ) ).toThrow( /must differ/ );
		expect( () => parseArguments( [ '--scene', 'basic', '--frobnicate' ] ) ).toThrow( /unknown argument/ );

	} );

} );
