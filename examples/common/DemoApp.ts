import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { TransformControls } from 'three/addons/controls/TransformControls.js';
import Stats from 'three/addons/libs/stats.module.js';
import GUI from 'lil-gui';
import {
	GridInterpolator, LightProbeVolume, VisibilityGuard, captureBounces, createProbeInterpolator, evaluateIrradiance, irradianceMatrices,
	type AddOptions, type TetrahedralMesh,
} from 'three-capture-lighting';
import { loadCharacter, type Character } from './character.js';
import { Overlay } from './Overlay.js';
import type { ProbeLayout } from '@scenes/layout.js';

export type { ProbeLayout };

/** What a scene page gives the demo. */
export interface DemoOptions {

	layouts: ProbeLayout[];
	camera: { position: number[]; target: number[]; fov?: number; near?: number; far?: number };
	/** The character's walk, a closed loop. */
	path: THREE.Curve<THREE.Vector3>;
	/** Character height in scene units. */
	characterHeight: number;
	/** Cube camera planes for the captures. */
	capture: { near: number; far: number };
	/** Builds the static scene into `app.scene` (async: may load assets). */
	build( app: DemoApp ): Promise<void>;
	/** Seconds per loop of the path. Default 30. */
	loopSeconds?: number;

}

export type ViewMode = 'tetrahedral + diffuse' | 'indirect only' | 'direct + hemisphere';
const VIEWS: ViewMode[] = [ 'tetrahedral + diffuse', 'indirect only', 'direct + hemisphere' ];
const EDGES = [ [ 0, 1 ], [ 0, 2 ], [ 0, 3 ], [ 1, 2 ], [ 1, 3 ], [ 2, 3 ] ];

/** State a page leaves on `window.__demo` for tests and benchmarks. */
export interface DemoReport {

	ready: boolean;
	captureMs: number;
	probes: number;
	cells: number;
	/** CPU time of the last frames' work (update + render call), ms. */
	frameMs: number[];
	/** Time between the last frames (what the user sees, GPU included), ms. */
	intervalMs: number[];
	character: 'fox' | 'fallback' | 'none';
	/** With `?volume=`: ms to decode and validate the baked file into a volume (no capture). */
	loadMs?: number;
	/** With the visibility guard on: tetrahedra with an edge through static geometry. */
	leakingCells?: number;
	error: string;

}

/**
 * The frame shared by the paper's scene pages: renderer, camera and controls, a probe volume per
 * layout captured on the GPU, the character walking its loop with optional extra spheres, probe
 * markers shaded by their own SH, the tetrahedra as wireframe with the character's cell lit,
 * view modes, live probe editing, and a lil-gui panel.
 *
 * Query parameters: `assets` (asset URL, default /assets/), `layout`, `interpolation`, `view`,
 * `resolution`, `spheres` (extra probe-lit spheres), `t` (freeze time at t seconds), `hide=gui`
 * (no panel, no stats), `probes=0` (hide the probe markers), `drop=name,name` (leave out the
 * probes with these names, e.g. to see what one bleed probe contributes), `character=0`,
 * `ball=x,y,z` (a white probe-lit test ball there), `tonemapping=none`, `guard=1` (visibility
 * guard on), `zones=1` (the layout's lighting zones), `outside=nearest` (nearest-hull-point extrapolation instead of outer cells), `deringing=s` (window strength), `nonnegative=1`,
 * `bounces=n` (capture again n times with the static scene lit by the probes), `volume=URL` (a
 * baked volume file instead of a capture).
 */
export class DemoApp {

	readonly renderer: THREE.WebGLRenderer;
	readonly scene = new THREE.Scene();
	readonly camera: THREE.PerspectiveCamera;
	readonly controls: OrbitControls;
	readonly overlay = new Overlay();
	readonly query = new URLSearchParams( location.search );
	/** Base URL of the third-party assets. */
	readonly assets: string;
	/** Objects that must not appear in captures (markers, helpers, dynamic objects). */
	readonly helpers = new THREE.Group();
	readonly report: DemoReport = { ready: false, captureMs: 0, probes: 0, cells: 0, frameMs: [], intervalMs: [], character: 'none', leakingCells: 0, error: '' };

	readonly params = {
		layout: '',
		interpolation: 'tetrahedral' as 'tetrahedral' | 'trilinear',
		view: 'tetrahedral + diffuse' as ViewMode,
		resolution: 32,
		showProbes: true,
		showCells: false,
		animate: true,
		edit: false,
		/** Visibility guard: probes an object cannot see (through static geometry) do not light it. */
		guard: false,
		/** Lighting zones from the layout (when it has them): each its own tetrahedralization. */
		zones: false,
		/** Outside the probes' hull: outer cells (continuous fade-out) or the nearest hull point (the old rule). */
		outside: 'outer cells' as 'outer cells' | 'nearest face',
		/** De-ringing window strength applied to each captured probe (0 = none). */
		deringing: 0,
		/** Raise the de-ringing where needed so that no probe's irradiance is negative. */
		nonNegative: false,
		/** Diffuse bounces added by capturing again with the static scene lit by the probes. */
		bounces: 0,
	};

	private readonly options: DemoOptions;
	private layouts: ProbeLayout[];
	private volume!: LightProbeVolume;
	private trilinear: LightProbeVolume | null = null;
	private character: Character | null = null;
	private readonly spheres: THREE.Mesh[] = [];
	private readonly markers = new THREE.Group();
	private readonly wireframe = new THREE.LineSegments( new THREE.BufferGeometry(), new THREE.LineBasicMaterial( { color: 0xaaaaaa, transparent: true, opacity: 0.3 } ) );
	private readonly current = new THREE.LineSegments( new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( new Float32Array( 36 ), 3 ) ), new THREE.LineBasicMaterial( { color: 0xffff00 } ) );
	private readonly transform: TransformControls;
	private readonly stats = new Stats();
	private readonly timer = new THREE.Timer();
	private readonly hemisphere = new Float32Array( 48 );
	private ball: THREE.Mesh | null = null;
	/** Static scene objects lit by the probes (large-object modes), re-added to every new volume. */
	private readonly scenery = new Map<THREE.Object3D, AddOptions>();
	private selected = - 1;
	private time = 0;
	private fps = 0;
	private capturing = false;
	private guard: VisibilityGuard | null = null;
	/** The lil-gui panel (null with `hide=gui`): pages add their own controls to it. */
	gui: GUI | null = null;

	constructor( options: DemoOptions ) {

		this.options = options;
		this.layouts = options.layouts.map( ( layout ) => dropProbes( layout, ( this.query.get( 'drop' ) ?? '' ).split( ',' ).filter( Boolean ) ) );
		this.assets = this.query.get( 'assets' ) ?? '/assets/';
		this.params.layout = this.query.get( 'layout' ) ?? this.layouts[ 0 ].name;
		this.params.interpolation = this.query.get( 'interpolation' ) === 'trilinear' ? 'trilinear' : 'tetrahedral';
		this.params.view = ( VIEWS as string[] ).includes( this.query.get( 'view' ) ?? '' ) ? this.query.get( 'view' ) as ViewMode : 'tetrahedral + diffuse';
		this.params.resolution = Number( this.query.get( 'resolution' ) ?? 32 );
		this.params.showProbes = this.query.get( 'probes' ) !== '0';
		this.params.guard = this.query.get( 'guard' ) === '1';
		this.params.zones = this.query.get( 'zones' ) === '1';
		this.params.outside = this.query.get( 'outside' ) === 'nearest' ? 'nearest face' : 'outer cells';
		this.params.deringing = Number( this.query.get( 'deringing' ) ?? 0 );
		this.params.nonNegative = this.query.get( 'nonnegative' ) === '1';
		this.params.bounces = Number( this.query.get( 'bounces' ) ?? 0 );

		this.renderer = new THREE.WebGLRenderer( { antialias: true, preserveDrawingBuffer: true } );
		this.renderer.setPixelRatio( Math.min( window.devicePixelRatio, 2 ) );
		this.renderer.setSize( window.innerWidth, window.innerHeight );
		// Filmic tone mapping for viewing; ?tonemapping=none keeps colour ratios for measurements.
		this.renderer.toneMapping = this.query.get( 'tonemapping' ) === 'none' ? THREE.NoToneMapping : THREE.ACESFilmicToneMapping;
		document.body.appendChild( this.renderer.domElement );
		this.renderer.domElement.addEventListener( 'webglcontextlost', () => this.overlay.error( 'The WebGL context was lost; the probe SH are kept. Waiting for the browser to restore it…' ) );
		this.renderer.domElement.addEventListener( 'webglcontextrestored', () => this.overlay.error( '' ) );

		const { position, target, fov = 60, near = 0.05, far = 500 } = options.camera;
		this.camera = new THREE.PerspectiveCamera( fov, window.innerWidth / window.innerHeight, near, far );
		this.camera.position.fromArray( position );
		this.controls = new OrbitControls( this.camera, this.renderer.domElement );
		this.controls.target.fromArray( target );
		this.controls.update();

		this.transform = new TransformControls( this.camera, this.renderer.domElement );
		this.transform.addEventListener( 'dragging-changed', ( event ) => {

			this.controls.enabled = ! event.value;
			if ( ! event.value ) this.moveSelectedProbe();

		} );
		this.helpers.add( this.markers, this.wireframe, this.current, this.transform.getHelper() );
		this.scene.add( this.helpers );

		// A sky/ground hemisphere as SH, for the paper's "direct + hemisphere" comparison view.
		const hemisphereSH = new Float32Array( 27 );
		const sky = [ 0.6, 0.7, 0.9 ], ground = [ 0.3, 0.25, 0.2 ];
		for ( let c = 0; c < 3; c ++ ) {

			hemisphereSH[ c ] = ( sky[ c ] + ground[ c ] ) * Math.sqrt( Math.PI );
			hemisphereSH[ 3 + c ] = ( sky[ c ] - ground[ c ] ) * Math.sqrt( 3 * Math.PI ) / 2;

		}

		irradianceMatrices( hemisphereSH, this.hemisphere );
		if ( this.query.get( 'hide' ) !== 'gui' ) document.body.appendChild( this.stats.dom );
		else document.body.classList.add( 'no-ui' ); // screenshots for tests: no text that changes
		window.addEventListener( 'resize', () => this.resize() );
		window.addEventListener( 'error', ( event ) => this.fail( event.message ) );
		window.addEventListener( 'unhandledrejection', ( event ) => this.fail( String( event.reason?.message ?? event.reason ) ) );
		this.renderer.domElement.addEventListener( 'pointerdown', ( event ) => this.pick( event ) );
		Object.assign( window, { __demo: this.report, __demoApp: this } );

	}

	/** Builds the scene, loads the character, captures every probe and starts rendering. */
	async start(): Promise<void> {

		try {

			this.overlay.progress( 'loading the scene…', 0 );
			await this.options.build( this );
			if ( this.query.get( 'character' ) !== '0' ) await this.addCharacter();
			const spheres = Number( this.query.get( 'spheres' ) ?? 0 );
			for ( let i = 0; i < spheres; i ++ ) this.addSphere( i, spheres );
			const ball = this.query.get( 'ball' );
			if ( ball ) this.addBall( ball.split( ',' ).map( Number ) );
			const baked = this.query.get( 'volume' );
			if ( baked ) await this.loadBaked( baked );
			this.createGui();
			if ( ! baked ) {

				this.rebuildVolume();
				await this.recapture();

			}

			this.renderer.setAnimationLoop( ( timestamp ) => this.frame( timestamp ) );

		} catch ( error ) {

			this.fail( ( error as Error ).message );
			console.error( error );

		}

	}

	/** Shows an error on the page (not only in the console) and records it for tests. */
	fail( message: string ): void {

		this.report.error = message;
		this.overlay.error( message );

	}

	private async addCharacter(): Promise<void> {

		this.character = await loadCharacter( this.assets + 'fox/Fox.glb', this.options.characterHeight );
		this.report.character = this.character.kind;
		if ( this.character.kind === 'fallback' ) this.overlay.notice( `Character asset not found at ${this.assets}fox/Fox.glb — showing a stand-in. ${this.character.reason}` );
		this.scene.add( this.character.object );

	}

	private addSphere( i: number, count: number ): void {

		const material = new THREE.MeshStandardMaterial( { color: new THREE.Color().setHSL( i / count, 0.3, 0.7 ), roughness: 0.6 } );
		const sphere = new THREE.Mesh( new THREE.SphereGeometry( this.options.characterHeight * 0.25, 16, 8 ), material );
		sphere.userData.phase = i / count;
		this.spheres.push( sphere );
		this.scene.add( sphere );

	}

	/** A white, rough test ball that stays put: it shows the probe light at one point. */
	private addBall( position: number[] ): void {

		const ball = new THREE.Mesh( new THREE.SphereGeometry( this.options.characterHeight * 0.5, 48, 24 ), new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1 } ) );
		ball.position.fromArray( position );
		ball.name = 'test ball';
		this.ball = ball;
		this.scene.add( ball );

	}

	/** The test ball's box on screen in CSS pixels: [ left, top, right, bottom ] (for tests). */
	ballScreenBox(): number[] {

		return screenBox( this.ball ?? new THREE.Object3D(), this.camera, this.renderer.domElement );

	}

	private get dynamicObjects(): THREE.Object3D[] {

		return [ ...( this.character ? [ this.character.object ] : [] ), ...this.spheres, ...( this.ball ? [ this.ball ] : [] ) ];

	}

	private get layout(): ProbeLayout {

		return this.layouts.find( ( layout ) => layout.name === this.params.layout ) ?? this.layouts[ 0 ];

	}

	/**
	 * A baked volume instead of a capture (`?volume=URL`, a file from "export baked volume" or
	 * `capture-lighting bake`): its stored tetrahedralization is used as it is.
	 */
	private async loadBaked( url: string ): Promise<void> {

		this.overlay.progress( `loading ${url}…`, 0 );
		const response = await fetch( url );
		if ( ! response.ok ) throw new Error( `Baked volume not found: ${url} (HTTP ${response.status}).` );
		const buffer = await response.arrayBuffer();
		const start = performance.now();
		const volume = LightProbeVolume.fromArrayBuffer( buffer );
		this.report.loadMs = performance.now() - start;
		const layout: ProbeLayout = { name: `baked: ${url.split( /[/?#]/ ).filter( Boolean ).pop()}`, positions: Array.from( volume.positions ), names: volume.names.slice(), roles: volume.roles.slice() };
		this.layouts.push( layout );
		this.params.layout = layout.name;
		this.rebuildVolume( undefined, volume );
		this.overlay.progress( '', 1 );
		this.updateMarkers();

	}

	/** Downloads the current volume as a baked file (float16 SH), to load with `?volume=`. */
	private exportBaked(): void {

		const link = document.createElement( 'a' );
		link.href = URL.createObjectURL( new Blob( [ this.volume.toArrayBuffer( { precision: 'float16' } ) ], { type: 'application/octet-stream' } ) );
		link.download = `${this.layout.name.replace( /\W+/g, '-' )}.lpv`;
		link.click();
		URL.revokeObjectURL( link.href );

	}

	/**
	 * A new volume for the current layout, keeping the SH of probes that did not change (or
	 * `baked`, a volume loaded from a file, as it is).
	 */
	private rebuildVolume( sh?: Float32Array, baked?: LightProbeVolume ): void {

		const layout = this.layout;
		for ( const object of [ ...this.dynamicObjects, ...this.scenery.keys() ] ) { this.volume?.remove( object ); this.trilinear?.remove( object ); }
		const interpolator = createProbeInterpolator( layout.positions, { outside: this.params.outside === 'nearest face' ? 'nearestFace' : 'outerCells' } );
		const zones = this.params.zones ? layout.zones?.map( ( { name, probes, bounds: { min, max } } ) => ( { name, probes, bounds: { min: { x: min[ 0 ], y: min[ 1 ], z: min[ 2 ] }, max: { x: max[ 0 ], y: max[ 1 ], z: max[ 2 ] } } } ) ) : undefined;
		this.volume = baked ?? new LightProbeVolume( { positions: layout.positions, names: layout.names, roles: layout.roles, sh, interpolator, zones } );
		this.trilinear = null;
		if ( layout.grid ) {

			const grid = new GridInterpolator( layout.grid.min, layout.grid.max, layout.grid.counts );
			this.trilinear = new LightProbeVolume( { positions: grid.positions, interpolator: grid, sh: this.volume.sh } );

		}

		if ( this.params.interpolation === 'trilinear' && ! this.trilinear ) this.params.interpolation = 'tetrahedral';
		this.applyGuard();
		for ( const object of this.dynamicObjects ) this.activeVolume.add( object );
		for ( const [ object, options ] of this.scenery ) this.activeVolume.add( object, options );
		this.report.probes = this.volume.count;
		this.gui?.controllersRecursive().forEach( ( c ) => c.updateDisplay() );

	}

	/** Turns the visibility guard on or off on both volumes; its BVH of the static scene is built once. */
	private applyGuard(): void {

		if ( this.params.guard && ! this.guard ) {

			const dynamic = new Set<THREE.Object3D>( [ this.helpers, ...this.dynamicObjects ] );
			this.guard = new VisibilityGuard( this.scene.children.filter( ( object ) => ! dynamic.has( object ) ) );

		}

		const occluders = this.params.guard ? this.guard : null;
		this.volume.setOccluders( occluders );
		this.trilinear?.setOccluders( occluders );
		this.report.leakingCells = this.params.guard ? this.volume.findLeakingTetrahedra().length : 0;

	}

	/**
	 * Lights a static scene object with the probes (e.g. a floor per vertex or per pixel, see
	 * `AddOptions.mode`), in this and every later volume; `options = null` stops it.
	 */
	setScenery( object: THREE.Object3D, options: AddOptions | null ): void {

		this.volume.remove( object );
		this.trilinear?.remove( object );
		if ( options ) { this.scenery.set( object, options ); this.activeVolume.add( object, options ); } else this.scenery.delete( object );

	}

	/** The volume lighting the dynamic objects now (tetrahedral, or the trilinear baseline). */
	get activeVolume(): LightProbeVolume {

		return this.params.interpolation === 'trilinear' && this.trilinear ? this.trilinear : this.volume;

	}

	/** Captures all probes (or `indices`) at the current resolution, with a progress bar. */
	async recapture( indices?: number[] ): Promise<void> {

		if ( this.capturing ) return;
		this.capturing = true;
		const start = performance.now();
		try {

			const options = {
				resolution: this.params.resolution, near: this.options.capture.near, far: this.options.capture.far, indices,
				deringing: this.params.deringing, nonNegative: this.params.nonNegative,
				exclude: [ this.helpers, ...this.dynamicObjects ],
				onProgress: ( done: number, total: number ) => this.overlay.progress( `capturing ${done} / ${total} probes at ${this.params.resolution}²`, done / total ),
			};
			if ( this.params.bounces > 0 ) await this.captureWithBounces( options );
			else await this.volume.capture( this.renderer, this.scene, options );
			if ( this.trilinear ) this.trilinear.sh.set( this.volume.sh );
			this.report.captureMs = performance.now() - start;
			this.overlay.progress( '', 1 );
			this.updateMarkers();

		} finally {

			this.capturing = false;

		}

	}

	/**
	 * Direct light plus `params.bounces` bounces. The scenes' faint emissive stand-in for indirect
	 * light (loadOBJScene's `ambient`) is switched off meanwhile: the bounces replace it.
	 */
	private async captureWithBounces( options: Parameters<LightProbeVolume[ 'capture' ]>[ 2 ] ): Promise<void> {

		const standIns = new Map<THREE.MeshStandardMaterial, THREE.Color>();
		this.scene.traverse( ( object ) => {

			for ( const material of ( [] as THREE.Material[] ).concat( ( object as THREE.Mesh ).material ?? [] ) ) {

				if ( material.userData.ambientStandIn === true && ! standIns.has( material as THREE.MeshStandardMaterial ) ) standIns.set( material as THREE.MeshStandardMaterial, ( material as THREE.MeshStandardMaterial ).emissive.clone() );

			}

		} );
		for ( const material of standIns.keys() ) material.emissive.setRGB( 0, 0, 0 );
		try {

			await captureBounces( this.volume, this.renderer, this.scene, { ...options, bounces: this.params.bounces, onPass: ( pass ) => this.overlay.progress( `bounce pass ${pass} / ${this.params.bounces} done`, 1 ) } );

		} finally {

			for ( const [ material, emissive ] of standIns ) material.emissive.copy( emissive );

		}

	}

	private createGui(): void {

		if ( this.query.get( 'hide' ) === 'gui' ) return;
		const gui = this.gui = new GUI();
		const p = this.params;
		gui.add( p, 'layout', this.layouts.map( ( layout ) => layout.name ) ).onChange( () => { this.rebuildVolume(); this.recapture(); } );
		gui.add( p, 'interpolation', [ 'tetrahedral', 'trilinear' ] ).onChange( () => {

			if ( p.interpolation === 'trilinear' && ! this.trilinear ) {

				p.interpolation = 'tetrahedral';
				this.overlay.notice( 'Trilinear interpolation needs a grid layout.' );

			}

			this.rebuildVolume( this.volume.sh );

		} ).listen();
		gui.add( p, 'view', VIEWS );
		gui.add( p, 'resolution', [ 8, 16, 32, 64, 128 ] ).name( 'capture resolution' ).onChange( () => this.recapture() );
		gui.add( { recapture: () => this.recapture() }, 'recapture' );
		gui.add( p, 'showProbes' ).name( 'show probes' );
		gui.add( p, 'showCells' ).name( 'show tetrahedra' );
		gui.add( p, 'animate' );
		const beyond = gui.addFolder( 'beyond the paper' );
		beyond.add( p, 'outside', [ 'outer cells', 'nearest face' ] ).name( 'outside the hull' ).onChange( () => this.rebuildVolume( this.volume.sh ) );
		beyond.add( p, 'guard' ).name( 'no light through walls' ).onChange( () => this.applyGuard() );
		if ( this.layouts.some( ( layout ) => layout.zones ) ) beyond.add( p, 'zones' ).name( 'lighting zones' ).onChange( () => this.rebuildVolume( this.volume.sh ) );
		beyond.add( p, 'deringing', 0, 0.5, 0.01 ).name( 'de-ringing strength' ).onFinishChange( () => this.recapture() );
		beyond.add( p, 'nonNegative' ).name( 'irradiance never negative' ).onChange( () => this.recapture() );
		beyond.add( p, 'bounces', 0, 3, 1 ).name( 'diffuse bounces' ).onFinishChange( () => this.recapture() );
		const edit = gui.addFolder( 'edit probes' );
		edit.add( p, 'edit' ).name( 'click a probe to move it' ).onChange( () => this.select( - 1 ) );
		edit.add( { add: () => this.addProbe() }, 'add' ).name( 'add probe at target' );
		edit.add( { remove: () => this.removeSelectedProbe() }, 'remove' ).name( 'delete selected probe' );
		edit.add( { export: () => this.exportLayout() }, 'export' ).name( 'export layout JSON' );
		edit.add( { export: () => this.exportBaked() }, 'export' ).name( 'export baked volume (.lpv)' );

	}

	private updateMarkers(): void {

		for ( const marker of this.markers.children as THREE.Mesh[] ) { marker.geometry.dispose(); ( marker.material as THREE.Material ).dispose(); }
		this.markers.clear();
		const volume = this.volume;
		const radius = this.options.characterHeight * 0.12;
		const e = new Float32Array( 3 );
		for ( let i = 0; i < volume.count; i ++ ) {

			// A white diffuse ball lit by this probe alone: vertex colour E(n) / π, no other light.
			const geometry = new THREE.SphereGeometry( radius, 12, 6 );
			const normals = geometry.getAttribute( 'normal' );
			const colors = new Float32Array( 3 * normals.count );
			for ( let v = 0; v < normals.count; v ++ ) {

				evaluateIrradiance( volume.sh, [ normals.getX( v ), normals.getY( v ), normals.getZ( v ) ], e, 27 * i );
				colors.set( [ Math.max( 0, e[ 0 ] ) / Math.PI, Math.max( 0, e[ 1 ] ) / Math.PI, Math.max( 0, e[ 2 ] ) / Math.PI ], 3 * v );

			}

			geometry.setAttribute( 'color', new THREE.BufferAttribute( colors, 3 ) );
			const marker = new THREE.Mesh( geometry, new THREE.MeshBasicMaterial( { vertexColors: true } ) );
			marker.position.fromArray( volume.positions, 3 * i );
			marker.userData.probe = i;
			this.markers.add( marker );

		}

		const edges: number[] = [];
		const mesh = volume.interpolator as TetrahedralMesh;
		const cells = mesh.tetrahedra ?? ( volume.interpolator as unknown as { triangles: Uint32Array } ).triangles;
		const stride = mesh.tetrahedra ? 4 : 3;
		for ( let t = 0; t < cells.length / stride; t ++ ) {

			for ( const [ a, b ] of EDGES ) {

				if ( b >= stride ) continue;
				for ( const k of [ a, b ] ) edges.push( ...volume.positions.subarray( 3 * cells[ stride * t + k ], 3 * cells[ stride * t + k ] + 3 ) );

			}

		}

		this.wireframe.geometry.dispose();
		this.wireframe.geometry = new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( edges, 3 ) );
		this.report.cells = volume.interpolator.cellCount;

	}

	private frame( timestamp: number ): void {

		this.timer.update( timestamp );
		const delta = this.timer.getDelta();
		const frozen = this.query.get( 't' );
		this.time = frozen !== null ? Number( frozen ) : this.time + ( this.params.animate ? delta : 0 );
		const start = performance.now();

		this.moveDynamicObjects( delta );
		const volume = this.activeVolume;
		volume.update();
		for ( const object of [ ...this.dynamicObjects, ...this.scenery.keys() ] ) {

			const uniforms = volume.getUniforms( object );
			if ( ! uniforms ) continue;
			uniforms.probeVolumeDirectScale.value = this.params.view === 'indirect only' ? 0 : 1;
			if ( this.params.view === 'direct + hemisphere' ) uniforms.probeVolumeMatrices.value.set( this.hemisphere );

		}

		this.markers.visible = this.params.showProbes;
		this.wireframe.visible = this.current.visible = this.params.showCells;
		if ( this.params.showCells ) this.highlightCharacterCell();

		this.renderer.render( this.scene, this.camera );
		this.stats.update();
		this.report.frameMs.push( performance.now() - start );
		if ( this.report.frameMs.length > 300 ) this.report.frameMs.shift();
		if ( delta > 0 ) this.report.intervalMs.push( delta * 1000 );
		if ( this.report.intervalMs.length > 300 ) this.report.intervalMs.shift();
		if ( delta > 0 ) this.fps += ( 1 / delta - this.fps ) * 0.05;
		this.overlay.status( `${this.params.layout} — ${this.params.interpolation}\n${volume.count} probes, ${volume.interpolator.cellCount} ${this.params.interpolation === 'trilinear' ? 'boxes' : 'cells'}\ncapture ${this.report.captureMs.toFixed( 0 )} ms at ${this.params.resolution}²\n${this.fps.toFixed( 0 )} fps` );
		if ( ! this.report.ready && this.report.frameMs.length >= 5 ) this.report.ready = true;

	}

	private moveDynamicObjects( delta: number ): void {

		const path = this.options.path, loop = this.options.loopSeconds ?? 30;
		const u = ( ( this.time / loop ) % 1 + 1 ) % 1;
		if ( this.character ) {

			const object = this.character.object;
			path.getPointAt( u, object.position );
			const ahead = path.getPointAt( ( u + 0.001 ) % 1 );
			object.lookAt( ahead.x, object.position.y, ahead.z );
			// A frozen time (?t=) poses the character deterministically, for screenshots.
			if ( this.query.get( 't' ) !== null ) this.character.mixer?.setTime( this.time );
			else this.character.mixer?.update( this.params.animate ? delta : 0 );

		}

		const h = this.options.characterHeight;
		for ( const sphere of this.spheres ) {

			const phase = sphere.userData.phase as number;
			path.getPointAt( ( u + phase ) % 1, sphere.position );
			sphere.position.y += h * ( 0.8 + 0.5 * Math.sin( this.time * 2 + phase * 40 ) );
			sphere.position.x += h * Math.sin( phase * 97 );

		}

	}

	private highlightCharacterCell(): void {

		const mesh = this.volume.interpolator as TetrahedralMesh;
		const attribute = this.current.geometry.getAttribute( 'position' ) as THREE.BufferAttribute;
		const p = this.character?.object.position ?? new THREE.Vector3();
		const cell = mesh.locate ? mesh.locate( p.x, p.y + this.options.characterHeight * 0.5, p.z ) : - 1;
		let o = 0;
		for ( const [ a, b ] of EDGES ) {

			for ( const k of [ a, b ] ) {

				const v = cell >= 0 ? 3 * mesh.tetrahedra[ 4 * cell + k ] : 0;
				attribute.setXYZ( o ++, this.volume.positions[ v ], this.volume.positions[ v + 1 ], this.volume.positions[ v + 2 ] );

			}

		}

		attribute.needsUpdate = true;
		this.current.visible = cell >= 0;

	}

	/** Names of the page's probe layouts (for tests and benchmarks). */
	layoutNames(): string[] {

		return this.layouts.map( ( layout ) => layout.name );

	}

	/** The character's box on screen in CSS pixels: [ left, top, right, bottom ] (for tests). */
	characterScreenBox(): number[] {

		return screenBox( this.character?.object ?? new THREE.Object3D(), this.camera, this.renderer.domElement );

	}

	// Editing ----------------------------------------------------------------------------------

	private pick( event: PointerEvent ): void {

		if ( ! this.params.edit || this.transform.dragging ) return;
		const rect = this.renderer.domElement.getBoundingClientRect();
		const pointer = new THREE.Vector2( ( ( event.clientX - rect.left ) / rect.width ) * 2 - 1, - ( ( event.clientY - rect.top ) / rect.height ) * 2 + 1 );
		const raycaster = new THREE.Raycaster();
		raycaster.setFromCamera( pointer, this.camera );
		const hit = raycaster.intersectObjects( this.markers.children, false )[ 0 ];
		if ( hit ) this.select( hit.object.userData.probe as number );

	}

	private select( index: number ): void {

		this.selected = index;
		const marker = this.markers.children.find( ( m ) => m.userData.probe === index );
		if ( marker && this.params.edit ) this.transform.attach( marker ); else this.transform.detach();

	}

	/**
	 * Whether probe edits can update the volume in place (`moveProbe` / `addProbe`: the
	 * tetrahedralization changes locally, only the edited probe is captured again). A grid layout's
	 * first edit and volumes with zones are rebuilt instead.
	 */
	private get editsInPlace(): boolean {

		return ! this.layout.grid && ! this.volume.zones;

	}

	/** After a drag: the moved probe's cells are updated and the probe alone is captured again. */
	private async moveSelectedProbe(): Promise<void> {

		const index = this.selected;
		const marker = this.markers.children.find( ( m ) => m.userData.probe === index );
		if ( index < 0 || ! marker ) return;
		const positions = this.layout.positions, inPlace = this.editsInPlace;
		try {

			if ( inPlace ) this.volume.moveProbe( index, marker.position );
			const previous = positions.slice( 3 * index, 3 * index + 3 );
			marker.position.toArray( positions, 3 * index );
			if ( ! inPlace ) {

				delete this.layout.grid; // no longer a regular grid
				try { this.rebuildVolume( this.volume.sh.slice() ); } catch ( error ) { positions.splice( 3 * index, 3, ...previous ); this.rebuildVolume( this.volume.sh.slice() ); throw error; }

			}

		} catch ( error ) {

			this.overlay.notice( `Cannot move the probe there: ${( error as Error ).message}` );
			marker.position.fromArray( positions, 3 * index );
			return;

		}

		await this.recapture( [ index ] );
		this.select( index );

	}

	private async addProbe(): Promise<void> {

		const layout = this.layout, name = `probe ${layout.positions.length / 3 + 1}`, inPlace = this.editsInPlace;
		let index: number;
		if ( inPlace ) {

			index = this.volume.addProbe( this.controls.target, { name, role: 'fill' } );

		} else {

			const sh = new Float32Array( this.volume.sh.length + 27 );
			sh.set( this.volume.sh );
			delete layout.grid;
			layout.positions.push( ...this.controls.target.toArray() );
			layout.names?.push( name );
			layout.roles?.push( 'fill' );
			this.rebuildVolume( sh );
			index = this.volume.count - 1;

		}

		if ( inPlace ) { layout.positions.push( ...this.controls.target.toArray() ); layout.names?.push( name ); layout.roles?.push( 'fill' ); }
		await this.recapture( [ index ] );
		this.select( index );

	}

	private async removeSelectedProbe(): Promise<void> {

		const index = this.selected, layout = this.layout;
		if ( index < 0 ) { this.overlay.notice( 'Select a probe first (turn on editing and click one).' ); return; }
		this.select( - 1 );
		const sh = new Float32Array( this.volume.sh.length - 27 );
		sh.set( this.volume.sh.subarray( 0, 27 * index ) );
		sh.set( this.volume.sh.subarray( 27 * ( index + 1 ) ), 27 * index );
		const saved = layout.positions.splice( 3 * index, 3 );
		try {

			layout.names?.splice( index, 1 );
			layout.roles?.splice( index, 1 );
			delete layout.grid;
			delete layout.zones; // its probe indices shifted
			this.rebuildVolume( sh );
			this.updateMarkers();

		} catch ( error ) {

			layout.positions.splice( 3 * index, 0, ...saved );
			this.overlay.notice( `Cannot delete that probe: ${( error as Error ).message}` );

		}

	}

	private exportLayout(): void {

		const { name, positions, names, roles } = this.layout;
		const json = JSON.stringify( { name, positions: positions.map( ( v ) => Math.round( v * 1000 ) / 1000 ), names, roles }, null, '\t' );
		const link = document.createElement( 'a' );
		link.href = URL.createObjectURL( new Blob( [ json ], { type: 'application/json' } ) );
		link.download = `${name.replace( /\W+/g, '-' )}.json`;
		link.click();
		URL.revokeObjectURL( link.href );

	}

	private resize(): void {

		this.camera.aspect = window.innerWidth / window.innerHeight;
		this.camera.updateProjectionMatrix();
		this.renderer.setSize( window.innerWidth, window.innerHeight );

	}

}

/** A copy of the layout without the probes named in `names`. */
function dropProbes( layout: ProbeLayout, names: string[] ): ProbeLayout {

	const keep = ( _: unknown, i: number ) => ! names.includes( layout.names?.[ i ] ?? '' );
	const positions = layout.positions.filter( ( _, k ) => keep( null, Math.floor( k / 3 ) ) );
	if ( positions.length === layout.positions.length ) return { ...layout, positions: layout.positions.slice(), names: layout.names?.slice(), roles: layout.roles?.slice() };
	return { name: layout.name, positions, names: layout.names?.filter( keep ), roles: layout.roles?.filter( keep ) };

}

/** An object's bounding box projected to the canvas, in CSS pixels: [ left, top, right, bottom ]. */
function screenBox( object: THREE.Object3D, camera: THREE.Camera, canvas: HTMLCanvasElement ): number[] {

	const box = new THREE.Box3().setFromObject( object );
	const rect = canvas.getBoundingClientRect();
	let left = Infinity, top = Infinity, right = - Infinity, bottom = - Infinity;
	for ( let i = 0; i < 8; i ++ ) {

		const corner = new THREE.Vector3( i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z ).project( camera );
		const x = ( corner.x + 1 ) / 2 * rect.width, y = ( 1 - corner.y ) / 2 * rect.height;
		left = Math.min( left, x ); right = Math.max( right, x ); top = Math.min( top, y ); bottom = Math.max( bottom, y );

	}

	return [ left, top, right, bottom ];

}
