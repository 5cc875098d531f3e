import * as THREE from 'three';
import type GUI from 'lil-gui';
import { irradianceMatrices, patchMaterial, type LightProbeVolume, type ProbeVolumeUniforms } from 'three-capture-lighting';
// Not exported from the package index yet: imported by path.
import { ProbeVertexLighting } from '../src/runtime/ProbeVertexLighting.js';
import { ProbeTextureLighting } from '../src/runtime/ProbeTextureLighting.js';
import { ProbeVolumeTexture } from '../src/runtime/ProbeVolumeTexture.js';
import { toLightProbeGrid } from '../src/runtime/toLightProbeGrid.js';
import { DemoApp } from './common/DemoApp.js';
import { buildSponza, sponzaLayouts, sponzaPath, SPONZA_CHARACTER_HEIGHT } from '@scenes/sponza.js';

// The paper's Sponza (Table 4: 432 grid probes vs 85 placed with meaning): an open-sky atrium.
// The sun lights half of the courtyard; the fox walks from the sun patch into the shade and under
// the arcades, lit by the four probes of the tetrahedron around it.

const app = new DemoApp( {
	layouts: sponzaLayouts,
	camera: { position: [ 4.3, 3.4, 1.0 ], target: [ - 4, 0.7, - 0.6 ] },
	path: sponzaPath,
	characterHeight: SPONZA_CHARACTER_HEIGHT,
	capture: { near: 0.05, far: 400 },
	build: buildSponza,
} );

// Large objects (issue 6): the courtyard floor is one 30 × 13 m mesh. Lit as one object it gets one
// colour from the probes at its centre; per vertex or through a 3D SH texture over its bounds it
// follows the probes across the courtyard. 'ambient (no probes)' is the scene as built (a flat
// emissive ambient); the probe modes replace that ambient by probe light. ?floor=<mode> selects one.
const FLOOR_MODES = [ 'ambient (no probes)', 'object', 'vertex', 'texture', 'three.js grid' ] as const;
type FloorMode = typeof FLOOR_MODES[ number ];
const QUERY_MODES: Record<string, FloorMode> = { off: 'ambient (no probes)', object: 'object', vertex: 'vertex', texture: 'texture', grid: 'three.js grid' };

/** DemoApp members this page needs that are not public yet (see the report of issue 6). */
interface DemoInternals { activeVolume: LightProbeVolume; gui: GUI | null }

class FloorLighting {

	mode: FloorMode;
	private readonly floor: THREE.Mesh;
	/** The floor's material as built (with the emissive ambient): shown in mode 'ambient' and to captures. */
	private readonly original: THREE.Material;
	/** The same without the ambient, for the probe modes. */
	private readonly probeLit: THREE.MeshStandardMaterial;
	private volume: LightProbeVolume | null = null;
	private applied: FloorMode | null = null;
	private vertex: ProbeVertexLighting | null = null;
	private texture: ProbeTextureLighting | null = null;
	private gridTexture: ProbeVolumeTexture | null = null;
	private grid: THREE.Object3D | null = null;
	private objectMaterial: THREE.MeshStandardMaterial | null = null;
	private objectUniforms: ProbeVolumeUniforms | null = null;
	private readonly centre = new THREE.Vector3();
	private readonly sh = new Float32Array( 27 );
	/** ms of the last recompute (vertex or texture), for the overlay and measurements. */
	lastUpdateMs = 0;

	constructor( floor: THREE.Mesh, mode: FloorMode ) {

		this.floor = floor;
		this.mode = mode;
		this.original = floor.material as THREE.Material;
		this.probeLit = ( this.original as THREE.MeshStandardMaterial ).clone();
		this.probeLit.emissive.setRGB( 0, 0, 0 );
		this.probeLit.emissiveMap = null;
		floor.geometry.computeBoundingBox();
		floor.geometry.boundingBox!.getCenter( this.centre ).applyMatrix4( floor.matrixWorld );

	}

	/**
	 * Called before every render: captures (rendering into a cube target) see the floor as built,
	 * so the probes do not feed back their own light; the main view sees the chosen mode.
	 */
	beforeRender( target: THREE.WebGLRenderTarget | null ): void {

		const capturing = target !== null;
		if ( capturing ) {

			this.floor.material = this.original;
			if ( this.grid ) this.grid.visible = false;
			return;

		}

		const volume = ( app as unknown as DemoInternals ).activeVolume;
		if ( volume !== this.volume || this.mode !== this.applied ) this.apply( volume );
		const start = performance.now();
		let changed = false;
		if ( this.vertex ) { this.floor.material = this.vertexMaterial!; changed = this.vertex.update(); }
		if ( this.texture ) { this.floor.material = this.textureMaterial!; changed = this.texture.update(); }
		if ( this.gridTexture ) { this.floor.material = this.probeLit; this.grid!.visible = true; changed = this.gridTexture.resample( false ); }
		if ( this.objectUniforms ) {

			this.floor.material = this.objectMaterial!;
			irradianceMatrices( volume.sample( this.centre, this.sh ), this.objectUniforms.probeVolumeMatrices.value );

		}

		if ( this.applied === 'ambient (no probes)' ) this.floor.material = this.original;
		if ( changed ) this.lastUpdateMs = performance.now() - start;
		const direct = app.params.view === 'indirect only' ? 0 : 1;
		for ( const uniforms of [ this.objectUniforms, this.vertex?.uniforms, this.texture?.uniforms ] ) if ( uniforms ) uniforms.probeVolumeDirectScale.value = direct;

	}

	private vertexMaterial: THREE.Material | THREE.Material[] | null = null;
	private textureMaterial: THREE.Material | THREE.Material[] | null = null;

	private apply( volume: LightProbeVolume ): void {

		this.clear();
		this.volume = volume;
		this.applied = this.mode;
		this.floor.material = this.probeLit;
		const start = performance.now();
		switch ( this.mode ) {

			case 'object':
				// What LightProbeVolume.add does, without registering the floor (registered objects are
				// hidden from captures, and the floor must stay in them).
				this.objectMaterial = this.probeLit.clone();
				this.objectUniforms = patchMaterial( this.objectMaterial );
				break;

			case 'vertex':
				// 'sh': the floor has a bump map, which per-vertex irradiance would ignore.
				this.vertex = new ProbeVertexLighting( this.floor, volume, { output: 'sh' } );
				this.vertexMaterial = this.floor.material;
				break;

			case 'texture':
				this.texture = new ProbeTextureLighting( this.floor, volume, { texelSize: 0.5 } );
				this.textureMaterial = this.floor.material;
				break;

			case 'three.js grid': {

				this.gridTexture = new ProbeVolumeTexture( volume, new THREE.Box3().setFromObject( this.floor ), { texelSize: 0.5 } );
				this.grid = toLightProbeGrid( this.gridTexture );
				app.scene.add( this.grid );
				break;

			}

			default:
				this.floor.material = this.original;

		}

		this.lastUpdateMs = performance.now() - start;

	}

	private clear(): void {

		this.floor.material = this.probeLit;
		this.vertex?.dispose();
		this.texture?.dispose();
		this.gridTexture?.dispose();
		if ( this.grid ) { app.scene.remove( this.grid ); ( this.grid as THREE.Light ).dispose(); }
		this.objectMaterial?.dispose();
		this.vertex = this.texture = this.gridTexture = this.grid = this.objectMaterial = this.objectUniforms = null;
		this.vertexMaterial = this.textureMaterial = null;

	}

}

// The fox walks in and out of the sun: once it is loaded, let it receive the sun's shadow.
app.start().then( () => {

	app.scene.traverse( ( object ) => { object.receiveShadow = true; } );
	let floor: THREE.Mesh | null = null;
	app.scene.traverse( ( object ) => { if ( object.name === 'floors' && ( object as THREE.Mesh ).isMesh ) floor = object as THREE.Mesh; } );
	if ( ! floor ) return;
	const lighting = new FloorLighting( floor, QUERY_MODES[ app.query.get( 'floor' ) ?? 'off' ] ?? 'ambient (no probes)' );
	// WebGLRenderer calls a scene's onBeforeRender with the current render target as 4th argument.
	app.scene.onBeforeRender = ( _renderer, _scene, _camera, target ) => lighting.beforeRender( target as unknown as THREE.WebGLRenderTarget | null );
	Object.assign( window, { __floorLighting: lighting } );
	const gui = ( app as unknown as DemoInternals ).gui;
	gui?.add( lighting, 'mode', FLOOR_MODES as unknown as string[] ).name( 'floor lighting' );

} );
