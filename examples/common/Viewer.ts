import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import Stats from 'three/addons/libs/stats.module.js';
import { Overlay } from './Overlay.js';
import { readDemoQuery, type DemoQuery, type DemoSettings } from './queryParameters.js';
import { backendLabel, chooseRenderer, createRenderer, initRenderer, watchRendererLoss, type AnyRenderer, type RendererChoice } from './rendererChoice.js';
import { recordFrame, type DemoReport } from './report.js';

// ?renderer= is read, and for a WebGPURenderer three/webgpu and three-capture-lighting/webgpu
// loaded, before any page makes its Viewer, so the constructor can make the renderer at once.
const rendererChoice = await chooseRenderer();
const _size = new THREE.Vector2();

/** Where a page's camera starts. */
export interface ViewerCamera {

	position: number[];
	target: number[];
	fov?: number;
	near?: number;
	far?: number;

}

/**
 * The chrome of a scene page: renderer, scene, camera with orbit controls, resizing, stats, the
 * on-page overlay (status, progress, notices, errors) and the render loop with its timings in
 * `window.__demo`. It reads the query parameters; the page builds its scene and volume into it.
 */
export class Viewer {

	/** Status line, progress bar, notices and errors on the page. */
	readonly overlay = new Overlay();
	/** The page's query parameters. */
	readonly query: DemoQuery = readDemoQuery( location.search );
	/** The panel's state (query parameters first). */
	readonly settings: DemoSettings = this.query.settings;
	/** Base URL of the third-party assets. */
	readonly assets: string = this.query.assets;
	/** The scene the page builds and the probes capture. */
	readonly scene = new THREE.Scene();
	/** Objects that must not appear in captures (markers, helpers): a group in the scene. */
	readonly helpers = new THREE.Group();
	/** `window.__demo`. */
	readonly report: DemoReport = {
		ready: false, captureMs: 0, probes: 0, cells: 0, frameMs: [], intervalMs: [], character: 'none', leakingCells: 0, error: '', renderer: '',
	};
	/** `?renderer=`: which renderer was asked for and runs (the panel's "renderer" list switches it). */
	readonly rendererChoice: RendererChoice = rendererChoice;
	/**
	 * Antialiased, filmic tone mapping (`tonemapping=none`: none), drawing buffer kept for screenshots:
	 * a WebGLRenderer, or with `?renderer=webgpu|webgl2` a WebGPURenderer (`rendererChoice` says which).
	 */
	readonly renderer: AnyRenderer;
	/** Resolves once the renderer can render (a WebGPURenderer's `init()`); `ProbeVolumeDemo.start()` waits for it. */
	readonly ready: Promise<void>;
	readonly camera: THREE.PerspectiveCamera;
	/** Orbit controls around the page's camera target (probes are added there). */
	readonly controls: OrbitControls;
	/** Frames per second, smoothed. */
	fps = 0;
	private readonly stats = new Stats();
	private readonly timer = new THREE.Timer();
	private time = 0;

	/** Creates the renderer, camera and controls, and shows 'loading the scene…' until the first capture. */
	constructor( { camera: { position, target, fov = 60, near = 0.05, far = 500 } }: { camera: ViewerCamera } ) {

		const renderer = createRenderer( rendererChoice, { antialias: true, preserveDrawingBuffer: true } );
		this.renderer = renderer;
		this.renderer.setPixelRatio( Math.min( window.devicePixelRatio, 2 ) );
		this.renderer.setSize( window.innerWidth, window.innerHeight );
		// Filmic tone mapping for viewing; ?tonemapping=none keeps colour ratios for measurements.
		this.renderer.toneMapping = this.query.noToneMapping ? THREE.NoToneMapping : THREE.ACESFilmicToneMapping;
		document.body.appendChild( this.renderer.domElement );
		watchRendererLoss( renderer, ( message ) => this.overlay.error( message ) );
		if ( rendererChoice.notice ) this.overlay.notice( rendererChoice.notice );
		this.ready = initRenderer( renderer ).then( () => {

			// Which backend runs: in the report for tests, and on the page unless hide=gui (screenshots).
			this.report.renderer = backendLabel( renderer );
			if ( ! this.query.hideGui ) this.overlay.renderer( this.report.renderer );

		} );

		this.camera = new THREE.PerspectiveCamera( fov, window.innerWidth / window.innerHeight, near, far );
		this.camera.position.fromArray( position );
		this.controls = new OrbitControls( this.camera, this.renderer.domElement );
		this.controls.target.fromArray( target );
		this.controls.update();
		this.scene.add( this.helpers );

		// main.css places the title between the stats and the panel, or hides it for screenshots.
		if ( ! this.query.hideGui ) document.body.appendChild( this.stats.dom );
		document.body.classList.add( this.query.hideGui ? 'no-ui' : 'with-panel' ); // no-ui: no text that changes
		window.addEventListener( 'resize', () => this.resize() );
		window.addEventListener( 'error', ( event ) => this.fail( event.message ) );
		window.addEventListener( 'unhandledrejection', ( event ) => this.fail( String( event.reason?.message ?? event.reason ) ) );
		Object.assign( window, { __demo: this.report } );
		this.overlay.progress( 'loading the scene…', 0 );

	}

	/** Shows an error on the page (not only in the console) and records it for tests. */
	fail( message: string ): void {

		this.report.error = message;
		this.overlay.progress( '', 1 );
		this.overlay.error( message );

	}

	/** For a page's `init().catch( … )`: the error on the page and in the console. */
	showError( error: unknown ): void {

		this.fail( ( error as Error ).message );
		console.error( error );

	}

	/**
	 * Starts the render loop: every frame calls `frame( time, delta )` — seconds; `t=` freezes
	 * time, the panel's "animate" off makes delta 0 — then renders and records the frame's timings.
	 */
	animate( frame: ( time: number, delta: number ) => void ): void {

		this.ready.then( () => this.startLoop( frame ) ).catch( ( error ) => this.showError( error ) );

	}

	private startLoop( frame: ( time: number, delta: number ) => void ): void {

		// ?present=0: the frames go to a target of the canvas's size, never to the screen (a
		// WebGLRenderTarget: both renderers draw into one).
		const offscreen = this.query.offscreen ? new THREE.WebGLRenderTarget( 320, 180, { type: THREE.HalfFloatType } ) : null;
		this.renderer.setAnimationLoop( ( timestamp ) => {

			this.timer.update( timestamp );
			const delta = this.timer.getDelta();
			const step = this.settings.animate ? delta : 0;
			this.time = this.query.time !== null ? this.query.time : this.time + step;
			const start = performance.now();

			frame( this.time, step );
			if ( offscreen !== null ) {

				this.renderer.getDrawingBufferSize( _size );
				offscreen.setSize( _size.x, _size.y );
				this.renderer.setRenderTarget( offscreen );

			}

			this.renderer.render( this.scene, this.camera );
			if ( offscreen !== null ) this.renderer.setRenderTarget( null );

			this.stats.update();
			recordFrame( this.report, performance.now() - start, delta * 1000 );
			if ( delta > 0 ) this.fps += ( 1 / delta - this.fps ) * 0.05;

		} );

	}

	private resize(): void {

		this.camera.aspect = window.innerWidth / window.innerHeight;
		this.camera.updateProjectionMatrix();
		this.renderer.setSize( window.innerWidth, window.innerHeight );

	}

}
