/**
 * Large objects, CPU side: per-vertex field sampling (ProbeVertexLighting) and the 3D SH texture
 * resample (ProbeVolumeTexture, toLightProbeGrid), against a field whose SH is a linear function of
 * position — tetrahedral interpolation reproduces it exactly inside the probes' hull, so every
 * vertex and every grid node has an analytic answer.
 */

import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { ProbeVertexLighting } from '../../src/runtime/ProbeVertexLighting.js';
import { ProbeVolumeTexture } from '../../src/runtime/ProbeVolumeTexture.js';
import { ProbeTextureLighting } from '../../src/runtime/ProbeTextureLighting.js';
import { toLightProbeGrid } from '../../src/runtime/toLightProbeGrid.js';
import { getProbeVolumeUniforms, patchMaterial } from '../../src/runtime/patchMaterial.js';
import { evaluateIrradiance } from '../../src/sh/index.js';

/** SH(p) = A + Bx·x + By·y + Bz·z, 27 floats each, every coefficient and channel different. */
const A = Array.from( { length: 27 }, ( _, k ) => ( k < 3 ? 1.5 : 0.2 * Math.sin( 1.7 * k ) ) );
const BX = Array.from( { length: 27 }, ( _, k ) => 0.03 * Math.cos( 0.9 * k + 0.3 ) );
const BY = Array.from( { length: 27 }, ( _, k ) => 0.05 * Math.sin( 1.3 * k + 0.1 ) );
const BZ = Array.from( { length: 27 }, ( _, k ) => 0.02 * Math.cos( 2.1 * k + 0.7 ) );

function linearSH( x: number, y: number, z: number, target = new Float64Array( 27 ) ): Float64Array {

	for ( let k = 0; k < 27; k ++ ) target[ k ] = A[ k ] + BX[ k ] * x + BY[ k ] * y + BZ[ k ] * z;
	return target;

}

/** Probes around [−12, 12] × [−4, 6] × [−12, 12]: the box's corners and irregular interior points. */
function linearVolume(): LightProbeVolume {

	const positions: number[] = [];
	for ( const x of [ - 12, 12 ] ) for ( const y of [ - 4, 6 ] ) for ( const z of [ - 12, 12 ] ) positions.push( x, y, z );
	for ( let i = 0; i < 30; i ++ ) positions.push( 10 * Math.sin( 3.1 * i + 1 ), 1 + 4 * Math.sin( 5.3 * i ), 10 * Math.cos( 2.3 * i + 0.5 ) );
	const sh = new Float32Array( 27 * positions.length / 3 );
	for ( let i = 0; i < positions.length / 3; i ++ ) sh.set( linearSH( positions[ 3 * i ], positions[ 3 * i + 1 ], positions[ 3 * i + 2 ] ), 27 * i );
	return new LightProbeVolume( { positions, sh } );

}

/** A tilted, moved, non-uniformly scaled sphere: every vertex has another position and normal. */
function sphereMesh( segments = 24 ): THREE.Mesh {

	const mesh = new THREE.Mesh( new THREE.SphereGeometry( 3, segments, segments / 2 ), new THREE.MeshStandardMaterial() );
	mesh.position.set( 2, 1, - 3 );
	mesh.rotation.set( 0.4, 1.1, - 0.3 );
	mesh.scale.set( 1.5, 0.8, 1.2 );
	mesh.updateMatrixWorld();
	return mesh;

}

describe( 'ProbeVertexLighting: the field sampled at every vertex', () => {

	it( 'output "irradiance": each vertex holds E(world normal) of the analytic SH at its world position (float tolerance)', () => {

		const volume = linearVolume();
		const mesh = sphereMesh();
		const lighting = new ProbeVertexLighting( mesh, volume );
		const position = mesh.geometry.getAttribute( 'position' ), normal = mesh.geometry.getAttribute( 'normal' );
		const attribute = mesh.geometry.getAttribute( 'probeIrradiance' );
		expect( attribute.count ).toBe( position.count );
		const normalMatrix = new THREE.Matrix3().getNormalMatrix( mesh.matrixWorld );
		const p = new THREE.Vector3(), n = new THREE.Vector3();
		let worst = 0, spread = 0;
		for ( let i = 0; i < position.count; i ++ ) {

			p.fromBufferAttribute( position, i ).applyMatrix4( mesh.matrixWorld );
			n.fromBufferAttribute( normal, i ).applyMatrix3( normalMatrix ).normalize();
			const expected = evaluateIrradiance( linearSH( p.x, p.y, p.z ), n, new Float64Array( 3 ) );
			for ( let c = 0; c < 3; c ++ ) {

				worst = Math.max( worst, Math.abs( attribute.getComponent( i, c ) - expected[ c ] ) / Math.abs( expected[ c ] ) );
				spread = Math.max( spread, Math.abs( attribute.getComponent( i, c ) - attribute.getComponent( 0, c ) ) );

			}

		}

		expect( worst ).toBeLessThan( 1e-5 );
		expect( spread ).toBeGreaterThan( 0.1 ); // not one colour
		lighting.dispose();

	} );

	it( 'output "sh": each vertex holds the analytic SH (27 floats + 0) of its world position', () => {

		const volume = linearVolume();
		const mesh = sphereMesh();
		const lighting = new ProbeVertexLighting( mesh, volume, { output: 'sh' } );
		const position = mesh.geometry.getAttribute( 'position' );
		const p = new THREE.Vector3();
		let worst = 0;
		for ( let i = 0; i < position.count; i ++ ) {

			p.fromBufferAttribute( position, i ).applyMatrix4( mesh.matrixWorld );
			const expected = linearSH( p.x, p.y, p.z );
			for ( let k = 0; k < 27; k ++ ) worst = Math.max( worst, Math.abs( lighting.data[ 28 * i + k ] - expected[ k ] ) );
			expect( lighting.data[ 28 * i + 27 ] ).toBe( 0 );

		}

		expect( worst ).toBeLessThan( 2e-6 );
		// The 7 attributes read the interleaved buffer: attribute probeSH2 component 1 is float 9.
		expect( mesh.geometry.getAttribute( 'probeSH2' ).getComponent( 5, 1 ) ).toBe( lighting.data[ 28 * 5 + 9 ] );
		lighting.dispose();

	} );

	it( 'update() recomputes only when the mesh moved, its positions changed or the probe SH changed', () => {

		const volume = linearVolume();
		const mesh = sphereMesh( 8 );
		const lighting = new ProbeVertexLighting( mesh, volume );
		const before = lighting.data.slice();
		expect( lighting.update() ).toBe( false );
		mesh.position.x += 1;
		expect( lighting.update() ).toBe( true );
		expect( lighting.data ).not.toEqual( before );
		expect( lighting.update() ).toBe( false );
		volume.sh[ 0 ] += 1;
		expect( lighting.update() ).toBe( true );
		mesh.geometry.getAttribute( 'position' ).needsUpdate = true;
		expect( lighting.update() ).toBe( true );
		lighting.dispose();

	} );

	it( 'replaces Standard materials by patched clones and restores them; dispose removes the attributes', () => {

		const volume = linearVolume();
		const material = new THREE.MeshStandardMaterial();
		const basic = new THREE.MeshBasicMaterial();
		const mesh = new THREE.Mesh( new THREE.BoxGeometry(), [ material, basic ] );
		const lighting = new ProbeVertexLighting( mesh, volume, { output: 'sh', intensity: 0.5 } );
		const materials = mesh.material as THREE.Material[];
		expect( materials[ 0 ] ).not.toBe( material );
		expect( materials[ 1 ] ).toBe( basic );
		expect( getProbeVolumeUniforms( materials[ 0 ] )?.probeVolumeIntensity.value ).toBe( 0.5 );
		expect( getProbeVolumeUniforms( material ) ).toBeNull();
		lighting.dispose();
		expect( mesh.material ).toEqual( [ material, basic ] );
		expect( mesh.geometry.getAttribute( 'probeSH0' ) ).toBeUndefined();

	} );

	it( 'bad input: named errors', () => {

		const volume = linearVolume();
		const mesh = sphereMesh( 8 );
		expect( () => new ProbeVertexLighting( {} as THREE.Mesh, volume ) ).toThrow( /ProbeVertexLighting: mesh must be a three.js Mesh/ );
		expect( () => new ProbeVertexLighting( mesh, {} as LightProbeVolume ) ).toThrow( /ProbeVertexLighting: field.interpolator/ );
		expect( () => new ProbeVertexLighting( mesh, volume, { output: 'rgb' as 'sh' } ) ).toThrow( /options.output is "rgb"/ );
		expect( () => new ProbeVertexLighting( new THREE.SkinnedMesh( mesh.geometry, mesh.material ), volume ) ).toThrow( /skinned and instanced/ );
		expect( () => new ProbeVertexLighting( new THREE.Mesh( mesh.geometry, new THREE.MeshBasicMaterial() ), volume ) ).toThrow( /no MeshStandardMaterial/ );
		expect( mesh.geometry.getAttribute( 'probeIrradiance' ) ).toBeUndefined(); // the failed call left nothing behind
		const noNormals = new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( [ 0, 0, 0, 1, 0, 0, 0, 1, 0 ], 3 ) );
		expect( () => new ProbeVertexLighting( new THREE.Mesh( noNormals, new THREE.MeshStandardMaterial() ), volume ) ).toThrow( /needs a normal attribute/ );
		const first = new ProbeVertexLighting( mesh, volume );
		expect( () => new ProbeVertexLighting( new THREE.Mesh( mesh.geometry, new THREE.MeshStandardMaterial() ), volume ) ).toThrow( /already carries probe attributes/ );
		volume.sh[ 30 ] = NaN;
		expect( () => first.update() ).toThrow( /ProbeVertexLighting.update: field.sh\[30\] is NaN/ );
		first.dispose();
		expect( () => first.update() ).toThrow( /after dispose/ );

	} );

} );

describe( 'ProbeVolumeTexture: the field resampled on a grid, in three\'s LightProbeGrid atlas layout', () => {

	/** The 28 floats of node (ix, iy, iz) read back from the atlas, and a padding check. */
	function node( texture: ProbeVolumeTexture, ix: number, iy: number, iz: number, slice = 1 + iz ): number[] {

		const { x: nx, y: ny, z: nz } = texture.resolution;
		const data = ( texture.texture.image as { data: Uint16Array | Float32Array } ).data;
		const values: number[] = [];
		for ( let t = 0; t < 7; t ++ ) for ( let c = 0; c < 4; c ++ ) {

			const v = data[ 4 * ( ix + nx * ( iy + ny * ( t * ( nz + 2 ) + slice ) ) ) + c ];
			values.push( texture.type === 'half' ? THREE.DataUtils.fromHalfFloat( v ) : v );

		}

		return values;

	}

	it( 'float texels: every node equals volume.sample( node ) and the analytic SH; padding slices repeat the edge slices', () => {

		const volume = linearVolume();
		const texture = new ProbeVolumeTexture( volume, { min: { x: - 10, y: - 2, z: - 9 }, max: { x: 10, y: 4, z: 11 } }, { resolution: [ 9, 4, 6 ], type: 'float' } );
		expect( texture.resolution.toArray() ).toEqual( [ 9, 4, 6 ] );
		expect( texture.texture.image ).toMatchObject( { width: 9, height: 4, depth: 7 * 8 } );
		const p = new THREE.Vector3(), sampled = new Float32Array( 27 );
		let worstSample = 0, worstAnalytic = 0;
		for ( let iz = 0; iz < 6; iz ++ ) for ( let iy = 0; iy < 4; iy ++ ) for ( let ix = 0; ix < 9; ix ++ ) {

			texture.nodePosition( ix, iy, iz, p );
			volume.sample( p, sampled );
			const analytic = linearSH( p.x, p.y, p.z );
			const values = node( texture, ix, iy, iz );
			for ( let k = 0; k < 27; k ++ ) {

				worstSample = Math.max( worstSample, Math.abs( values[ k ] - sampled[ k ] ) );
				worstAnalytic = Math.max( worstAnalytic, Math.abs( values[ k ] - analytic[ k ] ) );

			}

			expect( values[ 27 ] ).toBe( 0 );

		}

		expect( worstSample ).toBeLessThan( 1e-6 );
		expect( worstAnalytic ).toBeLessThan( 2e-6 );
		expect( texture.nodePosition( 8, 3, 5 ).toArray() ).toEqual( [ 10, 4, 11 ] );
		expect( node( texture, 3, 2, 0, 0 ) ).toEqual( node( texture, 3, 2, 0 ) );
		expect( node( texture, 3, 2, 5, 7 ) ).toEqual( node( texture, 3, 2, 5 ) );
		texture.dispose();

	} );

	it( 'half texels (the default): nodes within half-float rounding (1e-3 relative) of volume.sample', () => {

		const volume = linearVolume();
		const texture = new ProbeVolumeTexture( volume, new THREE.Box3( new THREE.Vector3( - 8, 0, - 8 ), new THREE.Vector3( 8, 3, 8 ) ) );
		expect( texture.texture.type ).toBe( THREE.HalfFloatType );
		// Default texel: longest side / 31 → 32 nodes along x and z, 7 along y (3 / (16 / 31) + 1 = 6.8).
		expect( texture.resolution.toArray() ).toEqual( [ 32, 7, 32 ] );
		const p = new THREE.Vector3(), sampled = new Float32Array( 27 );
		let worst = 0;
		for ( const [ ix, iy, iz ] of [ [ 0, 0, 0 ], [ 31, 6, 31 ], [ 17, 3, 5 ], [ 4, 6, 29 ] ] ) {

			volume.sample( texture.nodePosition( ix, iy, iz, p ), sampled );
			const values = node( texture, ix, iy, iz );
			for ( let k = 0; k < 27; k ++ ) worst = Math.max( worst, Math.abs( values[ k ] - sampled[ k ] ) / Math.max( 0.1, Math.abs( sampled[ k ] ) ) );

		}

		expect( worst ).toBeLessThan( 1e-3 );
		texture.dispose();

	} );

	it( 'a flat box (a floor) gets one texel of thickness; counts clamp to 2..maxResolution', () => {

		const volume = linearVolume();
		const texture = new ProbeVolumeTexture( volume, { min: { x: - 10, y: 0.5, z: - 5 }, max: { x: 10, y: 0.5, z: 5 } }, { texelSize: 0.1, maxResolution: 40 } );
		expect( texture.resolution.toArray() ).toEqual( [ 40, 2, 40 ] );
		expect( texture.max.y - texture.min.y ).toBeCloseTo( 20 / 39, 6 );
		expect( ( texture.min.y + texture.max.y ) / 2 ).toBeCloseTo( 0.5, 9 );
		expect( texture.resample( false ) ).toBe( false ); // nothing changed
		volume.sh[ 3 ] += 0.5;
		expect( texture.resample( false ) ).toBe( true );
		texture.dispose();

	} );

	it( 'bad input: named errors', () => {

		const volume = linearVolume();
		const box = { min: { x: 0, y: 0, z: 0 }, max: { x: 1, y: 1, z: 1 } };
		expect( () => new ProbeVolumeTexture( volume, new THREE.Box3() ) ).toThrow( /ProbeVolumeTexture.setBounds: bounds must be .* empty Box3/ );
		expect( () => new ProbeVolumeTexture( volume, { min: box.max, max: box.min } ) ).toThrow( /min must not exceed/ );
		expect( () => new ProbeVolumeTexture( volume, { min: box.min, max: box.min } ) ).toThrow( /zero size/ );
		expect( () => new ProbeVolumeTexture( volume, box, { texelSize: - 1 } ) ).toThrow( /texelSize must be a positive/ );
		expect( () => new ProbeVolumeTexture( volume, box, { resolution: [ 4, NaN, 4 ] } ) ).toThrow( /options.resolution/ );
		expect( () => new ProbeVolumeTexture( volume, box, { type: 'byte' as 'half' } ) ).toThrow( /options.type is "byte"/ );
		expect( () => new ProbeVolumeTexture( { interpolator: volume.interpolator, sh: new Float32Array( 27 ) }, box ) ).toThrow( /field.sh has length 27, expected 27 × 38/ );
		volume.sh[ 0 ] = Infinity;
		expect( () => new ProbeVolumeTexture( volume, box ) ).toThrow( /ProbeVolumeTexture: field.sh\[0\] is Infinity; probe SH must be finite and within ±1\.00e\+30/ );

	} );

} );

describe( 'toLightProbeGrid: three\'s LightProbeGridWebGL over the same texture', () => {

	it( 'the grid\'s probes (cell centres) are the texture\'s nodes, and it shares the texture', () => {

		const volume = linearVolume();
		const texture = new ProbeVolumeTexture( volume, { min: { x: - 9, y: 0, z: - 7 }, max: { x: 11, y: 3, z: 8 } }, { resolution: [ 11, 4, 6 ] } );
		const grid = toLightProbeGrid( texture );
		expect( grid.texture ).toBe( texture.texture );
		expect( grid.resolution.toArray() ).toEqual( [ 11, 4, 6 ] );
		const a = new THREE.Vector3(), b = new THREE.Vector3();
		for ( const [ ix, iy, iz ] of [ [ 0, 0, 0 ], [ 10, 3, 5 ], [ 4, 1, 2 ] ] ) {

			grid.getProbePosition( ix, iy, iz, a );
			texture.nodePosition( ix, iy, iz, b );
			expect( a.distanceTo( b ) ).toBeLessThan( 1e-9 );

		}

		expect( grid.boundingBox.min.x ).toBeCloseTo( - 10, 9 );
		expect( grid.boundingBox.max.z ).toBeCloseTo( 9.5, 9 );
		expect( () => toLightProbeGrid( {} as ProbeVolumeTexture ) ).toThrow( /toLightProbeGrid: volumeTexture must be a ProbeVolumeTexture/ );
		texture.dispose();

	} );

} );

describe( 'ProbeTextureLighting', () => {

	it( 'covers the object\'s world bounds, resamples when it moves, restores materials on dispose', () => {

		const volume = linearVolume();
		const material = new THREE.MeshStandardMaterial();
		const floor = new THREE.Mesh( new THREE.PlaneGeometry( 16, 10 ).rotateX( - Math.PI / 2 ), material );
		floor.position.set( 1, 0.5, - 1 );
		const lighting = new ProbeTextureLighting( floor, volume, { texelSize: 1 } );
		const texture = lighting.volumeTexture;
		expect( texture.min.x ).toBeCloseTo( - 7, 9 );
		expect( texture.max.z ).toBeCloseTo( 4, 9 );
		expect( texture.resolution.toArray() ).toEqual( [ 17, 2, 11 ] );
		expect( floor.material ).not.toBe( material );
		expect( getProbeVolumeUniforms( floor.material as THREE.Material )?.probeVolumeSH?.value ).toBe( texture.texture );
		expect( lighting.update() ).toBe( false );
		floor.position.x += 2;
		expect( lighting.update() ).toBe( true );
		expect( texture.min.x ).toBeCloseTo( - 5, 9 );
		expect( () => new ProbeTextureLighting( new THREE.Group(), volume ) ).toThrow( /ProbeTextureLighting: the object has empty bounds/ );
		expect( () => new ProbeTextureLighting( floor, volume, { padding: - 1 } ) ).toThrow( /options.padding/ );
		lighting.dispose();
		expect( floor.material ).toBe( material );

	} );

} );

describe( 'patchMaterial: the large-object sources', () => {

	it( 'source \'texture\' makes its own texture uniforms; bad sources and combinations get named errors', () => {

		const uniforms = patchMaterial( new THREE.MeshStandardMaterial(), { source: 'texture' } );
		expect( uniforms.probeVolumeSH?.value ).toBeNull();
		expect( uniforms.probeVolumeGridResolution?.value.toArray() ).toEqual( [ 2, 2, 2 ] );
		expect( () => patchMaterial( new THREE.MeshStandardMaterial(), { source: 'lightmap' as 'texture' } ) ).toThrow( /patchMaterial: options.source is "lightmap"/ );
		expect( () => patchMaterial( new THREE.MeshStandardMaterial(), { source: 'vertexSH', perVertex: true } ) ).toThrow( /perVertex applies to source 'uniform' only/ );
		const plain = { probeVolumeMatrices: { value: new Float32Array( 48 ) }, probeVolumeIntensity: { value: 1 }, probeVolumeDirectScale: { value: 1 } };
		expect( () => patchMaterial( new THREE.MeshStandardMaterial(), { source: 'texture', uniforms: plain } ) ).toThrow( /source 'texture' needs options.uniforms with probeVolumeSH/ );

	} );

} );
