import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { BakedVolumeError, LightProbeVolume } from '../../src/index.js';
import { decodeBakedVolume, encodeBakedVolume } from '../../src/format.js';
import type { BakedFit } from '../../src/io/index.js';
import { LightProbeVolumeExporter } from '../../src/runtime/LightProbeVolumeExporter.js';
import { LightProbeVolumeLoader } from '../../src/runtime/LightProbeVolumeLoader.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';
import { randomVolume } from '../helpers/randomVolume.js';

/*
 * Gradient probes and the fit record through LightProbeVolumeExporter → LightProbeVolumeLoader
 * (the sections themselves are tested in test/io/gradients.test.ts). The truth: gradient probes
 * reproduce a field linear in space exactly, Σ wᵢ (cᵢ + G·(q − pᵢ)) = c(q) for any weights summing
 * to 1, so a loaded volume must sample such a field exactly everywhere, inside the hull and out.
 */

const loader = new LightProbeVolumeLoader();
const exporter = new LightProbeVolumeExporter();

const FIT: BakedFit = { samples: 800, gradients: true, lambda: 0.125, gradientLambda: 0.5, crossValidationError: 0.0561, source: 'test' };

/** A linear SH field: value k at q is A[k] + Σₐ B[a][k]·q[a], seeded. */
function linearField( seed: number ): { at: ( q: ArrayLike<number>, k: number ) => number; gradient: Float32Array } {

	const random = mulberry32( seed );
	// Values and slopes exact in float32 (multiples of 1/64, 1/256); the probes' SH are the field rounded to float32.
	const A = Array.from( { length: 27 }, () => Math.round( 64 * random() ) / 64 );
	// ( + 0 turns −0 into 0, which JSON cannot tell apart.)
	const gradient = Float32Array.from( { length: 81 }, () => Math.round( 256 * ( random() - 0.5 ) / 4 ) / 256 + 0 );
	const at = ( q: ArrayLike<number>, k: number ) => A[ k ]
		+ gradient[ k ] * q[ 0 ] + gradient[ 27 + k ] * q[ 1 ] + gradient[ 54 + k ] * q[ 2 ];
	return { at, gradient };

}

/** `volume` (positions kept) holding the linear field as gradient probes, with the fit record. */
function gradientVolume( count: number, seed: number ): { volume: LightProbeVolume; field: ReturnType<typeof linearField> } {

	const base = randomVolume( count, seed, 'gradient bake' );
	const field = linearField( seed + 1 );
	const sh = new Float32Array( 27 * count ), gradients = new Float32Array( 81 * count );
	for ( let i = 0; i < count; i ++ ) {

		const p = base.positions.subarray( 3 * i, 3 * i + 3 );
		for ( let k = 0; k < 27; k ++ ) sh[ 27 * i + k ] = field.at( p, k );
		gradients.set( field.gradient, 81 * i );

	}

	const volume = new LightProbeVolume( { positions: base.positions, sh, gradients, names: base.names, roles: base.roles } );
	volume.fitSettings = FIT;
	volume.metadata = base.metadata;
	return { volume, field };

}

/** Largest |sample − field| over seeded points in and around the 10 m box, relative to 1 + |field|. */
function fieldError( volume: LightProbeVolume, field: ReturnType<typeof linearField> ): number {

	const random = mulberry32( 5 );
	const target = new Float32Array( 27 );
	let worst = 0;
	for ( let n = 0; n < 300; n ++ ) {

		const q = [ 16 * random() - 3, 16 * random() - 3, 16 * random() - 3 ];
		volume.sample( q, target );
		for ( let k = 0; k < 27; k ++ ) {

			const truth = field.at( q, k );
			worst = Math.max( worst, Math.abs( target[ k ] - truth ) / ( 1 + Math.abs( truth ) ) );

		}


	}

	return worst;

}

describe( 'LightProbeVolume baked files with gradient probes', () => {

	it( 'binary float32: gradients bitwise, fitSettings, and the loaded volume samples the linear field as exactly as the baked one', () => {

		const { volume, field } = gradientVolume( 50, 11 );
		const loaded = loader.parse( exporter.parse( volume ) );
		expect( Array.from( loaded.gradients! ) ).toEqual( Array.from( volume.gradients! ) );
		expect( loaded.fitSettings ).toEqual( FIT );
		expect( loaded.metadata ).toBe( 'gradient bake' );
		// Float32 sums of ~10 terms: a few ulps of values up to ~10.
		const baked = fieldError( volume, field );
		expect( baked ).toBeLessThan( 1e-5 );
		expect( fieldError( loaded, field ) ).toBe( baked );
		// The same SH without the gradients (what a 1.0 reader loads) do not: the gradient term is used.
		const plain = LightProbeVolume.fromBakedData( { ...decodeBakedVolume( exporter.parse( volume ) ), gradients: null, fit: null } );
		expect( fieldError( plain, field ) ).toBeGreaterThan( 0.05 );

	} );

	it( 'binary float16 and JSON: the field within half precision / exactly', () => {

		const { volume, field } = gradientVolume( 40, 12 );
		const half = loader.parse( exporter.parse( volume, { precision: 'float16' } ) );
		for ( let i = 0; i < volume.gradients!.length; i ++ ) {

			const value = volume.gradients![ i ];
			expect( Math.abs( half.gradients![ i ] - value ), `gradients[${i}]` ).toBeLessThanOrEqual( Math.abs( value ) * 2 ** - 11 );

		}

		// SH and gradients rounded by ≤ 2^−11 relative: the field within ~1e-3 of 1 + |value| over the ±13 m test box.
		expect( fieldError( half, field ) ).toBeLessThan( 5e-3 );
		const json = loader.parse( JSON.stringify( exporter.parse( volume, { binary: false } ) ) );
		expect( Array.from( json.gradients! ) ).toEqual( Array.from( volume.gradients! ) );
		expect( json.fitSettings ).toEqual( FIT );
		expect( fieldError( json, field ) ).toBe( fieldError( volume, field ) );

	} );

	it( 'after removeProbe the live probes\' gradients are written renumbered, and the loaded volume lights as the edited one', () => {

		const { volume, field } = gradientVolume( 40, 13 );
		volume.removeProbe( 4 );
		volume.removeProbe( 21 );
		const loaded = loader.parse( exporter.parse( volume ) );
		expect( loaded.count ).toBe( 38 );
		const live = Array.from( { length: 40 }, ( _, i ) => i ).filter( ( i ) => volume.isProbeActive( i ) );
		const expected = live.flatMap( ( i ) => Array.from( volume.gradients!.subarray( 81 * i, 81 * i + 81 ) ) );
		expect( Array.from( loaded.gradients! ) ).toEqual( expected );
		// The remaining probes still hold the linear field: exact after the edit and after the round trip.
		expect( fieldError( loaded, field ) ).toBeLessThan( 1e-5 );

	} );

	it( 'a plain volume, and the stored 1.0 file, load with gradients and fitSettings null', () => {

		const plain = loader.parse( exporter.parse( randomVolume( 20, 14, 'plain' ) ) );
		expect( [ plain.gradients, plain.fitSettings ] ).toEqual( [ null, null ] );
		const old = loader.parse( readFileSync( new URL( '../io/fixtures/v1.0-tiny.lpv', import.meta.url ) ) );
		expect( [ old.gradients, old.fitSettings ] ).toEqual( [ null, null ] );
		expect( old.count ).toBe( 5 );
		const stored = loader.parse( readFileSync( new URL( '../io/fixtures/v1.1-gradients-tiny.lpv', import.meta.url ) ) );
		expect( stored.gradients!.length ).toBe( 5 * 81 );
		expect( stored.fitSettings!.samples ).toBe( 64 );
		// Data shaped as before version 1.1 (no gradients or fit member) loads as plain probes.
		const { gradients: _g, fit: _f, ...before } = decodeBakedVolume( exporter.parse( randomVolume( 10, 15, 'old' ) ) );
		expect( LightProbeVolume.fromBakedData( before as Parameters<typeof LightProbeVolume.fromBakedData>[ 0 ] ).gradients ).toBeNull();

	} );

	it( 'named errors: gradients given with a file; malformed gradients in decoded data; a fit record claiming gradients the volume lacks', () => {

		const file = exporter.parse( gradientVolume( 10, 16 ).volume );
		expect( () => loader.parse( file, { gradients: new Float32Array( 810 ) } as never ) ).toThrow( /^LightProbeVolumeLoader\.parse: parameters\.gradients .*comes from the baked file/ );
		const data = decodeBakedVolume( file );
		expect( () => LightProbeVolume.fromBakedData( { ...data, gradients: new Float32Array( 80 ) } ) )
			.toThrow( /^LightProbeVolume\.fromBakedData: data\.gradients must be null or a Float32Array of 81 floats per probe/ );
		expect( () => LightProbeVolume.fromBakedData( { ...data, fit: 'fitted' as never } ) ).toThrow( /data\.fit must be null or a fit record/ );

		const volume = randomVolume( 10, 17, 'claims' );
		volume.fitSettings = FIT;
		let caught: unknown = null;
		try {

			exporter.parse( volume );

		} catch ( error ) {

			caught = error;

		}

		expect( caught ).toBeInstanceOf( BakedVolumeError );
		expect( caught ).toMatchObject( { code: 'count' } );
		expect( ( caught as Error ).message ).toMatch( /^LightProbeVolumeExporter\.parse: fit\.gradients is true but the volume holds no gradients/ );
		// The codec agrees with the runtime's gradient bound: what it refuses, the volume refuses too.
		const tooLarge = new Float32Array( 810 ).fill( 1e30 );
		expect( () => encodeBakedVolume( { ...data, gradients: tooLarge } ) ).toThrow( BakedVolumeError );
		expect( () => new LightProbeVolume( { positions: data.positions, sh: data.sh, gradients: tooLarge } ) ).toThrow( RangeError );

	} );

} );
