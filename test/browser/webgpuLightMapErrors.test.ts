import { Box3, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { placeGrid } from '../../src/placement/placeGrid.js';
import { ProbeVolumeIrradiance } from '../../src/webgpu/lightmap/ProbeVolumeIrradiance.js';

/*
 * Bad input to ProbeVolumeIrradiance (issue 15 interop) gets a named error saying what was
 * expected, and a failed call changes nothing. Runs in Node: nothing here reaches the GPU (the
 * constructor only reads `isWebGPURenderer`; the texture uploads on first use).
 */

const renderer = { isWebGPURenderer: true };

function litVolume(): LightProbeVolume {

	const volume = new LightProbeVolume( { positions: placeGrid( [ 0, 0, 0 ], [ 2, 2, 2 ], [ 2, 2, 2 ] ) } );
	for ( let i = 0; i < volume.count; i ++ ) volume.sh[ 27 * i ] = 1 + i;
	return volume;

}

describe( 'ProbeVolumeIrradiance: bad input', () => {

	it( 'a renderer other than WebGPURenderer is a TypeError naming it', () => {

		for ( const bad of [ { isWebGLRenderer: true }, null, undefined, {} ] ) {

			expect( () => new ProbeVolumeIrradiance( bad, litVolume() ) ).toThrow( /^ProbeVolumeIrradiance: expected a WebGPURenderer/ );

		}

	} );

	it( 'something other than a volume, a volume with no light, or with non-finite SH', () => {

		expect( () => new ProbeVolumeIrradiance( renderer, {} as LightProbeVolume ) ).toThrow( /^ProbeVolumeIrradiance: expected a LightProbeVolume/ );
		const dark = new LightProbeVolume( { positions: placeGrid( [ 0, 0, 0 ], [ 1, 1, 1 ], [ 2, 2, 2 ] ) } );
		expect( () => new ProbeVolumeIrradiance( renderer, dark ) ).toThrow( /^ProbeVolumeIrradiance: the volume has no light yet; call volume.capture/ );
		const broken = litVolume();
		broken.sh[ 5 ] = NaN;
		expect( () => new ProbeVolumeIrradiance( renderer, broken ) ).toThrow( /^ProbeVolumeIrradiance: field\.sh\[5\] is NaN/ );

	} );

	it( 'bad bounds name ProbeVolumeIrradiance and say what was expected', () => {

		const volume = litVolume();
		const cases: [ unknown, RegExp ][] = [
			[ new Box3(), /options\.bounds must be \{ min, max \} with finite x, y, z .*empty Box3/ ],
			[ { min: { x: 0, y: 0, z: 0 } }, /options\.bounds must be \{ min, max \}/ ],
			[ 'room', /options\.bounds must be \{ min, max \}/ ],
			[ new Box3( new Vector3( 1, 0, 0 ), new Vector3( 0, 1, 1 ) ), /options\.bounds\.min must not exceed options\.bounds\.max/ ],
			[ new Box3( new Vector3( 1, 1, 1 ), new Vector3( 1, 1, 1 ) ), /options\.bounds is a single point/ ],
		];
		for ( const [ bounds, message ] of cases ) {

			expect( () => new ProbeVolumeIrradiance( renderer, volume, { bounds: bounds as Box3 } ) ).toThrow( RangeError );
			expect( () => new ProbeVolumeIrradiance( renderer, volume, { bounds: bounds as Box3 } ) ).toThrow( new RegExp( '^ProbeVolumeIrradiance: ' + message.source ) );

		}

		// A flat box (a floor) is fine: the texture widens it to one texel.
		const floor = new Box3( new Vector3( 0, 1, 0 ), new Vector3( 2, 1, 2 ) );
		expect( () => new ProbeVolumeIrradiance( renderer, volume, { bounds: floor, resolution: 4 } ) ).not.toThrow();

	} );

	it( 'bad options name ProbeVolumeIrradiance', () => {

		const volume = litVolume();
		expect( () => new ProbeVolumeIrradiance( renderer, volume, 'fast' as never ) ).toThrow( /^ProbeVolumeIrradiance: options must be an object/ );
		expect( () => new ProbeVolumeIrradiance( renderer, volume, { type: 'double' as never } ) ).toThrow( /^ProbeVolumeIrradiance: options\.type is "double"; expected 'half' or 'float'/ );
		expect( () => new ProbeVolumeIrradiance( renderer, volume, { resolution: 0 } ) ).toThrow( /^ProbeVolumeIrradiance: options\.resolution must be/ );
		expect( () => new ProbeVolumeIrradiance( renderer, volume, { texelSize: - 1 } ) ).toThrow( /^ProbeVolumeIrradiance: options\.texelSize must be/ );
		expect( () => new ProbeVolumeIrradiance( renderer, volume, { intensity: - 1 } ) ).toThrow( /^ProbeVolumeIrradiance: options\.intensity must be a finite number ≥ 0/ );

	} );

	it( 'a bad intensity is refused and the old one kept', () => {

		const source = new ProbeVolumeIrradiance( renderer, litVolume(), { intensity: 2, resolution: 4 } );
		for ( const bad of [ NaN, - 0.5, Infinity, '1' ] ) {

			expect( () => { source.intensity = bad as number; } ).toThrow( /^ProbeVolumeIrradiance\.intensity: expected a finite number ≥ 0/ );
			expect( source.intensity ).toBe( 2 );

		}

	} );

	it( 'update() with non-finite SH throws by its own name and leaves the texture as it was', () => {

		const volume = litVolume();
		const source = new ProbeVolumeIrradiance( renderer, volume, { type: 'float', resolution: 4 } );
		const data = ( source.volumeTexture.texture.image as { data: Float32Array } ).data;
		const before = data.slice();
		volume.sh[ 27 ] = Infinity;
		expect( () => source.update() ).toThrow( /^ProbeVolumeIrradiance\.update: field\.sh\[27\] is Infinity/ );
		expect( data ).toEqual( before );
		// And a real change does resample: the texture's first node follows probe 0.
		volume.sh[ 27 ] = 2;
		volume.sh[ 0 ] = 5;
		source.update();
		expect( data[ 4 * ( 0 + 1 * 0 ) + 4 * source.volumeTexture.resolution.x * source.volumeTexture.resolution.y ] ).toBeCloseTo( 5, 5 );

	} );

	it( 'after dispose(): update, irradiance and intensity throw, a second dispose does nothing', () => {

		const source = new ProbeVolumeIrradiance( renderer, litVolume(), { resolution: 4 } );
		source.dispose();
		expect( () => source.update() ).toThrow( /^ProbeVolumeIrradiance\.update: called after dispose\(\)/ );
		expect( () => source.irradiance( null, null ) ).toThrow( /^ProbeVolumeIrradiance\.irradiance: called after dispose\(\)/ );
		expect( () => { source.intensity = 1; } ).toThrow( /^ProbeVolumeIrradiance\.intensity: set after dispose\(\)/ );
		expect( () => source.dispose() ).not.toThrow();

	} );

} );
