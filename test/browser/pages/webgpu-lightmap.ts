import * as THREE from 'three/webgpu';
import { ivec2, screenCoordinate, textureLoad, vec3, vec4 } from 'three/tsl';
import { LightMapper } from 'three/addons/lighting/LightMapper.js';
// The webgpu subpath by file, as webgpu-shading.ts does.
import { LightProbeVolume, placeGrid, ProbeVolumeIrradiance } from '../../../src/webgpu.js';

// ProbeVolumeIrradiance evaluated on the GPU against the CPU, on either WebGPURenderer backend:
// test/browser/webgpuLightMapExact.test.ts calls window.lightmap.* and asserts on the numbers.
//
// The field: every probe's SH is affine in its position, sh_k( p ) = A_k + B_k · p. Barycentric
// (and trilinear) weights reproduce an affine function exactly, so volume.sample() gives the same
// affine field anywhere inside the probes' box; the resampling texture stores it at its nodes
// and its trilinear filter reproduces an affine function exactly between them. So at any point of
// the box the GPU must return E( n ) of sh( p ) — no resampling error, only the texels' precision
// and the filter's weight precision.

/** The probes' box: the grid spans it, and so does the resampling texture. */
const MIN = [ - 2, 0, - 1.5 ], MAX = [ 2, 3, 1.5 ];
const INTENSITY = 1.5;

/** A_k: sky-like, every band and channel non-zero. */
const A = [
	1.2, 1.1, 0.95, 0.35, 0.4, 0.55, 0.22, 0.08, - 0.12, - 0.3, 0.12, 0.25, 0.12, - 0.07, 0.06,
	0.07, 0.12, - 0.06, - 0.12, 0.06, 0.12, 0.1, - 0.08, 0.05, 0.15, 0.02, - 0.1,
];

/** B_k per axis: gentle slopes (≤ 0.06 per metre) so one texel changes E by ≲ 10 %. */
function slope( k: number, axis: number ): number {

	return 0.06 * Math.sin( 1.7 * k + 2.3 * axis + 0.4 );

}

/** The analytic field at p (27 floats). */
function fieldSH( x: number, y: number, z: number ): number[] {

	const out: number[] = [];
	for ( let k = 0; k < 27; k ++ ) out.push( A[ k ] + slope( k, 0 ) * x + slope( k, 1 ) * y + slope( k, 2 ) * z );
	return out;

}

function irradiance( sh: ArrayLike<number>, n: number[] ): number[] {

	const normal = new THREE.Vector3( n[ 0 ], n[ 1 ], n[ 2 ] );
	const e = new THREE.SphericalHarmonics3().fromArray( Array.from( sh ) ).getIrradianceAt( normal, new THREE.Vector3() );
	return [ e.x * INTENSITY, e.y * INTENSITY, e.z * INTENSITY ];

}

/** A seeded generator, so every run tests the same points. */
function random( seed: number ): () => number {

	let s = seed >>> 0;
	return () => {

		s = ( s * 1664525 + 1013904223 ) >>> 0;
		return s / 4294967296;

	};

}

interface Setup { renderer: THREE.WebGPURenderer; volume: LightProbeVolume; source: ProbeVolumeIrradiance }

async function setup( backend: 'webgpu' | 'webgl2', type: 'half' | 'float' ): Promise<Setup> {

	const renderer = new THREE.WebGPURenderer( { forceWebGL: backend === 'webgl2' } );
	await renderer.init();
	const volume = new LightProbeVolume( { positions: placeGrid( MIN, MAX, [ 3, 4, 3 ] ) } );
	const p = volume.positions;
	for ( let i = 0; i < volume.count; i ++ ) volume.sh.set( fieldSH( p[ 3 * i ], p[ 3 * i + 1 ], p[ 3 * i + 2 ] ), 27 * i );
	const bounds = new THREE.Box3( new THREE.Vector3( ...MIN ), new THREE.Vector3( ...MAX ) );
	// Node counts differ per axis, so a swapped axis in the lookup shows.
	const source = new ProbeVolumeIrradiance( renderer, volume, { bounds, resolution: [ 6, 5, 4 ], type, intensity: INTENSITY } );
	return { renderer, volume, source };

}

/** One row of float texels holding `values` (xyz per texel). */
function row( values: number[][] ): THREE.DataTexture {

	const data = new Float32Array( 4 * values.length );
	values.forEach( ( v, i ) => data.set( [ v[ 0 ], v[ 1 ], v[ 2 ], 1 ], 4 * i ) );
	const texture = new THREE.DataTexture( data, values.length, 1, THREE.RGBAFormat, THREE.FloatType );
	texture.needsUpdate = true;
	return texture;

}

/** The points: random ones inside the box, the box's corners and grid nodes, outside ones, odd normals. */
function points(): { positions: number[][]; normals: number[][]; kinds: string[] } {

	const next = random( 7 ), positions: number[][] = [], normals: number[][] = [], kinds: string[] = [];
	const unit = () => {

		const z = 2 * next() - 1, a = 2 * Math.PI * next(), r = Math.sqrt( 1 - z * z );
		return [ r * Math.cos( a ), r * Math.sin( a ), z ];

	};

	for ( let i = 0; i < 40; i ++ ) {

		positions.push( [ 0, 1, 2 ].map( ( a ) => MIN[ a ] + ( MAX[ a ] - MIN[ a ] ) * next() ) );
		normals.push( unit() );
		kinds.push( 'inside' );

	}

	for ( const c of [ [ 0, 0, 0 ], [ 1, 1, 1 ], [ 1, 0, 1 ], [ 0, 1, 0 ] ] ) {

		positions.push( c.map( ( t, a ) => MIN[ a ] + ( MAX[ a ] - MIN[ a ] ) * t ) );
		normals.push( unit() );
		kinds.push( 'corner' );

	}

	for ( const q of [ [ - 3.5, 1.2, 0.3 ], [ 0.5, 4.5, - 0.2 ], [ 2.8, - 1, 2.6 ], [ - 0.4, 1.1, - 4 ] ] ) {

		positions.push( q );
		normals.push( unit() );
		kinds.push( 'outside' );

	}

	for ( let i = 0; i < 2; i ++ ) {

		positions.push( [ 0.3 - i, 1.4 + i, 0.2 ] );
		normals.push( [ 0, 0, 0 ] );
		kinds.push( 'zero normal' );

	}

	return { positions, normals, kinds };

}

/**
 * `source.irradiance( position, normal )` drawn for every point as one fragment of a float row
 * (the fragment reads its point from float textures), next to the CPU's values: `volume` — E( n )
 * by three's SphericalHarmonics3.getIrradianceAt of volume.sample( q ), `field` — of the analytic
 * field at q, where q is the point clamped to the box (the documented behaviour outside it).
 */
async function exact( backend: 'webgpu' | 'webgl2', type: 'half' | 'float' ) {

	const { renderer, volume, source } = await setup( backend, type );
	const { positions, normals, kinds } = points();
	const count = positions.length;
	const at = ivec2( screenCoordinate.xy );
	const position = textureLoad( row( positions ), at ).xyz, normal = textureLoad( row( normals ), at ).xyz;
	const material = new THREE.NodeMaterial();
	material.fragmentNode = vec4( source.irradiance( position, normal ), 1 );
	const target = new THREE.RenderTarget( count, 1, { type: THREE.FloatType, depthBuffer: false } );
	renderer.setRenderTarget( target );
	new THREE.QuadMesh( material ).render( renderer );
	renderer.setRenderTarget( null );
	const pixels = await renderer.readRenderTargetPixelsAsync( target, 0, 0, count, 1 ) as Float32Array;
	const rows = positions.map( ( p, i ) => {

		const q = p.map( ( v, a ) => Math.min( MAX[ a ], Math.max( MIN[ a ], v ) ) );
		return {
			kind: kinds[ i ], position: p, normal: normals[ i ],
			gpu: Array.from( pixels.subarray( 4 * i, 4 * i + 3 ) ),
			volume: irradiance( volume.sample( q ), normals[ i ] ),
			field: irradiance( fieldSH( q[ 0 ], q[ 1 ], q[ 2 ] ), normals[ i ] ),
			// E( n ) half a texel along x away: what an off-by-half-texel lookup would return.
			shifted: irradiance( fieldSH( q[ 0 ] + 0.5 * steps( source )[ 0 ], q[ 1 ], q[ 2 ] ), normals[ i ] ),
			...errorScales( normals[ i ], q, source ),
		};

	} );
	const backendName = ( renderer.backend as { isWebGPUBackend?: boolean } ).isWebGPUBackend === true ? 'webgpu' : 'webgl2';
	source.dispose();
	target.dispose();
	renderer.dispose();
	return { backend: backendName, rows };

}

/** World distance between grid nodes per axis. */
function steps( source: ProbeVolumeIrradiance ): number[] {

	const { min, max, resolution } = source.volumeTexture;
	return [ 0, 1, 2 ].map( ( a ) => ( max.getComponent( a ) - min.getComponent( a ) ) / ( resolution.getComponent( a ) - 1 ) );

}

/**
 * The scales of the GPU's errors at ( n, q ), per the field's own numbers: `perTexel`, the largest
 * change of E( n ) (any channel) over one texel step of any axis, Σ_k |basis_k( n ) · B_k| · step,
 * which the filter's weight precision multiplies; `gradient`, that per metre; `halfRounding`, per
 * channel, the most that rounding every coefficient of the nodes around q to half floats (2⁻¹¹
 * relative) changes E( n ), Σ_k |basis_k( n )| · ( |sh_k( q )| + one texel's change ) · 2⁻¹¹.
 */
function errorScales( n: number[], q: number[], source: ProbeVolumeIrradiance ) {

	const [ x, y, z ] = n, step = steps( source ), sh = fieldSH( q[ 0 ], q[ 1 ], q[ 2 ] );
	// |basis_k( n )|: getIrradianceAt's constants (2 · 0.511664, 2 · 0.429043, …).
	const basis = [
		0.886227, 1.023328 * Math.abs( y ), 1.023328 * Math.abs( z ), 1.023328 * Math.abs( x ),
		0.858086 * Math.abs( x * y ), 0.858086 * Math.abs( y * z ), Math.abs( 0.743125 * z * z - 0.247708 ),
		0.858086 * Math.abs( x * z ), 0.429043 * Math.abs( x * x - y * y ),
	];
	let perTexel = 0, gradient = 0;
	const halfRounding = [ 0, 0, 0 ];
	for ( let c = 0; c < 3; c ++ ) {

		for ( let a = 0; a < 3; a ++ ) {

			let sum = 0;
			for ( let i = 0; i < 9; i ++ ) sum += basis[ i ] * Math.abs( slope( 3 * i + c, a ) );
			perTexel = Math.max( perTexel, sum * step[ a ] * INTENSITY );
			gradient = Math.max( gradient, sum * INTENSITY );

		}

		for ( let i = 0; i < 9; i ++ ) {

			const texel = [ 0, 1, 2 ].reduce( ( s, a ) => s + Math.abs( slope( 3 * i + c, a ) ) * step[ a ], 0 );
			halfRounding[ c ] += basis[ i ] * ( Math.abs( sh[ 3 * i + c ] ) + texel ) * 2 ** - 11 * INTENSITY;

		}

	}

	return { perTexel, gradient, halfRounding };

}

/**
 * The light map of a flat quad baked by three's LightMapper from the source, and a second map of
 * the same quad baked from `position − centre` (the same rasterisation, jitter and padding fill):
 * each texel's CPU truth is E( n ) at the position the second map holds — exact for an affine
 * field, since the texel is a mean of samples and E is affine in position along the flat quad.
 */
async function lightMap( backend: 'webgpu' | 'webgl2', samples: number ) {

	const { renderer, volume, source } = await setup( backend, 'float' );
	const size = 32;
	const quad = new THREE.Mesh( new THREE.PlaneGeometry( 2, 1.5 ), new THREE.MeshBasicNodeMaterial() );
	quad.geometry.setAttribute( 'uv1', quad.geometry.getAttribute( 'uv' ).clone() );
	quad.position.set( 0.2, 1.5, 0.1 );
	quad.rotation.set( 0.3, - 0.5, 0.2 );
	quad.updateMatrixWorld();
	const centre = quad.position.clone();
	const normal = new THREE.Vector3( 0, 0, 1 ).transformDirection( quad.matrixWorld );
	const light = new LightMapper( renderer, size, source.irradiance );
	const where = new LightMapper( renderer, size, ( p: any ) => p.sub( vec3( centre ) ) );
	light.addObjects( [ quad ] );
	where.addObjects( [ quad ] );
	light.update( samples );
	where.update( samples );
	const read = async ( mapper: LightMapper ) => {

		const data = await renderer.readRenderTargetPixelsAsync( ( mapper as any )._renderTarget, 0, 0, size, size );
		return Array.from( data as ArrayLike<number>, ( v ) => data instanceof Uint16Array ? THREE.DataUtils.fromHalfFloat( v ) : v );

	};

	const [ baked, placed ] = [ await read( light ), await read( where ) ];
	const texels = [], inverse = quad.matrixWorld.clone().invert();
	for ( let i = 0; i < size * size; i ++ ) {

		const p = [ 0, 1, 2 ].map( ( a ) => placed[ 4 * i + a ] + centre.getComponent( a ) );
		const local = new THREE.Vector3( ...p ).applyMatrix4( inverse ).toArray();
		const cpu = irradiance( volume.sample( p ), normal.toArray() );
		texels.push( { position: p, local, gpu: baked.slice( 4 * i, 4 * i + 3 ), cpu } );

	}

	// The largest |∂E/∂p| (any channel, axis) for the quad's normal, and |p − centre| on the quad.
	const { gradient } = errorScales( normal.toArray(), centre.toArray(), source );
	const backendName = ( renderer.backend as { isWebGPUBackend?: boolean } ).isWebGPUBackend === true ? 'webgpu' : 'webgl2';
	light.dispose();
	where.dispose();
	source.dispose();
	renderer.dispose();
	return { backend: backendName, samples: light.samples, size, gradient, radius: Math.hypot( 1, 0.75 ), texels };

}

Object.assign( window, { lightmap: { exact, lightMap } } );
