/**
 * Gradient probes in a LightProbeVolume, without a GPU. Truth, independent of the code under test: a field linear in
 * space, SH(q) = a + B·q, with each probe holding its value c = a + B·p and gradient G = B. The gradient formula
 * Σ wᵢ (cᵢ + Gᵢ (q − pᵢ)) is then a + B·q for any weights that sum to 1 — inside the hull, in the outer cells, in a
 * zone's own tetrahedralization, after the visibility guard's renormalisation — so every mode must give the analytic
 * SH at its point: sample(), object mode (irradiance matrices at the anchor), the scenery of bounce passes, per vertex
 * and per texel. Plain probes (no gradients) do not reproduce the field outside the hull, which shows each check can fail.
 */
import { getHeapSpaceStatistics } from 'node:v8';
import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { GridInterpolator } from '../../src/interpolation/GridInterpolator.js';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { ProbeVertexLighting } from '../../src/runtime/ProbeVertexLighting.js';
import { ProbeVolumeTexture } from '../../src/runtime/ProbeVolumeTexture.js';
import { CAPTURE_ACCESS } from '../../src/runtime/captureProbes.js';
import { lightScenery } from '../../src/runtime/sceneryLight.js';
import { blendSH } from '../../src/interpolation/blendSH.js';
import { irradianceAt, irradianceMatrices } from '../../src/sh/irradiance.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';

/** The linear field: a (27) and B (81, B[ 27·axis + k ] = ∂SH_k/∂axis). */
function linearField( seed = 1 ) {

	const random = mulberry32( seed );
	const a = Array.from( { length: 27 }, ( _, k ) => ( k < 3 ? 2 : 0 ) + random() - 0.5 );
	const B = Array.from( { length: 81 }, () => 0.3 * ( random() - 0.5 ) );
	const at = ( x: number, y: number, z: number, out = new Float64Array( 27 ) ) => {

		for ( let k = 0; k < 27; k ++ ) out[ k ] = a[ k ] + B[ k ] * x + B[ 27 + k ] * y + B[ 54 + k ] * z;
		return out;

	};

	return { a, B, at };

}

type Field = ReturnType<typeof linearField>;

/** A jittered 4 × 3 × 4 layout in [−2, 2] × [0, 2] × [−2, 2]: its SH and gradients from the field. */
function layout( field: Field, seed = 2 ) {

	const random = mulberry32( seed );
	const positions: number[] = [];
	for ( let i = 0; i < 4; i ++ ) for ( let j = 0; j < 3; j ++ ) for ( let k = 0; k < 4; k ++ ) {

		const jitter = () => 0.3 * ( random() - 0.5 );
		positions.push( - 2 + 4 * i / 3 + jitter(), j + jitter(), - 2 + 4 * k / 3 + jitter() );

	}

	return { positions, ...probesOf( field, positions ) };

}

function probesOf( field: Field, positions: ArrayLike<number> ) {

	const count = positions.length / 3;
	const sh = new Float32Array( 27 * count ), gradients = new Float32Array( 81 * count );
	for ( let i = 0; i < count; i ++ ) {

		sh.set( field.at( positions[ 3 * i ], positions[ 3 * i + 1 ], positions[ 3 * i + 2 ] ), 27 * i );
		gradients.set( field.B, 81 * i );

	}

	return { sh, gradients };

}

/** Largest |actual − expected| relative to max( 1, |expected| ) over 27 (or n) values. */
function worst( actual: ArrayLike<number>, expected: ArrayLike<number>, n = 27 ): number {

	let error = 0;
	for ( let k = 0; k < n; k ++ ) {

		error = Math.max( error, Math.abs( actual[ k ] - expected[ k ] ) / Math.max( 1, Math.abs( expected[ k ] ) ) );

	}

	return error;

}

/** Points inside the layout, just outside it and far outside it (outer cells), below the floor of probes too. */
function testPoints( count = 60, seed = 3 ): number[][] {

	const random = mulberry32( seed );
	const points: number[][] = [];
	for ( let i = 0; i < count; i ++ ) {

		const reach = [ 1.5, 3, 8 ][ i % 3 ];
		points.push( [ reach * ( 2 * random() - 1 ), 1 + reach * ( 2 * random() - 1 ), reach * ( 2 * random() - 1 ) ] );

	}

	return points;

}

const TOLERANCE = 2e-6; // float32 storage of c and G

function sphere(): THREE.Mesh {

	return new THREE.Mesh( new THREE.SphereGeometry( 0.1 ), new THREE.MeshStandardMaterial() );

}

describe( 'gradient probes: a linear field is reproduced exactly in every mode', () => {

	const field = linearField();
	const { positions, sh, gradients } = layout( field );

	it( 'sample(): everywhere, inside the hull and outside it (outer cells); the plain probes only inside', () => {

		const volume = new LightProbeVolume( { positions, sh, gradients } );
		const plain = new LightProbeVolume( { positions, sh } );
		let plainOutside = 0;
		for ( const [ x, y, z ] of testPoints() ) {

			const expected = field.at( x, y, z );
			expect( worst( volume.sample( [ x, y, z ] ), expected ) ).toBeLessThan( TOLERANCE );
			plainOutside = Math.max( plainOutside, worst( plain.sample( [ x, y, z ] ), expected ) );

		}

		expect( plainOutside ).toBeGreaterThan( 0.1 );

	} );

	it( 'sample() with a grid interpolator (8 weights), planar probes (3) and collinear ones (2), outside them too', () => {

		const grid = new GridInterpolator( [ - 2, 0, - 2 ], [ 2, 2, 2 ], [ 3, 2, 3 ] );
		const planar: number[] = [], line: number[] = [];
		for ( let i = 0; i < 9; i ++ ) planar.push( Math.sin( 2.1 * i ) * 2, 1, Math.cos( 1.3 * i ) * 2 );
		for ( let i = 0; i < 4; i ++ ) line.push( i - 1.5, 0.5 * i, 0 );
		const cases = [
			{ positions: grid.positions, interpolator: grid },
			{ positions: planar },
			{ positions: line },
		];
		for ( const { positions: p, interpolator } of cases ) {

			const volume = new LightProbeVolume( { positions: p, ...probesOf( field, p ), interpolator } );
			for ( const [ x, y, z ] of testPoints( 30, 4 ) ) {

				expect( worst( volume.sample( [ x, y, z ] ), field.at( x, y, z ) ) ).toBeLessThan( TOLERANCE );

			}


		}

	} );

	it( 'sample() in zones (each its own tetrahedralization, a point of one zone far in the other\'s) and through the visibility guard', () => {

		const count = positions.length / 3;
		const left: number[] = [], right: number[] = [];
		for ( let i = 0; i < count; i ++ ) ( positions[ 3 * i ] < 0 ? left : right ).push( i );
		const box = ( x0: number, x1: number ) => ( { min: { x: x0, y: - 5, z: - 5 }, max: { x: x1, y: 5, z: 5 } } );
		const zones = [ { name: 'left', probes: left, bounds: box( - 5, 0 ) }, { name: 'right', probes: right, bounds: box( 0, 5 ) } ];
		const zoned = new LightProbeVolume( { positions, sh, gradients, zones } );
		for ( const [ x, y, z ] of testPoints( 30, 5 ) ) {

			expect( worst( zoned.sample( [ x, y, z ] ), field.at( x, y, z ) ) ).toBeLessThan( TOLERANCE );
			expect( worst( zoned.sample( [ x, y, z ], undefined, { zone: 'left' } ), field.at( x, y, z ) ) ).toBeLessThan( TOLERANCE );

		}

		// A wall at x = 0.3 blocks the probes on its other side: weights renormalised, or the nearest visible probe alone.
		const wall = [ 0.3, - 10, - 10, 0.3, 10, - 10, 0.3, - 10, 10, 0.3, 10, - 10, 0.3, 10, 10, 0.3, - 10, 10 ];
		const guarded = new LightProbeVolume( { positions, sh, gradients, occluders: wall } );
		const plain = new LightProbeVolume( { positions, sh, occluders: wall } );
		let moved = 0;
		for ( const [ x, y, z ] of testPoints( 30, 6 ) ) {

			expect( worst( guarded.sample( [ x, y, z ] ), field.at( x, y, z ) ) ).toBeLessThan( TOLERANCE );
			moved = Math.max( moved, worst( plain.sample( [ x, y, z ] ), field.at( x, y, z ) ) );

		}

		expect( moved ).toBeGreaterThan( 0.01 ); // the guard changed weights, which plain probes do not survive

	} );

	it( 'object mode: update() writes the irradiance matrices of the analytic SH at the object\'s anchor, inside and outside the hull', () => {

		const volume = new LightProbeVolume( { positions, sh, gradients } );
		const plain = new LightProbeVolume( { positions, sh } );
		const mesh = sphere(), other = sphere();
		const parent = new THREE.Group();
		parent.add( mesh );
		parent.position.set( 0.5, - 0.25, 0 );
		volume.add( mesh );
		plain.add( other );
		const matrices = volume.getUniforms( mesh )!.probeVolumeMatrices.value;
		let plainError = 0;
		for ( const [ x, y, z ] of testPoints( 30, 7 ) ) {

			mesh.position.set( x - 0.5, y + 0.25, z );
			other.position.set( x, y, z );
			volume.update();
			plain.update();
			const expected = irradianceMatrices( field.at( x, y, z ), new Float64Array( 48 ) );
			expect( worst( matrices, expected, 48 ) ).toBeLessThan( TOLERANCE );
			plainError = Math.max( plainError, worst( plain.getUniforms( other )!.probeVolumeMatrices.value, expected, 48 ) );

		}

		expect( plainError ).toBeGreaterThan( 0.05 );
		volume.dispose();
		plain.dispose();

	} );

	it( 'static scenery (add( scene )\'s props) blends again when gradients are set, replaced, written in place or removed', () => {

		const volume = new LightProbeVolume( { positions, sh } );
		const scene = new THREE.Scene();
		const prop = sphere();
		prop.position.set( 5, 1, 0 ); // outside the hull: the gradients matter here
		scene.add( prop );
		volume.add( scene );
		expect( volume.getLighting( prop ) ).toBe( 'object' );
		const matrices = volume.getUniforms( prop )!.probeVolumeMatrices.value;
		const expected = irradianceMatrices( field.at( 5, 1, 0 ), new Float64Array( 48 ) );
		const plainMatrices = Array.from( matrices );
		expect( worst( matrices, expected, 48 ) ).toBeGreaterThan( 0.05 );
		volume.setGradients( gradients );
		volume.update();
		expect( worst( matrices, expected, 48 ) ).toBeLessThan( TOLERANCE );
		// Written in place: found by comparing with the registry's copy, as for sh.
		volume.gradients!.fill( 0 );
		volume.update();
		const zeroGradients = Array.from( matrices );
		expect( worst( zeroGradients, expected, 48 ) ).toBeGreaterThan( 0.05 );
		volume.gradients!.set( gradients );
		volume.update();
		expect( worst( matrices, expected, 48 ) ).toBeLessThan( TOLERANCE );
		volume.setGradients( null );
		volume.update();
		expect( Array.from( matrices ) ).toEqual( plainMatrices );
		expect( zeroGradients ).toEqual( plainMatrices ); // zero gradients are plain probes, bit for bit
		volume.dispose();

	} );

	it( 'the scenery of a bounce pass (lightScenery) takes a field\'s gradients at its anchor', () => {

		const volume = new LightProbeVolume( { positions } );
		const scene = new THREE.Scene();
		const prop = sphere();
		prop.position.set( - 4, 3, 2 );
		scene.add( prop );
		volume.add( scene );
		const { lit } = volume[ CAPTURE_ACCESS ]();
		const matrices = volume.getUniforms( prop )!.probeVolumeMatrices.value;
		const restore = lightScenery( lit, { interpolator: volume.interpolator, sh, gradients, positions: volume.positions } );
		expect( worst( matrices, irradianceMatrices( field.at( - 4, 3, 2 ), new Float64Array( 48 ) ), 48 ) ).toBeLessThan( TOLERANCE );
		restore();
		expect( Array.from( matrices ).every( ( v ) => v === 0 ) ).toBe( true ); // the volume's own (black) light is back
		volume.dispose();

	} );

	it( 'per vertex (SH and irradiance outputs): the analytic SH / E(n) at every vertex of a floor outside the hull', () => {

		const volume = new LightProbeVolume( { positions, sh, gradients } );
		for ( const output of [ 'sh', 'irradiance' ] as const ) {

			const geometry = new THREE.PlaneGeometry( 12, 12, 6, 6 ).rotateX( - Math.PI / 2 );
			const floor = new THREE.Mesh( geometry, new THREE.MeshStandardMaterial() );
			floor.position.set( 1, - 1.5, 0 ); // below every probe
			floor.updateMatrixWorld();
			const lighting = new ProbeVertexLighting( floor, volume, { output } );
			const position = floor.geometry.getAttribute( 'position' ), world = new THREE.Vector3();
			const irradiance = new Float64Array( 3 );
			for ( let i = 0; i < position.count; i ++ ) {

				world.fromBufferAttribute( position, i ).applyMatrix4( floor.matrixWorld );
				const expected = field.at( world.x, world.y, world.z );
				if ( output === 'sh' ) {

					expect( worst( lighting.data.subarray( 28 * i, 28 * i + 27 ), expected ) ).toBeLessThan( TOLERANCE );

				} else {

					irradianceAt( expected, 0, 0, 1, 0, irradiance, 0 );
					expect( worst( lighting.data.subarray( 3 * i, 3 * i + 3 ), irradiance, 3 ) ).toBeLessThan( TOLERANCE );

				}

			}

			lighting.dispose();

		}

	} );

	it( 'per texel (ProbeVolumeTexture, float): the analytic SH at every node; add( mesh, { mode: \'texture\' } ) in half floats', () => {

		const volume = new LightProbeVolume( { positions, sh, gradients } );
		const box = new THREE.Box3( new THREE.Vector3( - 6, - 3, - 1 ), new THREE.Vector3( 4, 5, 6 ) );
		const texture = new ProbeVolumeTexture( volume, box, { type: 'float', resolution: [ 5, 4, 6 ] } );
		const data = ( texture.texture.image as { data: Float32Array } ).data;
		const { x: nx, y: ny, z: nz } = texture.resolution, slice = nx * ny, subVolume = slice * ( nz + 2 );
		const node = new THREE.Vector3(), values = new Float64Array( 27 );
		for ( let iz = 0; iz < nz; iz ++ ) for ( let iy = 0; iy < ny; iy ++ ) for ( let ix = 0; ix < nx; ix ++ ) {

			texture.nodePosition( ix, iy, iz, node );
			const texel = ix + nx * iy + slice * ( 1 + iz );
			for ( let k = 0; k < 27; k ++ ) values[ k ] = data[ 4 * ( texel + subVolume * Math.floor( k / 4 ) ) + k % 4 ];
			expect( worst( values, field.at( node.x, node.y, node.z ) ) ).toBeLessThan( TOLERANCE );

		}

		texture.dispose();

		const wall = new THREE.Mesh( new THREE.PlaneGeometry( 8, 3 ), new THREE.MeshStandardMaterial() );
		wall.position.set( 0, 1.5, - 5 ); // behind the probes: outer cells
		wall.updateMatrixWorld();
		volume.add( wall, { mode: 'texture', maxResolution: 8 } );
		const uniforms = volume.getUniforms( wall )!;
		const fromHalf = THREE.DataUtils.fromHalfFloat;
		const half = ( uniforms.probeVolumeSH!.value!.image as { data: Uint16Array } ).data;
		const min = uniforms.probeVolumeGridMin!.value, max = uniforms.probeVolumeGridMax!.value;
		const r = uniforms.probeVolumeGridResolution!.value;
		const s = r.x * r.y, sub = s * ( r.z + 2 );
		let error = 0;
		for ( let iy = 0; iy < r.y; iy ++ ) for ( let ix = 0; ix < r.x; ix ++ ) {

			const x = min.x + ( max.x - min.x ) * ix / ( r.x - 1 ), y = min.y + ( max.y - min.y ) * iy / ( r.y - 1 ), z = min.z;
			const texel = ix + r.x * iy + s; // the first slice of nodes: z = min.z
			for ( let k = 0; k < 27; k ++ ) values[ k ] = fromHalf( half[ 4 * ( texel + sub * Math.floor( k / 4 ) ) + k % 4 ] );
			error = Math.max( error, worst( values, field.at( x, y, z ) ) );

		}

		expect( error ).toBeLessThan( 2e-3 ); // half floats: 11 bits
		volume.dispose();

	} );

} );

describe( 'gradient probes: the lightings follow changes of the gradients', () => {

	const field = linearField( 11 );
	const { positions, sh, gradients } = layout( field, 12 );

	it( 'ProbeVertexLighting and ProbeVolumeTexture resample when gradients are set, written in place or removed, and not otherwise', () => {

		const volume = new LightProbeVolume( { positions, sh } );
		const floor = new THREE.Mesh( new THREE.PlaneGeometry( 10, 10, 4, 4 ).rotateX( - Math.PI / 2 ), new THREE.MeshStandardMaterial() );
		floor.position.y = - 2;
		floor.updateMatrixWorld();
		const vertices = new ProbeVertexLighting( floor, volume, { output: 'sh' } );
		const box = new THREE.Box3( new THREE.Vector3( - 5, - 3, - 5 ), new THREE.Vector3( 5, - 1, 5 ) );
		const texture = new ProbeVolumeTexture( volume, box );
		const plainVertices = vertices.data.slice();
		const plainTexels = ( texture.texture.image as { data: Uint16Array } ).data.slice();
		expect( vertices.update() ).toBe( false );
		expect( texture.resample( false ) ).toBe( false );
		volume.setGradients( gradients );
		expect( vertices.update() ).toBe( true );
		expect( texture.resample( false ) ).toBe( true );
		expect( vertices.update() ).toBe( false );
		expect( texture.resample( false ) ).toBe( false );
		const world = new THREE.Vector3();
		world.fromBufferAttribute( floor.geometry.getAttribute( 'position' ), 0 ).applyMatrix4( floor.matrixWorld );
		expect( worst( vertices.data.subarray( 0, 27 ), field.at( world.x, world.y, world.z ) ) ).toBeLessThan( TOLERANCE );
		volume.gradients![ 81 * 5 + 30 ] += 0.5;
		expect( vertices.update() ).toBe( true );
		expect( texture.resample( false ) ).toBe( true );
		volume.setGradients( null );
		expect( vertices.update() ).toBe( true );
		expect( texture.resample( false ) ).toBe( true );
		expect( vertices.data ).toEqual( plainVertices );
		expect( ( texture.texture.image as { data: Uint16Array } ).data ).toEqual( plainTexels );
		volume.setGradients( gradients );
		vertices.update();
		volume.gradients![ 3 ] = NaN;
		expect( () => vertices.update() ).toThrow( /ProbeVertexLighting\.update: field\.gradients\[3\] is NaN/ );
		expect( () => texture.resample( false ) ).toThrow( /ProbeVolumeTexture\.resample: field\.gradients\[3\] is NaN/ );
		vertices.dispose();
		texture.dispose();

	} );

	it( 'a field { interpolator, sh, gradients } without positions, or gradients of another length, is refused by name', () => {

		const volume = new LightProbeVolume( { positions, sh } );
		const floor = new THREE.Mesh( new THREE.PlaneGeometry( 2, 2 ), new THREE.MeshStandardMaterial() );
		const box = new THREE.Box3( new THREE.Vector3( - 1, - 1, - 1 ), new THREE.Vector3( 1, 1, 1 ) );
		const noPositions = { interpolator: volume.interpolator, sh, gradients };
		const short = { interpolator: volume.interpolator, sh, gradients: gradients.subarray( 81 ), positions: volume.positions };
		expect( () => new ProbeVertexLighting( floor, noPositions, { output: 'sh' } ) ).toThrow( /ProbeVertexLighting: a field with gradients needs field\.positions/ );
		expect( () => new ProbeVolumeTexture( short, box ) ).toThrow( /ProbeVolumeTexture: field\.gradients must be null or a Float32Array of 81 × 48/ );
		const huge = {
			interpolator: volume.interpolator, sh, positions: volume.positions,
			gradients: gradients.map( ( v, i ) => ( i === 7 ? 1e30 : v ) ),
		};
		expect( () => new ProbeVolumeTexture( huge, box ) ).toThrow( /ProbeVolumeTexture: field\.gradients\[7\] is 1\.0*\d*e\+30; probe gradients must be finite and within/ );

	} );

} );

describe( 'gradient probes: null gradients are the old results, bit for bit', () => {

	const field = linearField( 21 );
	const { positions, sh, gradients } = layout( field, 22 );

	it( 'sample() and object uniforms of a volume without gradients equal interpolate + blendSH, and after setGradients( null ) too', () => {

		const never = new LightProbeVolume( { positions, sh } );
		const cleared = new LightProbeVolume( { positions, sh, gradients } ).setGradients( null );
		expect( cleared.gradients ).toBe( null );
		const indices = new Uint32Array( 8 ), weights = new Float32Array( 8 );
		const a = sphere(), b = sphere();
		never.add( a );
		cleared.add( b );
		for ( const [ x, y, z ] of testPoints( 30, 23 ) ) {

			never.interpolator.interpolate( x, y, z, indices, weights, - 1 );
			const expected = blendSH( indices, weights, sh, new Float32Array( 27 ), never.interpolator.weightCount );
			expect( never.sample( [ x, y, z ] ) ).toEqual( expected );
			expect( cleared.sample( [ x, y, z ] ) ).toEqual( expected );
			a.position.set( x, y, z );
			b.position.set( x, y, z );
			never.update();
			cleared.update();
			expect( never.getUniforms( a )!.probeVolumeMatrices.value ).toEqual( irradianceMatrices( expected ) );
			expect( cleared.getUniforms( b )!.probeVolumeMatrices.value ).toEqual( never.getUniforms( a )!.probeVolumeMatrices.value );

		}

	} );

} );

describe( 'gradient probes: edits keep the gradients in step', () => {

	const field = linearField( 31 );
	const { positions, sh, gradients } = layout( field, 32 );

	it( 'moveProbe zeroes the moved probe\'s gradient, addProbe appends a zero one (its SH from the gradient formula), removeProbe zeroes', () => {

		const volume = new LightProbeVolume( { positions, sh, gradients } );
		const count = volume.count;
		volume.moveProbe( 5, [ 0.1, 0.9, 0.2 ] );
		expect( volume.gradients!.length ).toBe( 81 * count );
		expect( Array.from( volume.gradients!.subarray( 81 * 5, 81 * 6 ) ).every( ( v ) => v === 0 ) ).toBe( true );
		expect( volume.gradients!.subarray( 81 * 6 ) ).toEqual( gradients.subarray( 81 * 6 ) );
		expect( volume.gradients!.subarray( 0, 81 * 5 ) ).toEqual( gradients.subarray( 0, 81 * 5 ) );

		// The added probe's SH: the field there before it was added — exact, as it is the gradient formula's.
		const before = volume.sample( [ 6, 1, 0 ] );
		const index = volume.addProbe( [ 6, 1, 0 ] );
		expect( index ).toBe( count );
		expect( volume.gradients!.length ).toBe( 81 * ( count + 1 ) );
		expect( Array.from( volume.gradients!.subarray( 81 * index ) ).every( ( v ) => v === 0 ) ).toBe( true );
		expect( volume.sh.subarray( 27 * index, 27 * index + 27 ) ).toEqual( before );
		expect( worst( before, field.at( 6, 1, 0 ) ) ).toBeLessThan( TOLERANCE );
		for ( let i = 0; i < 20; i ++ ) volume.addProbe( [ 7 + 0.3 * i, Math.sin( i ), Math.cos( i ) ] ); // the store grows
		expect( volume.gradients!.length ).toBe( 81 * volume.count );
		expect( volume.gradients!.subarray( 81 * 6, 81 * count ) ).toEqual( gradients.subarray( 81 * 6 ) );
		expect( Array.from( volume.gradients!.subarray( 81 * count ) ).every( ( v ) => v === 0 ) ).toBe( true );

		volume.removeProbe( 7 );
		expect( volume.gradients!.length ).toBe( 81 * volume.count );
		expect( Array.from( volume.gradients!.subarray( 81 * 7, 81 * 8 ) ).every( ( v ) => v === 0 ) ).toBe( true );
		// New gradients after the removal: the removed slot is kept at zero; the next add starts from them.
		const next = new Float32Array( 81 * volume.count ).fill( 0.01 );
		volume.setGradients( next );
		expect( volume.gradients ).not.toBe( next );
		expect( Array.from( volume.gradients!.subarray( 81 * 7, 81 * 8 ) ).every( ( v ) => v === 0 ) ).toBe( true );
		expect( volume.gradients![ 81 * 8 ] ).toBeCloseTo( 0.01, 7 );
		const last = volume.addProbe( [ 0, - 3, 0 ] );
		expect( volume.gradients!.length ).toBe( 81 * volume.count );
		expect( volume.gradients![ 81 * 8 ] ).toBeCloseTo( 0.01, 7 );
		expect( Array.from( volume.gradients!.subarray( 81 * last ) ).every( ( v ) => v === 0 ) ).toBe( true );

	} );

	it( 'edits of a plain volume leave gradients null', () => {

		const volume = new LightProbeVolume( { positions, sh } );
		volume.moveProbe( 2, [ - 1.9, 0.1, 0.3 ] );
		volume.addProbe( [ 3, 3, 3 ] );
		volume.removeProbe( 4 );
		expect( volume.gradients ).toBe( null );

	} );

} );

describe( 'gradient probes: bad gradients get named errors and change nothing', () => {

	const field = linearField( 41 );
	const { positions, sh, gradients } = layout( field, 42 );

	it( 'setGradients: wrong length, NaN, Infinity, a string, a non-array, a value beyond 1e30 / the layout\'s diagonal', () => {

		const volume = new LightProbeVolume( { positions, sh, gradients } );
		const kept = volume.gradients, copy = kept!.slice(), sampled = volume.sample( [ 4, 1, 4 ] );
		const withValue = ( i: number, v: unknown ) => {

			const g: unknown[] = Array.from( gradients );
			g[ i ] = v;
			return g as number[];

		};

		const diagonal = Math.hypot( ...[ 0, 1, 2 ].map( ( a ) => {

			const c = positions.filter( ( _, i ) => i % 3 === a );
			return Math.max( ...c ) - Math.min( ...c );

		} ) );
		const bad: [ unknown, RegExp ][] = [
			[ gradients.subarray( 1 ), /LightProbeVolume\.setGradients: gradients must have length 3888 \(81 floats.*48 probes\), got 3887/ ],
			[ new Float32Array( 27 * 48 ), /must have length 3888/ ],
			[ withValue( 10, NaN ), /LightProbeVolume\.setGradients: gradients\[10\] is NaN; probe gradients must be finite/ ],
			[ withValue( 11, Infinity ), /gradients\[11\] is Infinity/ ],
			[ withValue( 12, '0.5' ), /TypeError|gradients\[12\] is string/ ],
			[ withValue( 13, 1.01e30 / diagonal ), /gradients\[13\] is .*within ±/ ],
			[ 'gradients', /LightProbeVolume\.setGradients: gradients must be an array or typed array of numbers/ ],
			[ undefined, /gradients must be an array/ ],
		];
		for ( const [ value, message ] of bad ) {

			expect( () => volume.setGradients( value as number[] ) ).toThrow( message );
			expect( volume.gradients ).toBe( kept );
			expect( volume.gradients ).toEqual( copy );
			expect( volume.sample( [ 4, 1, 4 ] ) ).toEqual( sampled );

		}

		// At the bound itself it is taken.
		volume.setGradients( withValue( 13, 0.99e30 / diagonal ) );
		expect( volume.gradients![ 13 ] ).toBeCloseTo( 0.99e30 / diagonal, - 24 );

	} );

	it( 'the constructor: the same checks on parameters.gradients', () => {

		expect( () => new LightProbeVolume( { positions, sh, gradients: gradients.subarray( 81 ) } ) ).toThrow( /^LightProbeVolume: gradients must have length 3888/ );
		expect( () => new LightProbeVolume( { positions, sh, gradients: Array.from( gradients, ( v, i ) => ( i === 99 ? NaN : v ) ) } ) ).toThrow( /^LightProbeVolume: gradients\[99\] is NaN/ );
		const volume = new LightProbeVolume( { positions, sh, gradients: Array.from( gradients ) } );
		expect( volume.gradients ).toBeInstanceOf( Float32Array );
		expect( volume.gradients ).toEqual( gradients );
		expect( volume.gradients ).not.toBe( gradients );

	} );

	it( 'update(): gradients of another length written into the volume, or a NaN gradient, are named', () => {

		const volume = new LightProbeVolume( { positions, sh, gradients } );
		const mesh = sphere();
		mesh.name = 'ball';
		volume.add( mesh );
		volume.gradients = gradients.subarray( 81 );
		expect( () => volume.update() ).toThrow( /^LightProbeVolume\.update: gradients has length 3807, expected 81 × 48 probes; use setGradients\(\)/ );
		volume.setGradients( gradients );
		volume.gradients![ 81 * 3 + 2 ] = NaN;
		mesh.position.set( 0, 0, 0 );
		let thrown: Error | null = null;
		try {

			for ( const [ x, y, z ] of testPoints( 30, 43 ) ) {

				mesh.position.set( x, y, z );
				volume.update();

			}

		} catch ( error ) {

			thrown = error as Error;

		}

		expect( thrown?.message ).toMatch( /LightProbeVolume\.update: the blend for object "?ball"?.*probe 3 holds gradients\[245\] = NaN/ );
		expect( Array.from( volume.getUniforms( mesh )!.probeVolumeMatrices.value ).every( ( v ) => v === 0 ) ).toBe( true );
		volume.dispose();

	} );

} );

describe( 'gradient probes: update() allocates nothing more than with plain probes', () => {

	it( '100 objects (inside and outside the hull) for 500 frames: the young generation grows by the same bytes with gradients as without', () => {

		// Allocation shows as growth of V8's new space between two reads; a scavenge in between empties it, so windows
		// with negative growth are left out and the smallest growth of the others is taken. The loops are warmed up
		// first so they run optimised code. Compared with plain probes, not with zero: the weighting itself
		// (TetrahedralMesh.interpolate) allocates about 16 bytes a call on this Node, which is not the blend's doing.
		const field = linearField( 51 );
		const { positions, sh, gradients } = layout( field, 52 );
		const growthOf = ( withGradients: boolean ) => {

			const volume = new LightProbeVolume( { positions, sh, gradients: withGradients ? gradients : undefined } );
			const meshes = Array.from( { length: 100 }, sphere );
			for ( const mesh of meshes ) volume.add( mesh );
			const frame = ( f: number ) => {

				for ( let i = 0; i < meshes.length; i ++ ) {

					const t = 0.01 * f + i;
					meshes[ i ].position.set( 6 * Math.sin( t ), 1 + 3 * Math.cos( 1.3 * t ), 6 * Math.sin( 0.7 * t - 2 * i ) );

				}

				volume.update();

			};

			for ( let f = 0; f < 2000; f ++ ) frame( f );
			const growth: number[] = [];
			for ( let window = 0; window < 4; window ++ ) {

				const start = newSpace();
				for ( let f = 0; f < 500; f ++ ) frame( f );
				growth.push( newSpace() - start );

			}

			volume.dispose();
			for ( const mesh of meshes ) mesh.geometry.dispose();
			return Math.min( ...growth.filter( ( g ) => g >= 0 ) );

		};

		const plain = growthOf( false ), withGradients = growthOf( true );
		// 50,000 object updates: one allocation of 16 bytes per gradient blend would add 800 kB.
		expect( Math.abs( withGradients - plain ) ).toBeLessThan( 16 * 1024 );

	} );

} );

function newSpace(): number {

	return getHeapSpaceStatistics().find( ( space ) => space.space_name === 'new_space' )!.space_used_size;

}
