import { describe, expect, it } from 'vitest';
import {
	cubeFaceDirection, cubeTexelSolidAngle, evaluateIrradiance, evaluateRadiance, evaluateSHBasis,
	getCubeProjectionTable, irradianceMatrices, projectCubeMapToSH, projectEquirectToSH,
} from '../../src/sh/index.js';

/** Six valid RGBA faces of the given size. */
function faces( size: number ): Float32Array[] {

	return Array.from( { length: 6 }, () => new Float32Array( size * size * 4 ).fill( 0.5 ) );

}

/** Expects `call` to throw an Error whose message names the function and every given fragment. */
function expectError( call: () => unknown, where: string, ...fragments: string[] ): void {

	let error: unknown;
	try {

		call();

	} catch ( e ) {

		error = e;

	}

	expect( error, 'expected a throw' ).toBeInstanceOf( Error );
	const message = ( error as Error ).message;
	expect( message.startsWith( `${where}:` ), message ).toBe( true );
	for ( const fragment of fragments ) expect( message ).toContain( fragment );

}

describe( 'bad input throws an Error naming the function and argument', () => {

	it( 'projectCubeMapToSH', () => {

		const good = faces( 4 );
		expect( () => projectCubeMapToSH( good, 4 ) ).not.toThrow();

		const nan = faces( 4 );
		nan[ 2 ][ 17 ] = NaN;
		expectError( () => projectCubeMapToSH( nan, 4 ), 'projectCubeMapToSH', 'faces[2][17]', 'NaN' );
		const infinite = faces( 4 );
		infinite[ 5 ][ 0 ] = Infinity;
		expectError( () => projectCubeMapToSH( infinite, 4 ), 'projectCubeMapToSH', 'faces[5][0]' );

		const short = faces( 4 );
		short[ 4 ] = new Float32Array( 63 );
		expectError( () => projectCubeMapToSH( short, 4 ), 'projectCubeMapToSH', 'faces[4]', '64', '63' );
		// Faces of size 4 passed as size 5: every face has the wrong length; the first is named.
		expectError( () => projectCubeMapToSH( good, 5 ), 'projectCubeMapToSH', 'faces[0]', '100' );
		// RGBA data declared as RGB.
		expectError( () => projectCubeMapToSH( good, 4, { channels: 3 } ), 'projectCubeMapToSH', 'faces[0]', '48' );

		expectError( () => projectCubeMapToSH( good.slice( 0, 5 ), 4 ), 'projectCubeMapToSH', 'faces', '6', '5' );
		expectError( () => projectCubeMapToSH( null as never, 4 ), 'projectCubeMapToSH', 'faces' );
		const withHole = [ ...good ] as unknown[];
		withHole[ 3 ] = 'not an array';
		expectError( () => projectCubeMapToSH( withHole as never, 4 ), 'projectCubeMapToSH', 'faces[3]' );

		expectError( () => projectCubeMapToSH( good, 0 ), 'projectCubeMapToSH', 'size' );
		expectError( () => projectCubeMapToSH( good, 2.5 ), 'projectCubeMapToSH', 'size' );
		expectError( () => projectCubeMapToSH( good, NaN ), 'projectCubeMapToSH', 'size' );

		expectError( () => projectCubeMapToSH( good, 4, { solidAngle: 'approx' as never } ), 'projectCubeMapToSH', 'solidAngle', 'approx' );
		expectError( () => projectCubeMapToSH( good, 4, { channels: 2 as never } ), 'projectCubeMapToSH', 'channels' );
		expectError( () => projectCubeMapToSH( good, 4, { target: new Float32Array( 26 ) } ), 'projectCubeMapToSH', 'target', '27' );
		expectError( () => projectCubeMapToSH( good, 4, { target: new Float32Array( 27 ), targetOffset: 1 } ), 'projectCubeMapToSH', 'target', '28' );
		expectError( () => getCubeProjectionTable( - 1 ), 'getCubeProjectionTable', 'size' );

	} );

	it( 'projectEquirectToSH', () => {

		const pixels = new Float32Array( 8 * 4 * 4 );
		expect( () => projectEquirectToSH( pixels, 8, 4 ) ).not.toThrow();
		expectError( () => projectEquirectToSH( pixels, 8, 5 ), 'projectEquirectToSH', 'pixels', '160', '128' );
		expectError( () => projectEquirectToSH( pixels, 4, 4 ), 'projectEquirectToSH', 'pixels', '64' );
		expectError( () => projectEquirectToSH( pixels, 8, 4, { channels: 3 } ), 'projectEquirectToSH', 'pixels', '96' );
		expectError( () => projectEquirectToSH( pixels, 0, 4 ), 'projectEquirectToSH', 'width' );
		expectError( () => projectEquirectToSH( pixels, 8, 1.5 ), 'projectEquirectToSH', 'height' );
		expectError( () => projectEquirectToSH( pixels, 8, 4, { rowOrder: 'up' as never } ), 'projectEquirectToSH', 'rowOrder' );
		const nan = pixels.slice();
		nan[ 33 ] = NaN;
		expectError( () => projectEquirectToSH( nan, 8, 4 ), 'projectEquirectToSH', 'pixels[33]' );
		expectError( () => projectEquirectToSH( 'pixels' as never, 8, 4 ), 'projectEquirectToSH', 'pixels' );

	} );

	it( 'evaluateIrradiance / evaluateRadiance', () => {

		const sh = new Float32Array( 27 ).fill( 0.1 );
		expect( () => evaluateIrradiance( sh, [ 0, 0, 1 ] ) ).not.toThrow();
		expectError( () => evaluateIrradiance( new Float32Array( 26 ), [ 0, 0, 1 ] ), 'evaluateIrradiance', 'sh', '26' );
		expectError( () => evaluateIrradiance( new Float32Array( 28 ), [ 0, 0, 1 ] ), 'evaluateIrradiance', 'sh', '28' );
		expectError( () => evaluateRadiance( new Float32Array( 9 ), [ 0, 0, 1 ] ), 'evaluateRadiance', 'sh', '9' );
		const nan = sh.slice();
		nan[ 5 ] = NaN;
		expectError( () => evaluateIrradiance( nan, [ 0, 0, 1 ] ), 'evaluateIrradiance', 'sh[5]', 'NaN' );
		expectError( () => evaluateIrradiance( sh, { x: 0, y: NaN, z: 1 } ), 'evaluateIrradiance', 'normal.y' );
		expectError( () => evaluateIrradiance( sh, { x: 0, z: 1 } as never ), 'evaluateIrradiance', 'normal.y', 'undefined' );
		expectError( () => evaluateIrradiance( sh, [ 0, 1 ] ), 'evaluateIrradiance', 'normal', 'length 2' );
		expectError( () => evaluateRadiance( sh, null as never ), 'evaluateRadiance', 'dir' );
		expectError( () => evaluateIrradiance( sh, [ 0, 0, 1 ], new Float32Array( 2 ) ), 'evaluateIrradiance', 'target' );
		expectError( () => evaluateIrradiance( sh, [ 0, 0, 1 ], undefined, 27 ), 'evaluateIrradiance', 'shOffset', '27' );
		expectError( () => evaluateIrradiance( sh, [ 0, 0, 1 ], undefined, - 1 ), 'evaluateIrradiance', 'shOffset' );

	} );

	it( 'irradianceMatrices', () => {

		const probes = new Float32Array( 27 * 2 );
		expect( () => irradianceMatrices( probes, undefined, 0, 27 ) ).not.toThrow();
		expectError( () => irradianceMatrices( probes, undefined, 0, 28 ), 'irradianceMatrices', 'shOffset' );
		expectError( () => irradianceMatrices( new Float32Array( 30 ) ), 'irradianceMatrices', 'sh', '30' );
		expectError( () => irradianceMatrices( probes, new Float32Array( 47 ) ), 'irradianceMatrices', 'out', '48' );
		expectError( () => irradianceMatrices( probes, new Float32Array( 96 ), 49 ), 'irradianceMatrices', 'out', '97' );
		expectError( () => irradianceMatrices( probes, new Float32Array( 96 ), - 1 ), 'irradianceMatrices', 'outOffset' );
		// Only the probe that is read is checked for NaN (per-frame cost), and it is named by index.
		probes[ 30 ] = NaN;
		expect( () => irradianceMatrices( probes, undefined, 0, 0 ) ).not.toThrow();
		expectError( () => irradianceMatrices( probes, undefined, 0, 27 ), 'irradianceMatrices', 'sh[30]' );

	} );

	it( 'basis, direction and solid-angle helpers', () => {

		expectError( () => evaluateSHBasis( NaN, 0, 1, new Float32Array( 9 ) ), 'evaluateSHBasis', 'x' );
		expectError( () => evaluateSHBasis( 0, 0, 1, new Float32Array( 8 ) ), 'evaluateSHBasis', 'out', '9' );
		expectError( () => evaluateSHBasis( 0, 0, 1, new Float32Array( 9 ), 1 ), 'evaluateSHBasis', 'out', '10' );
		expectError( () => cubeFaceDirection( 6, 0, 0, 4 ), 'cubeFaceDirection', 'face' );
		expectError( () => cubeFaceDirection( 0, 4, 0, 4 ), 'cubeFaceDirection', 'column' );
		expectError( () => cubeFaceDirection( 0, 0, 0, 4, [ 0, 0 ] ), 'cubeFaceDirection', 'out' );
		expectError( () => cubeTexelSolidAngle( 0, - 1, 4 ), 'cubeTexelSolidAngle', 'row' );

	} );

} );
