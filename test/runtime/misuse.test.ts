/**
 * Every public entry point of the runtime, capture, codec and glTF modules called with a wrong
 * argument, table-driven: each call must throw (or reject with) an Error whose message starts with
 * the API's name and says what was wrong — never a TypeError from inside three.js or JavaScript
 * ("Cannot read properties of null", "… is not a function") — and the volume must be exactly as it
 * was before the call (positions, SH, names, roles, dirty set, capture settings, registered objects,
 * the spare mesh's material and attributes). No GPU: every check runs before anything is rendered,
 * so a stand-in renderer is enough (a check that let a bad argument through would crash on it).
 */

import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { LightProbeVolumeExporter } from '../../src/runtime/LightProbeVolumeExporter.js';
import { LightProbeVolumeLoader } from '../../src/runtime/LightProbeVolumeLoader.js';
import { captureBounces } from '../../src/runtime/captureBounces.js';
import { VisibilityGuard } from '../../src/runtime/VisibilityGuard.js';
import { getProbeVolumeUniforms, patchMaterial, unpatchMaterial } from '../../src/runtime/patchMaterial.js';
import { ProbeVertexLighting } from '../../src/runtime/ProbeVertexLighting.js';
import { ProbeTextureLighting } from '../../src/runtime/ProbeTextureLighting.js';
import { ProbeVolumeTexture } from '../../src/runtime/ProbeVolumeTexture.js';
import { toLightProbeGrid } from '../../src/runtime/toLightProbeGrid.js';
import { ProbeCapturer } from '../../src/capture/ProbeCapturer.js';
import { SHProjector } from '../../src/capture/SHProjector.js';
import { projectEquirectToSHGPU } from '../../src/capture/projectEquirectToSHGPU.js';
import {
	bakedVolumeFromJSON, bakedVolumeToJSON, crc32, decodeBakedVolume, encodeBakedVolume, fromFloat16Bits, toFloat16Bits,
	validateBakedVolume,
} from '../../src/io/index.js';
import { GLTFLightProbeVolumeExporterPlugin } from '../../src/gltf/GLTFLightProbeVolumeExporterPlugin.js';
import { GLTFLightProbeVolumeLoaderPlugin } from '../../src/gltf/GLTFLightProbeVolumeLoaderPlugin.js';
import type { GLTFParser } from 'three/examples/jsm/loaders/GLTFLoader.js';
import type { GLTFWriter } from 'three/examples/jsm/exporters/GLTFExporter.js';

/** A 4 × 3 × 3 grid of probes (36), SH a smooth function of the index. */
function probes(): { positions: number[]; sh: Float32Array } {

	const positions: number[] = [];
	for ( let x = 0; x < 4; x ++ ) for ( let y = 0; y < 3; y ++ ) for ( let z = 0; z < 3; z ++ ) {

		positions.push( x, y + 0.01 * x, z + 0.02 * y );

	}

	const sh = new Float32Array( 9 * positions.length );
	for ( let i = 0; i < sh.length; i ++ ) sh[ i ] = 0.5 + 0.25 * Math.sin( 0.1 * i );
	return { positions, sh };

}

const { positions, sh } = probes();
const volume = new LightProbeVolume( { positions, sh, names: positions.filter( ( _, i ) => i % 3 === 0 ).map( ( _, i ) => `p${i}` ) } );
volume.captureSettings = { resolution: 16, near: 0.1, far: 50, type: 'half', solidAngle: 'exact' };
const lit = new THREE.Mesh( new THREE.SphereGeometry( 0.2 ), new THREE.MeshStandardMaterial() );
lit.position.set( 1.5, 1, 1 );
volume.add( lit );
volume.moveProbe( 5, [ 0.1, 1.6, 2.1 ] ); // one dirty probe
const spare = new THREE.Mesh( new THREE.BoxGeometry( 1, 1, 1 ), new THREE.MeshStandardMaterial() );
spare.position.set( 1, 1, 1 );
const spareMaterial = spare.material;
const scene = new THREE.Scene();
scene.add( spare );
const renderer = { isWebGLRenderer: true, getContext: () => ( { isContextLost: () => false } ) } as unknown as THREE.WebGLRenderer;
const target = new Float32Array( 27 );
const triangles = [ 0.5, - 1, - 1, 0.5, 5, - 1, 0.5, - 1, 5 ];
const guard = new VisibilityGuard( triangles );
const box = new THREE.Box3( new THREE.Vector3( 0, 0, 0 ), new THREE.Vector3( 3, 2, 2 ) );
const texture = new ProbeVolumeTexture( volume, box, { resolution: 4 } );
const panorama = Object.assign( new THREE.Texture(), { image: { width: 8, height: 4 } } );
const baked = () => ( { positions, sh } );
const json = JSON.stringify( bakedVolumeToJSON( baked() ) );
const writer = { processBuffer: () => 0, json: {}, byteOffset: 0, extensionsUsed: {} } as unknown as GLTFWriter;
const loader = new LightProbeVolumeLoader();
const exporter = new LightProbeVolumeExporter();

/** What a failed call must leave unchanged. */
function snapshot(): string {

	return JSON.stringify( {
		positions: Array.from( volume.positions ), sh: Array.from( volume.sh ), names: volume.names, roles: volume.roles,
		dirty: volume.dirtyProbes(), settings: volume.captureSettings, metadata: volume.metadata, count: volume.count,
		litUniforms: volume.getUniforms( lit ) !== null, spareLit: volume.getUniforms( spare ) !== null,
		spareMaterial: spare.material === spareMaterial, spareAttributes: Object.keys( spare.geometry.attributes ),
		spareProbePatched: getProbeVolumeUniforms( spareMaterial ) !== null, guard: volume.visibilityGuard === null,
		interpolator: volume.interpolator.constructor.name, cells: volume.interpolator.cellCount,
	} );

}

type Case = [ api: string, call: () => unknown ];

const p = [ 1, 1, 1 ];
const cases: Case[] = [
	// new LightProbeVolume
	[ 'LightProbeVolume', () => new LightProbeVolume( null as never ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( undefined as never ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions: 'abc' as never } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions: [ 0, 0 ] } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions: [] } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions: [ 0, 0, NaN ] } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions: [ 0, 0, 1e19, 1, 0, 0, 0, 1, 0, 0, 0, 1 ] } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions: [ 0, 0, '1' as never ] } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, sh: new Float32Array( 26 ) } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, sh: Array.from( sh, ( v, i ) => i === 3 ? 1e39 : v ) } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, sh: Float32Array.from( sh, ( v, i ) => i === 0 ? - 3.4e38 : v ) } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, sh: Float32Array.from( sh, ( v, i ) => i === 9 ? NaN : v ) } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, sh: 'x' as never } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, names: volume.names.map( ( _, i ) => i ) as never } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, names: 'a' as never } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, names: [ 'a' ] } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, names: volume.names.map( ( n, i ) => i ? n : '\uDC00' ) } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, roles: volume.roles.map( ( r, i ) => i ? r : 'sun' ) as never } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, roles: [ 'sky' ] } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, zones: {} as never } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, zones: [ { name: 'a', probes: [ 99 ] } ] } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, zones: [ { name: 'a', probes: [] } ] } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, zones: [ { name: 'a', probes: [ 0 ] }, { name: 'a', probes: [ 1 ] } ] } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, zones: [ { name: 'a', probes: [ 0 ], bounds: { min: 1, max: 2 } as never } ] } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, interpolator: {} as never } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, interpolator: new LightProbeVolume( { positions: positions.slice( 0, 15 ) } ).interpolator } ) ],
	[ 'VisibilityGuard', () => new LightProbeVolume( { positions, occluders: 5 as never } ) ],
	[ 'VisibilityGuard', () => new LightProbeVolume( { positions, occluders: triangles, guard: { blockedWeight: 2 } } ) ],
	[ 'LightProbeVolume', () => new LightProbeVolume( { positions, occluders: triangles, guard: 'x' as never } ) ],
	// sample
	[ 'LightProbeVolume.sample', () => volume.sample( null as never ) ],
	[ 'LightProbeVolume.sample', () => volume.sample( undefined as never ) ],
	[ 'LightProbeVolume.sample', () => volume.sample( 'abc' as never ) ],
	[ 'LightProbeVolume.sample', () => volume.sample( [ NaN, 0, 0 ] ) ],
	[ 'LightProbeVolume.sample', () => volume.sample( [ 1e19, 0, 0 ] ) ],
	[ 'LightProbeVolume.sample', () => volume.sample( { x: '1', y: 0, z: 0 } as never ) ],
	[ 'LightProbeVolume.sample', () => volume.sample( [ 1, 1 ] ) ],
	[ 'LightProbeVolume.sample', () => volume.sample( p, new Float32Array( 3 ) ) ],
	[ 'LightProbeVolume.sample', () => volume.sample( p, 'x' as never ) ],
	[ 'LightProbeVolume.sample', () => volume.sample( p, target, null as never ) ],
	[ 'LightProbeVolume.sample', () => volume.sample( p, target, { zone: 5 as never } ) ],
	[ 'LightProbeVolume.sample', () => volume.sample( p, target, { zone: 'kitchen' } ) ],
	// add, remove, getZone, getUniforms
	[ 'LightProbeVolume.add', () => volume.add( null as never ) ],
	[ 'LightProbeVolume.add', () => volume.add( {} as never ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, null as never ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, { intensity: NaN } ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, { intensity: '2' as never } ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, { mode: 'bogus' as never } ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, { anchor: 5 as never } ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, { anchor: { x: NaN, y: 0, z: 0 } } ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, { perVertex: 'yes' as never } ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, { zone: 'hall' } ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, { mode: 'vertex', vertexOutput: 'rgb' as never } ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, { mode: 'texture', texelSize: - 1 } ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, { mode: 'texture', maxResolution: 1.5 } ) ],
	[ 'LightProbeVolume.add', () => volume.add( spare, { hideInCaptures: 1 as never } ) ],
	[ 'LightProbeVolume.remove', () => volume.remove( null as never ) ],
	[ 'LightProbeVolume.getZone', () => volume.getZone( null as never ) ],
	[ 'LightProbeVolume.getUniforms', () => volume.getUniforms( 5 as never ) ],
	// occluders
	[ 'VisibilityGuard', () => volume.setOccluders( 5 as never ) ],
	[ 'VisibilityGuard', () => volume.setOccluders( 'x' as never ) ],
	[ 'LightProbeVolume.setOccluders', () => volume.setOccluders( triangles, 'x' as never ) ],
	[ 'VisibilityGuard', () => volume.setOccluders( triangles, { blockedWeight: - 1 } ) ],
	[ 'LightProbeVolume.findLeakingTetrahedra', () => volume.findLeakingTetrahedra() ],
	// edits
	[ 'LightProbeVolume.moveProbe', () => volume.moveProbe( 99, p ) ],
	[ 'LightProbeVolume.moveProbe', () => volume.moveProbe( 0, null as never ) ],
	[ 'LightProbeVolume.moveProbe', () => volume.moveProbe( '0' as never, p ) ],
	[ 'LightProbeVolume.moveProbe', () => volume.moveProbe( 0, [ NaN, 0, 0 ] ) ],
	[ 'LightProbeVolume.moveProbe', () => volume.moveProbe( 0, [ 1e19, 0, 0 ] ) ],
	[ 'LightProbeVolume.addProbe', () => volume.addProbe( null as never ) ],
	[ 'LightProbeVolume.addProbe', () => volume.addProbe( p, null as never ) ],
	[ 'LightProbeVolume.addProbe', () => volume.addProbe( p, { name: 5 as never } ) ],
	[ 'LightProbeVolume.addProbe', () => volume.addProbe( p, { name: '\uD800x' } ) ],
	[ 'LightProbeVolume.addProbe', () => volume.addProbe( p, { role: 'sun' as never } ) ],
	[ 'LightProbeVolume.addProbe', () => volume.addProbe( p, { sh: new Float32Array( 26 ) } ) ],
	[ 'LightProbeVolume.addProbe', () => volume.addProbe( p, { sh: new Float32Array( 27 ).fill( 3.4e38 ) } ) ],
	[ 'LightProbeVolume.removeProbe', () => volume.removeProbe( - 1 ) ],
	[ 'LightProbeVolume.removeProbe', () => volume.removeProbe( 1.5 ) ],
	// baked form
	[ 'LightProbeVolumeExporter.parse', () => exporter.parse( volume, null as never ) ],
	[ 'LightProbeVolumeExporter.parse', () => exporter.parse( volume, { precision: 'float8' as never } ) ],
	[ 'LightProbeVolumeExporter.parse', () => exporter.parse( null as never ) ],
	[ 'LightProbeVolumeExporter.parse', () => exporter.parse( volume, { binary: false, precision: 'float16' as never } ) ],
	[ 'LightProbeVolumeExporter.parse', () => exporter.parseAsync( volume, { binary: 1 as never } ) ],
	[ 'LightProbeVolumeLoader.parse', () => loader.parse( json, 'params' as never ) ],
	[ 'LightProbeVolumeLoader.parse', () => loader.parse( json, { positions } as never ) ],
	[ 'LightProbeVolumeLoader.parse', () => loader.parse( '{"format": ' ) ],
	[ 'LightProbeVolumeLoader.parse', () => loader.parse( [ 5 ] as never ) ],
	[ 'LightProbeVolumeLoader.parse', () => loader.parse( 5 as never ) ],
	[ 'LightProbeVolumeLoader.parse', () => loader.parse( new ArrayBuffer( 10 ) ) ],
	[ 'LightProbeVolumeLoader.parse', () => loader.parse( new TextEncoder().encode( '<!doctype html>' ) ) ],
	[ 'LightProbeVolumeLoader.setParameters', () => loader.setParameters( 'x' as never ) ],
	[ 'LightProbeVolumeLoader.load', () => loader.load( 5 as never, () => {} ) ],
	[ 'LightProbeVolumeLoader.load', () => loader.loadAsync( 'volume.lpv', 'x' as never ) ],
	[ 'LightProbeVolume.fromBakedData', () => LightProbeVolume.fromBakedData( null as never ) ],
	[ 'LightProbeVolume.fromBakedData', () => LightProbeVolume.fromBakedData( { positions } as never ) ],
	[ 'LightProbeVolume.fromBakedData', () => {

		const data = decodeBakedVolume( exporter.parse( volume ) );
		data.tetrahedra[ 5 ] = 1000;
		return LightProbeVolume.fromBakedData( data );

	} ],
	// capture (checked before anything is rendered)
	[ 'LightProbeVolume.capture', () => volume.capture( null as never, scene ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, null as never ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, null as never ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { resolution: NaN } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { indices: [], resolution: NaN } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { solidAngle: 'bogus' as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { solidAngle: 'EXACT' as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { near: 0 } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { far: - 1 } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { type: 1234 as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { indices: [ 99 ] } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { indices: 'abc' as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { indices: [ 0.5 ] } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { exclude: 5 as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { exclude: [ 5 ] as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { filter: 'x' as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { layers: 3 as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { onProgress: 1 as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { roles: { sun: {} } as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { roles: { sky: { far: 'x' as never } } } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { roles: { sky: 5 as never } } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { roles: { sky: { layers: {} as never } } } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { deringing: 2 } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { deringing: 'x' as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { nonNegative: 'yes' as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { bounces: - 1 } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { bounces: 1, output: 'x' as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { bounces: 1, onPass: 5 as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { bounces: 1, staticMeshes: 5 as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( renderer, scene, { bounces: 1, hideInBounces: 5 as never } ) ],
	[ 'LightProbeVolume.capture', () => volume.capture( null as never, scene, { bounces: 1 } ) ],
	[ 'LightProbeVolume.recaptureDirty', () => volume.recaptureDirty( null as never, scene ) ],
	[ 'LightProbeVolume.recaptureDirty', () => volume.recaptureDirty( renderer, scene, { indices: [ 0 ] } as never ) ],
	[ 'LightProbeVolume.recaptureDirty', () => volume.recaptureDirty( renderer, scene, { resolution: 0 } ) ],
	[ 'captureBounces', () => captureBounces( {} as never, renderer, scene, { bounces: 1 } ) ],
	[ 'captureBounces', () => captureBounces( volume, renderer, scene, null as never ) ],
	[ 'captureBounces', () => captureBounces( volume, renderer, scene, { bounces: 1, solidAngle: 'bogus' as never } ) ],
	// capture classes
	[ 'ProbeCapturer', () => new ProbeCapturer( null as never ) ],
	// WebGL-only classes refuse a WebGPURenderer by name (it would fail inside three.js otherwise).
	[ 'ProbeCapturer', () => new ProbeCapturer( { isWebGPURenderer: true } as never ) ],
	[ 'ProbeCapturer', () => new ProbeCapturer( renderer, { resolution: 0 } ) ],
	[ 'ProbeCapturer', () => new ProbeCapturer( renderer, { solidAngle: 'bogus' as never } ) ],
	[ 'ProbeCapturer', () => new ProbeCapturer( renderer, null as never ) ],
	[ 'SHProjector', () => new SHProjector( null as never ) ],
	[ 'SHProjector', () => new SHProjector( { isWebGPURenderer: true } as never ) ],
	[ 'SHProjector', () => new SHProjector( renderer, { multipleTargets: 'yes' as never } ) ],
	[ 'SHProjector.batchCapacity', () => SHProjector.batchCapacity( 0 ) ],
	[ 'SHProjector.supportsMultipleTargets', () => SHProjector.supportsMultipleTargets( null as never ) ],
	[ 'projectEquirectToSHGPU', () => projectEquirectToSHGPU( null as never, panorama ) ],
	[ 'projectEquirectToSHGPU', () => projectEquirectToSHGPU( renderer, null as never ) ],
	[ 'projectEquirectToSHGPU', () => projectEquirectToSHGPU( renderer, new THREE.CubeTexture() ) ],
	[ 'projectEquirectToSHGPU', () => projectEquirectToSHGPU( renderer, panorama, new Float32Array( 3 ) ) ],
	// materials
	[ 'patchMaterial', () => patchMaterial( null as never ) ],
	[ 'patchMaterial', () => patchMaterial( new THREE.MeshBasicMaterial() ) ],
	[ 'patchMaterial', () => patchMaterial( spareMaterial, null as never ) ],
	[ 'patchMaterial', () => patchMaterial( spareMaterial, { source: 'x' as never } ) ],
	[ 'patchMaterial', () => patchMaterial( spareMaterial, { perVertex: 'y' as never } ) ],
	[ 'patchMaterial', () => patchMaterial( spareMaterial, { intensity: NaN } ) ],
	[ 'patchMaterial', () => patchMaterial( spareMaterial, { uniforms: {} as never } ) ],
	[ 'unpatchMaterial', () => unpatchMaterial( null as never ) ],
	[ 'getProbeVolumeUniforms', () => getProbeVolumeUniforms( 5 as never ) ],
	// large objects
	[ 'ProbeVertexLighting', () => new ProbeVertexLighting( null as never, volume ) ],
	[ 'ProbeVertexLighting', () => new ProbeVertexLighting( spare, null as never ) ],
	[ 'ProbeVertexLighting', () => new ProbeVertexLighting( spare, volume, null as never ) ],
	[ 'ProbeVertexLighting', () => new ProbeVertexLighting( spare, volume, { output: 'x' as never } ) ],
	[ 'ProbeVertexLighting', () => new ProbeVertexLighting( spare, volume, { intensity: '1' as never } ) ],
	[ 'ProbeVertexLighting', () => new ProbeVertexLighting( spare, { interpolator: volume.interpolator, sh: new Float32Array( volume.sh ).fill( Infinity, 30, 31 ) } ) ],
	[ 'ProbeTextureLighting', () => new ProbeTextureLighting( null as never, volume ) ],
	[ 'ProbeTextureLighting', () => new ProbeTextureLighting( spare, volume, { padding: - 1 } ) ],
	[ 'ProbeTextureLighting', () => new ProbeTextureLighting( spare, volume, { maxResolution: 1 } ) ],
	[ 'ProbeTextureLighting', () => new ProbeTextureLighting( spare, volume, 5 as never ) ],
	[ 'ProbeVolumeTexture', () => new ProbeVolumeTexture( volume, null as never ) ],
	[ 'ProbeVolumeTexture', () => new ProbeVolumeTexture( volume, box, { resolution: null as never } ) ],
	[ 'ProbeVolumeTexture', () => new ProbeVolumeTexture( volume, box, { type: 'byte' as never } ) ],
	[ 'ProbeVolumeTexture', () => new ProbeVolumeTexture( { interpolator: volume.interpolator, sh: new Float32Array( volume.sh ).fill( 1e31, 0, 1 ) }, box ) ],
	[ 'ProbeVolumeTexture.nodePosition', () => texture.nodePosition( 0, 0, 0, {} as never ) ],
	[ 'ProbeVolumeTexture.nodePosition', () => texture.nodePosition( NaN, 0, 0 ) ],
	[ 'ProbeVolumeTexture.setBounds', () => texture.setBounds( null as never ) ],
	[ 'ProbeVolumeTexture.resample', () => texture.resample( 'yes' as never ) ],
	[ 'toLightProbeGrid', () => toLightProbeGrid( null as never ) ],
	[ 'toLightProbeGrid', () => toLightProbeGrid( texture, {} as never ) ],
	// visibility guard
	[ 'VisibilityGuard', () => new VisibilityGuard( 5 as never ) ],
	[ 'VisibilityGuard', () => new VisibilityGuard( triangles, null as never ) ],
	[ 'VisibilityGuard', () => new VisibilityGuard( triangles, { moveThreshold: - 1 } ) ],
	[ 'VisibilityGuard.segmentBlocked', () => guard.segmentBlocked( NaN, 0, 0, 1, 1, 1 ) ],
	[ 'VisibilityGuard.segmentBlocked', () => guard.segmentBlocked( '0' as never, 0, 0, 1, 1, 1 ) ],
	[ 'VisibilityGuard.filterWeights', () => guard.filterWeights( 0, 0, 0, positions, [ 99 ], new Float32Array( 4 ).fill( 0.25 ), 1 ) ],
	[ 'VisibilityGuard.filterWeights', () => guard.filterWeights( 0, 0, 0, positions, [ 0 ], null as never, 1 ) ],
	[ 'VisibilityGuard.applyMask', () => guard.applyMask( 1, null as never, 1 ) ],
	[ 'VisibilityGuard.applyMask', () => guard.applyMask( 1, [ 1 ], 40 ) ],
	[ 'VisibilityGuard.nearestVisible', () => guard.nearestVisible( 'x' as never, 0, 0, positions, null ) ],
	[ 'VisibilityGuard.nearestVisible', () => guard.nearestVisible( 0, 0, 0, null as never, null ) ],
	[ 'VisibilityGuard.findLeakingTetrahedra', () => guard.findLeakingTetrahedra( null as never, new Uint32Array( 4 ) ) ],
	[ 'VisibilityGuard.findLeakingTetrahedra', () => guard.findLeakingTetrahedra( positions, [ 0, 1, 2, 999 ] ) ],
	// codec
	[ 'encodeBakedVolume', () => encodeBakedVolume( null as never ) ],
	[ 'encodeBakedVolume', () => encodeBakedVolume( baked(), null as never ) ],
	[ 'encodeBakedVolume', () => encodeBakedVolume( { ...baked(), zones: [ { name: 'a', probes: [] } ] } ) ],
	[ 'encodeBakedVolume', () => encodeBakedVolume( { ...baked(), zones: [ { name: 'a', probes: [ 0 ] }, { name: 'a', probes: [ 1 ] } ] } ) ],
	[ 'encodeBakedVolume', () => encodeBakedVolume( { ...baked(), positions: positions.map( ( v, i ) => i === 4 ? 1e155 : v ) } ) ],
	[ 'encodeBakedVolume', () => encodeBakedVolume( { ...baked(), sh: Float32Array.from( sh, ( v, i ) => i === 0 ? 1e31 : v ) } ) ],
	[ 'encodeBakedVolume', () => encodeBakedVolume( { ...baked(), names: volume.names.map( ( _, i ) => i ) as never } ) ],
	[ 'decodeBakedVolume', () => decodeBakedVolume( null as never ) ],
	[ 'decodeBakedVolume', () => decodeBakedVolume( 'abc' as never ) ],
	[ 'bakedVolumeFromJSON', () => bakedVolumeFromJSON( '{"format": ' ) ],
	[ 'bakedVolumeFromJSON', () => bakedVolumeFromJSON( 5 ) ],
	[ 'bakedVolumeToJSON', () => bakedVolumeToJSON( null as never ) ],
	[ 'validateBakedVolume', () => validateBakedVolume( null as never ) ],
	[ 'crc32', () => crc32( null as never ) ],
	[ 'crc32', () => crc32( new Uint8Array( 8 ), 5, 2 ) ],
	[ 'toFloat16Bits', () => toFloat16Bits( '1' as never ) ],
	[ 'fromFloat16Bits', () => fromFloat16Bits( 70000 ) ],
	// glTF plugins
	[ 'GLTFLightProbeVolumeLoaderPlugin', () => new GLTFLightProbeVolumeLoaderPlugin( null as never ) ],
	[ 'GLTFLightProbeVolumeLoaderPlugin', () => new GLTFLightProbeVolumeLoaderPlugin( {} as GLTFParser ) ],
	[ 'GLTFLightProbeVolumeExporterPlugin', () => new GLTFLightProbeVolumeExporterPlugin( null as never, [] ) ],
	[ 'GLTFLightProbeVolumeExporterPlugin', () => new GLTFLightProbeVolumeExporterPlugin( writer, [ { name: 5 as never, data: baked() } ] ) ],
	[ 'GLTFLightProbeVolumeExporterPlugin', () => new GLTFLightProbeVolumeExporterPlugin( writer, null as never ) ],
	[ 'GLTFLightProbeVolumeExporterPlugin', () => new GLTFLightProbeVolumeExporterPlugin( writer, [], null as never ) ],
];

/** The error a call throws or its promise rejects with, or null when it succeeds. */
async function outcome( call: () => unknown ): Promise<unknown> {

	try {

		await call();
		return null;

	} catch ( error ) {

		return error;

	}

}

const INTERNAL = /Cannot read prop|Cannot set prop|is not a function|is not iterable|is not a constructor|undefined is not|null is not|Invalid array length/;

describe( `misuse: ${cases.length} wrong calls of the public API`, () => {

	it( 'the table holds at least 100 cases', () => {

		expect( cases.length ).toBeGreaterThanOrEqual( 100 );

	} );

	it.each( cases.map( ( [ api, call ], i ): [ string, string, () => unknown ] => [ `#${i}`, api, call ] ) )(
		'%s %s: throws an Error naming the API, and changes nothing',
		async ( _, api, call ) => {

			const before = snapshot();
			const error = await outcome( call );
			expect( error, 'the call must fail' ).toBeInstanceOf( Error );
			const message = ( error as Error ).message;
			expect( message.startsWith( `${api}: ` ), message ).toBe( true );
			expect( message ).not.toMatch( INTERNAL );
			expect( message.length, 'says what was wrong and what is expected' ).toBeGreaterThan( api.length + 20 );
			expect( snapshot() ).toBe( before );

		},
	);

} );
