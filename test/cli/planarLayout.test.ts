import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { checkVolumeInput, readLayout, tetrahedralizeLayout } from '../../cli/layout.js';
import { encodeVolume, readVolume } from '../../cli/codec.js';
import { inspect } from '../../cli/inspect.js';
import { layoutShape } from '../../cli/layoutShape.js';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { LightProbeVolumeLoader } from '../../src/runtime/LightProbeVolumeLoader.js';
import { PlanarMesh } from '../../src/interpolation/PlanarMesh.js';
import { ProbeLineInterpolator } from '../../src/runtime/ProbeLineInterpolator.js';
import { checkChromium, resolveChromiumPath } from '../../cli/chromium.js';
import { decodeBakedVolume } from '../../src/io/index.js';
import { runCli, writeLayout, writeRoom } from './fixtures.js';

// The end-to-end bake runs in headless Chromium (SwiftShader) when it is installed.
const CHROMIUM = resolveChromiumPath();
const missing = checkChromium( CHROMIUM.path, CHROMIUM.source );
const skipReason = missing ? `${missing} The planar bake test is skipped.` : '';
if ( skipReason ) console.warn( skipReason );

/*
 * Layouts that span no volume — probes in one plane (a floor of probes) or on one line (a
 * corridor) — are baked without tetrahedra; LightProbeVolume interpolates them in their plane or
 * along their line. The SH here are a linear function of position, which both interpolators
 * reproduce exactly between the probes: that is the truth the loaded files are checked against.
 */

let dir = '';

beforeAll( () => {

	dir = mkdtempSync( join( tmpdir(), 'capture-lighting-planar-' ) );

} );

afterAll( () => rmSync( dir, { recursive: true, force: true } ) );

/**
 * SH coefficient i at (x, y, z): a different linear function per coefficient, L00 about 1 and the
 * higher bands a tenth of it (a plausible, non-negative light field, so inspect has no warning).
 */
function linearSH( x: number, y: number, z: number, i: number ): number {

	const value = 0.5 + 0.01 * i + ( 0.03 + 0.002 * i ) * x - ( 0.02 - 0.001 * i ) * y + ( 0.04 - 0.003 * i ) * z;
	return i < 3 ? value : 0.1 * value;

}

function shAt( positions: ArrayLike<number> ): Float32Array {

	const count = positions.length / 3;
	const sh = new Float32Array( 27 * count );
	for ( let p = 0; p < count; p ++ ) {

		const x = positions[ 3 * p ], y = positions[ 3 * p + 1 ], z = positions[ 3 * p + 2 ];
		for ( let i = 0; i < 27; i ++ ) sh[ 27 * p + i ] = linearSH( x, y, z, i );

	}

	return sh;

}

// A tilted plane through (0, 1, 0) spanned by u = (1, 0.5, 0) and v = (0, 0.25, 1): 12 irregular probes.
const U = [ 1, 0.5, 0 ], V = [ 0, 0.25, 1 ];
const inPlane = ( a: number, b: number ) => [ a * U[ 0 ] + b * V[ 0 ], 1 + a * U[ 1 ] + b * V[ 1 ], a * U[ 2 ] + b * V[ 2 ] ];
const PLANE_AB = [ 0, 0, 4, 0, 0, 4, 4, 4, 2, 0.3, 0.2, 2.5, 3.7, 1.9, 1.4, 3.1, 2.6, 2.2, 0.8, 1.2, 3.3, 3.6, 1.1, 0.7 ];
const PLANE = PLANE_AB.flatMap( ( _, i ) => i % 2 === 0 ? inPlane( PLANE_AB[ i ], PLANE_AB[ i + 1 ] ) : [] );
// A corridor: 6 probes along (1, 0, 2) from (−1, 1.5, 0), unevenly spaced.
const LINE = [ 0, 0.7, 1.1, 2.5, 3, 4.2 ].flatMap( ( t ) => [ - 1 + t, 1.5, 2 * t ] );

describe( 'planar and collinear layouts', () => {

	it( 'layoutShape: volume, plane, line, point (with tetrahedralize\'s tolerances)', () => {

		expect( layoutShape( [ ...PLANE, 0, 3, 0 ] ).shape ).toBe( 'volume' );
		expect( layoutShape( PLANE ).shape ).toBe( 'plane' );
		expect( layoutShape( LINE ).shape ).toBe( 'line' );
		expect( layoutShape( [ 1, 2, 3, 1, 2, 3 ] ) ).toMatchObject( { shape: 'point', distinct: 1 } );
		// 1e-12 of the extent off the plane is within tetrahedralize's 1e-9: still planar.
		const almost = PLANE.slice();
		almost[ 13 ] += 1e-12;
		expect( layoutShape( almost ).shape ).toBe( 'plane' );

	} );

	it( 'tetrahedralizeLayout returns null for a plane and a line, a tetrahedralization for a volume; checkVolumeInput accepts null', () => {

		const plane = readLayout( writeLayout( dir, 'plane.json', { positions: PLANE } ) );
		expect( tetrahedralizeLayout( 'plane.json', plane ) ).toBeNull();
		expect( () => checkVolumeInput( 'plane.json', plane, null ) ).not.toThrow();
		const line = readLayout( writeLayout( dir, 'line.json', { positions: LINE } ) );
		expect( tetrahedralizeLayout( 'line.json', line ) ).toBeNull();
		const volume = readLayout( writeLayout( dir, 'volume.json', { positions: [ ...PLANE, 0, 3, 0 ] } ) );
		expect( tetrahedralizeLayout( 'volume.json', volume )?.tetrahedra.length ).toBeGreaterThan( 0 );

	} );

	it( 'still refused: duplicates in a planar layout (named), and a bad zone of a planar layout (the codec\'s rule)', () => {

		const duplicate = [ ...PLANE, ...PLANE.slice( 9, 12 ) ];
		const names = Array.from( { length: 13 }, ( _, i ) => i === 3 ? 'corner' : '' );
		const file = writeLayout( dir, 'plane-dup.json', { positions: duplicate, names } );
		expect( () => tetrahedralizeLayout( file, readLayout( file ) ) )
			.toThrow( /plane-dup\.json: probe 12 and probe 3 \("corner"\) are at the same position \(4, 4, 4\); remove one\.$/ );
		const zoned = writeLayout( dir, 'plane-zone.json', { positions: PLANE, zones: [ { name: 'hall', probes: [ 0, 40 ] } ] } );
		expect( () => checkVolumeInput( zoned, readLayout( zoned ), null ) ).toThrow( /plane-zone\.json: .*zones\[0\].*40/ );

	} );

	it( 'a planar file without tetrahedra decodes (binary f32/f16, JSON), passes inspect, and loads as new LightProbeVolume( { positions, sh } )', () => {

		const sh = shAt( PLANE );
		const data = { positions: Float64Array.from( PLANE ), sh, tetrahedra: null, neighbors: null };
		const direct = new LightProbeVolume( { positions: PLANE, sh } );
		expect( direct.interpolator ).toBeInstanceOf( PlanarMesh );
		const points = [ [ 1, 1 ], [ 2.2, 3.1 ], [ 3.5, 0.4 ], [ 0.2, 3.8 ], [ 2, 2 ] ].map( ( [ a, b ] ) => inPlane( a, b ) );

		for ( const [ format, precision ] of [ [ 'bin', 'float32' ], [ 'bin', 'float16' ], [ 'json', 'float32' ] ] as const ) {

			const file = join( dir, `plane-${format}-${precision}.${format}` );
			writeFileSync( file, encodeVolume( data, format, precision ) );
			const bytes = readFileSync( file );
			expect( readVolume( bytes ).data.tetrahedra.length ).toBe( 0 );

			const lines: string[] = [], warnings: string[] = [];
			inspect( file, { strict: true, log: ( text ) => lines.push( text ), warn: ( text ) => warnings.push( text ) } );
			expect( lines.join( '\n' ) ).toMatch( /^ {2}tetrahedra +0 \(none stored: the probes lie in one plane; LightProbeVolume triangulates them in their plane when it loads the file\)$/m );
			expect( warnings ).toEqual( [] );

			const loaded = new LightProbeVolumeLoader().parse( format === 'json' ? JSON.parse( bytes.toString( 'utf8' ) ) : bytes );
			expect( loaded.interpolator ).toBeInstanceOf( PlanarMesh );
			for ( const point of points ) {

				const got = loaded.sample( point ), want = direct.sample( point );
				for ( let i = 0; i < 27; i ++ ) {

					// float16 rounds values below 2 by at most 2^−11 (half its step there); a blend with
					// weights summing to 1 adds no more. float32 and JSON store the same float32 values.
					const rounding = precision === 'float16' ? 2 ** - 11 : 0;
					expect( Math.abs( got[ i ] - want[ i ] ) ).toBeLessThanOrEqual( rounding + 1e-7 );
					// The truth: the linear field at the point (interpolation in the plane is exact for it).
					expect( Math.abs( got[ i ] - linearSH( point[ 0 ], point[ 1 ], point[ 2 ], i ) ) ).toBeLessThan( rounding + 1e-5 );

				}

			}

		}

	} );

	it( 'a collinear file loads with the line interpolator and samples the linear field along the line', () => {

		const sh = shAt( LINE );
		const file = join( dir, 'line.bin' );
		writeFileSync( file, encodeVolume( { positions: LINE, sh, tetrahedra: null, neighbors: null }, 'bin', 'float32' ) );
		const lines: string[] = [];
		inspect( file, { strict: true, log: ( text ) => lines.push( text ), warn: () => {} } );
		expect( lines.join( '\n' ) ).toMatch( /tetrahedra +0 \(none stored: the probes lie on one line; LightProbeVolume interpolates along their line/ );

		const loaded = new LightProbeVolumeLoader().parse( readFileSync( file ) );
		expect( loaded.interpolator ).toBeInstanceOf( ProbeLineInterpolator );
		const direct = new LightProbeVolume( { positions: LINE, sh } );
		for ( const t of [ 0.3, 1.8, 2.75, 4 ] ) {

			const point = [ - 1 + t, 1.5, 2 * t ];
			const got = loaded.sample( point );
			expect( Array.from( got ) ).toEqual( Array.from( direct.sample( point ) ) );
			for ( let i = 0; i < 27; i ++ ) expect( got[ i ] ).toBeCloseTo( linearSH( point[ 0 ], point[ 1 ], point[ 2 ], i ), 5 );

		}

	} );

	it( 'the CLI: inspect of a planar file exits 0 and says how the runtime interpolates it', () => {

		const file = join( dir, 'plane-cli.bin' );
		writeFileSync( file, encodeVolume( { positions: PLANE, sh: shAt( PLANE ) }, 'bin', 'float32' ) );
		const run = runCli( [ 'inspect', file ] );
		expect( run.code, run.stderr ).toBe( 0 );
		expect( run.stderr ).toBe( '' );
		expect( run.stdout ).toMatch( /^ {2}probes +12$/m );
		expect( run.stdout ).toMatch( /^ {2}tetrahedra +0 \(none stored: the probes lie in one plane;/m );

	} );

} );

describe.skipIf( skipReason !== '' )( 'capture-lighting bake of a planar layout (headless Chromium)', () => {

	it( 'a floor of 9 probes in the room: exit 0, no warning, no tetrahedra stored; inspect agrees; the runtime loads it in its plane', () => {

		const room = writeRoom( dir );
		// A 3 × 3 grid 1.5 m above the floor of the room (x, z ∈ [−2, 2]; red wall at x = −2).
		const positions = [ - 1, 0, 1 ].flatMap( ( z ) => [ - 1, 0, 1 ].flatMap( ( x ) => [ x, 1.5, z ] ) );
		const layout = writeLayout( dir, 'floor.json', { positions } );
		const out = join( dir, 'floor.bin' );
		// --ambient lights the walls (the emissive ceiling alone leaves them black and rings: E(n) down to
		// −1.7 % of the mean, which --strict would refuse); --strict makes any warning fail the test.
		const args = [ '--resolution', '8', '--ambient', '1', '--strict' ];
		const run = runCli( [ 'bake', room, '--probes', layout, '--out', out, ...args ], { CHROME_PATH: CHROMIUM.path } );
		expect( run.code, run.stderr ).toBe( 0 );
		expect( run.stderr ).not.toContain( 'warning:' );
		expect( run.stdout ).toMatch( /^ {2}tetrahedra +none: the probes lie in one plane/m );

		const inspected = runCli( [ 'inspect', '--strict', out ] );
		expect( inspected.code, inspected.stderr ).toBe( 0 );
		expect( inspected.stdout ).toMatch( /^ {2}tetrahedra +0 \(none stored: the probes lie in one plane;/m );
		expect( inspected.stdout ).toMatch( /^ {2}black probes +0 of 9 /m );

		const bytes = readFileSync( out );
		const data = decodeBakedVolume( bytes );
		expect( data.tetrahedra.length ).toBe( 0 );
		const loaded = new LightProbeVolumeLoader().parse( bytes );
		expect( loaded.interpolator ).toBeInstanceOf( PlanarMesh );
		// At a probe the field is that probe's SH; halfway along a grid edge, the mean of its two ends.
		const at = ( p: number ) => Array.from( data.sh.subarray( 27 * p, 27 * p + 27 ) );
		const sampled = Array.from( loaded.sample( positions.slice( 12, 15 ) ) );
		sampled.forEach( ( v, i ) => expect( v ).toBeCloseTo( at( 4 )[ i ], 6 ) );
		const mid = Array.from( loaded.sample( [ - 0.5, 1.5, 0 ] ) );
		mid.forEach( ( v, i ) => expect( v ).toBeCloseTo( 0.5 * ( at( 3 )[ i ] + at( 4 )[ i ] ), 6 ) );
		// The light is right too: the probe nearest the red wall (x = −1) has more red per green than the one opposite.
		const ratio = ( p: number ) => at( p )[ 0 ] / at( p )[ 1 ];
		expect( ratio( 3 ) ).toBeGreaterThan( 1.05 * ratio( 5 ) );

	} );

} );
