import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { HDRLoader } from 'three/addons/loaders/HDRLoader.js';
import { CSS2DObject, CSS2DRenderer } from 'three/addons/renderers/CSS2DRenderer.js';
import Stats from 'three/addons/libs/stats.module.js';
import GUI from 'lil-gui';
import { LightProbeVolume } from 'three-capture-lighting';
import { PlanarMesh, evaluateIrradiance, makeIrradianceNonNegative, windowSH } from 'three-capture-lighting/math';
import { projectEquirectToSHGPU } from 'three-capture-lighting/capture';
import { loadCharacter } from './common/character.js';
import { kyotoLegend } from './common/kyotoLegend.js';
import { panoramaTableText } from './common/kyotoPanoramaTable.js';
import { screenBox } from './common/screenBox.js';
import { Overlay } from './common/Overlay.js';
import { addRendererSwitch, backendLabel, chooseRenderer, createRenderer, initRenderer, watchRendererLoss } from './common/rendererChoice.js';
import type { DemoReport } from './common/report.js';
import { createKyotoMap, derivePanorama, kyoto, kyotoPath, type KyotoLayout, type KyotoPanorama } from '@scenes/kyoto.js';

// The paper's Kyoto experiment (section 3): light probes captured from street-level panoramas
// placed on a flat map, a 5x4 grid (20) vs 12 placed by hand. The paper did not partition the
// map; here it is triangulated in 2D (delaunator, through LightProbeVolume's planar fallback) and
// the fox and the white spheres are lit by the barycentric blend of their triangle's 3 probes.
// Each panorama is projected to SH9 on the GPU (projectEquirectToSHGPU). By default nothing is
// windowed: a very bright sun rings in SH9, and that is left visible; the panel's de-ringing
// strength and "irradiance never negative" switch apply to the volume's probes (the table shows
// the raw panoramas).
//
// Query: assets (asset folder URL, default /assets/), layout, t (freeze time, seconds),
// background=none, probes=0 (hide probe markers), hide=gui, deringing=s, nonnegative=1,
// renderer=webgpu|webgl2 (a WebGPURenderer, the library from three-capture-lighting/webgpu).
// For tests: window.__demo (DemoReport) and window.__kyoto (addPanorama( url, x, z, name? ), params, showLegend, …).

interface Panorama extends KyotoPanorama { texture: THREE.Texture; sh: Float32Array; ms: number; minE: number; maxE: number; size: string }

const query = new URLSearchParams( location.search );
const assets = query.get( 'assets' ) ?? '/assets/';
const FOX_HEIGHT = 1.8, LOOP_SECONDS = 60;
const frozen = query.get( 't' );

const report: DemoReport = { ready: false, captureMs: 0, probes: 0, cells: 0, frameMs: [], intervalMs: [], character: 'none', error: '', renderer: '' };
const overlay = new Overlay();
const layouts: KyotoLayout[] = structuredClone( kyoto.layouts );
const panoramas = new Map<string, Panorama>();
const params = {
	layout: layouts.some( ( l ) => l.name === query.get( 'layout' ) ) ? query.get( 'layout' )! : layouts[ 0 ].name,
	background: query.get( 'background' ) === 'none' ? 'none' : 'strongest probe',
	deringing: Number( query.get( 'deringing' ) ?? 0 ), nonNegative: query.get( 'nonnegative' ) === '1',
	exposure: 1, table: window.innerWidth >= 900, triangles: true, probes: query.get( 'probes' ) !== '0', labels: query.get( 'probes' ) !== '0', animate: true,
};

// ?renderer=: a WebGLRenderer, or a WebGPURenderer (typed as the WebGLRenderer the library's signatures name).
const rendererChoice = await chooseRenderer();
const renderer = createRenderer( rendererChoice, { antialias: true, preserveDrawingBuffer: true } ) as THREE.WebGLRenderer;
renderer.setPixelRatio( Math.min( window.devicePixelRatio, 2 ) );
renderer.setSize( window.innerWidth, window.innerHeight );
renderer.toneMapping = THREE.ACESFilmicToneMapping;
document.body.appendChild( renderer.domElement );
watchRendererLoss( renderer, ( message ) => overlay.error( message ) );
if ( rendererChoice.notice ) overlay.notice( rendererChoice.notice );
const labelRenderer = new CSS2DRenderer();
labelRenderer.setSize( window.innerWidth, window.innerHeight );
labelRenderer.domElement.style.cssText = 'position:absolute;top:0;left:0;pointer-events:none';
document.body.appendChild( labelRenderer.domElement );
const stats = new Stats();
// ?hide=gui: no panel, stats or text that changes from run to run (screenshots for tests); else
// main.css places the title between the stats and the panel.
if ( query.get( 'hide' ) === 'gui' ) document.body.classList.add( 'no-ui' ); else document.body.append( stats.dom );
document.body.classList.toggle( 'with-panel', query.get( 'hide' ) !== 'gui' );
const table = document.createElement( 'div' );
table.id = 'panoramas';
table.style.cssText = 'position:absolute;top:72px;left:8px;padding:4px 6px;background:rgba(0,0,0,0.55);white-space:pre;font:11px/1.35 ui-monospace,monospace;color:#ddd;pointer-events:none';
document.body.appendChild( table );

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera( 50, window.innerWidth / window.innerHeight, 0.1, 1000 );
camera.position.set( - 3, 21, 32 );
const controls = new OrbitControls( camera, renderer.domElement );
controls.target.set( - 3, 0, 1 );
controls.update();

const map = createKyotoMap();
const markers = new THREE.Group();
const triangles = new THREE.LineSegments(
	new THREE.BufferGeometry(),
	new THREE.LineBasicMaterial( { color: 0x203a5a, transparent: true, opacity: 0.7, toneMapped: false } )
);
const current = new THREE.Mesh( new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( new Float32Array( 9 ), 3 ) ), new THREE.MeshBasicMaterial( { color: 0xffb000, transparent: true, opacity: 0.35, side: THREE.DoubleSide, toneMapped: false, depthWrite: false } ) );
const currentEdges = new THREE.LineLoop( current.geometry, new THREE.LineBasicMaterial( { color: 0xff8000, toneMapped: false } ) );
scene.add( map, markers, triangles, current, currentEdges );

const lit: THREE.Object3D[] = [];
const spheres: THREE.Mesh[] = [];
let fox: THREE.Object3D | null = null, mixer: THREE.AnimationMixer | null = null;
let volume: LightProbeVolume | null = null, mesh: PlanarMesh | null = null;
let time = 0, fps = 0, hint = - 1, warmupMs = 0;
const indices = new Uint32Array( 4 ), weights = new Float32Array( 4 );
const timer = new THREE.Timer();

const layout = () => layouts.find( ( l ) => l.name === params.layout ) ?? layouts[ 0 ];
const nextFrame = () => new Promise<void>( ( resolve ) => { requestAnimationFrame( () => resolve() ); setTimeout( resolve, 50 ); } );

function fail( message: string ): void {

	report.error = message;
	overlay.error( message );

}

window.addEventListener( 'error', ( event ) => fail( event.message ) );
window.addEventListener( 'unhandledrejection', ( event ) => fail( String( event.reason?.message ?? event.reason ) ) );

/** Loads a panorama: `.hdr` as linear half float, anything else as an sRGB image (decoded to linear on the GPU). */
async function loadPanorama( url: string, name: string ): Promise<THREE.Texture> {

	const hdr = /\.hdr$/i.test( name );
	const texture = hdr ? await new HDRLoader().loadAsync( url ) : await new THREE.TextureLoader().loadAsync( url );
	if ( ! hdr ) texture.colorSpace = THREE.SRGBColorSpace;
	texture.mapping = THREE.EquirectangularReflectionMapping;
	return texture;

}

/**
 * Projects a panorama to SH9 on the GPU, timed, and records the range of its irradiance E(n). Awaited:
 * a WebGPURenderer reads its result back asynchronously.
 */
async function project( entry: KyotoPanorama, texture: THREE.Texture ): Promise<Panorama> {

	const start = performance.now();
	const sh = await projectEquirectToSHGPU( renderer, texture );
	const ms = performance.now() - start;
	let minE = Infinity, maxE = - Infinity;
	const e = new Float32Array( 3 );
	for ( let k = 0; k < 1000; k ++ ) { // Fibonacci sphere

		const y = 1 - ( 2 * k + 1 ) / 1000, r = Math.sqrt( 1 - y * y ), phi = k * 2.399963;
		evaluateIrradiance( sh, [ r * Math.cos( phi ), y, r * Math.sin( phi ) ], e );
		minE = Math.min( minE, e[ 0 ], e[ 1 ], e[ 2 ] ); maxE = Math.max( maxE, e[ 0 ], e[ 1 ], e[ 2 ] );

	}

	const { width, height } = texture.image as { width: number; height: number };
	const panorama = { ...entry, texture, sh, ms, minE, maxE, size: `${width}×${height}` };
	panoramas.set( entry.id, panorama );
	return panorama;

}

/** Loads the two photos, derives the other panoramas from them and projects them all. */
async function projectAll(): Promise<void> {

	const start = performance.now();
	const warmup = new THREE.DataTexture( new Uint16Array( 4 * 16 * 8 ), 16, 8, THREE.RGBAFormat, THREE.HalfFloatType );
	warmup.needsUpdate = true;
	await projectEquirectToSHGPU( renderer, warmup ); // compiles the shaders, so the times below are per panorama
	warmup.dispose();
	warmupMs = performance.now() - start;

	const photos = kyoto.panoramas.filter( ( p ) => p.kind === 'photo' );
	const textures = await Promise.all( photos.map( async ( p ) => {

		try {

			return await loadPanorama( assets + p.file, p.file! );

		} catch ( error ) {

			throw new Error( `Panorama not found: ${assets}${p.file} (${( error as Error ).message}). Get potsdamer_platz_1k.hdr and venice_sunset_1k.hdr from Poly Haven (polyhaven.com, CC0) into <assets>/panoramas/ — the asset folder is ../shared/assets beside the repository or $CAPTURE_LIGHTING_ASSETS — or pass ?assets=URL.` );

		}

	} ) );

	let done = 0;
	for ( const entry of kyoto.panoramas ) {

		overlay.progress( `projecting ${entry.label} to SH on the GPU (${done + 1} / ${kyoto.panoramas.length})`, done / kyoto.panoramas.length );
		await nextFrame();
		const texture = entry.kind === 'photo' ? textures[ photos.indexOf( entry ) ] : derivePanorama( panoramas.get( entry.source! )!.texture as THREE.DataTexture, entry.yaw ?? 0, entry.gain );
		await project( entry, texture );
		done ++;

	}

	overlay.progress( '', 1 );
	report.captureMs = warmupMs + [ ...panoramas.values() ].reduce( ( sum, p ) => sum + p.ms, 0 ); // GPU projection only, not loading

}

/** The volume for the current layout: probes at their map points, SH from their panoramas, 2D Delaunay. */
function buildVolume(): void {

	const { probes } = layout();
	volume?.dispose(); // restores the lit objects' materials
	const sh = new Float32Array( 27 * probes.length );
	probes.forEach( ( p, i ) => sh.set( panoramas.get( p.panorama )!.sh, 27 * i ) );
	if ( params.nonNegative ) makeIrradianceNonNegative( sh, params.deringing );
	else if ( params.deringing > 0 ) windowSH( sh, params.deringing, sh );
	volume = new LightProbeVolume( {
		positions: probes.flatMap( ( p ) => [ p.at[ 0 ], kyoto.height, p.at[ 1 ] ] ), sh,
		names: probes.map( ( p ) => p.name ), roles: probes.map( ( p ) => p.role ),
	} );
	if ( ! ( volume.interpolator instanceof PlanarMesh ) ) throw new Error( 'Kyoto: the probes are expected on one plane (a flat map).' );
	mesh = volume.interpolator;
	hint = - 1;
	// The fox samples on its vertical axis, so the highlighted triangle below is exactly the one used.
	for ( const object of lit ) volume.add( object, object === fox ? { anchor: new THREE.Vector3( 0, FOX_HEIGHT / 2, 0 ) } : {} );
	if ( mesh.duplicates.length > 0 ) overlay.notice( `${mesh.duplicates.length / 2} probe(s) at the same map point as another were merged (not used).` );
	report.probes = volume.count;
	report.cells = mesh.cellCount;
	updateMarkers();

}

/** Probe balls shaded by their own SH (white diffuse: E(n)/π), drop lines, labels, and the triangles on the map. */
function updateMarkers(): void {

	markers.traverse( ( o ) => {

		if ( o instanceof THREE.Mesh || o instanceof THREE.LineSegments ) { o.geometry.dispose(); o.material.dispose(); }
		if ( o instanceof CSS2DObject ) o.element.remove();

	} );
	markers.clear();
	const { probes } = layout();
	const e = new Float32Array( 3 ), drops: number[] = [];
	const ringMaterial = {
		photo: new THREE.MeshBasicMaterial( { color: 0xffffff, toneMapped: false } ),
		dropped: new THREE.MeshBasicMaterial( { color: 0x66eeff, toneMapped: false } )
	};
	for ( const p of probes ) {

		const panorama = panoramas.get( p.panorama )!;
		const geometry = new THREE.SphereGeometry( 0.4, 24, 12 );
		const normals = geometry.getAttribute( 'normal' );
		const colors = new Float32Array( 3 * normals.count );
		for ( let v = 0; v < normals.count; v ++ ) {

			evaluateIrradiance( panorama.sh, [ normals.getX( v ), normals.getY( v ), normals.getZ( v ) ], e );
			// Negative irradiance (SH ringing) cannot be displayed: it is shown magenta, not hidden.
			colors.set(
				e[ 0 ] < 0 || e[ 1 ] < 0 || e[ 2 ] < 0 ? [ 1, 0, 1 ] : [ e[ 0 ] / Math.PI, e[ 1 ] / Math.PI, e[ 2 ] / Math.PI ],
				3 * v
			);

		}

		geometry.setAttribute( 'color', new THREE.BufferAttribute( colors, 3 ) );
		const ball = new THREE.Mesh( geometry, new THREE.MeshBasicMaterial( { vertexColors: true } ) );
		ball.position.set( p.at[ 0 ], kyoto.height, p.at[ 1 ] );
		if ( panorama.kind !== 'derived' ) {

			const ring = new THREE.Mesh( new THREE.TorusGeometry( 0.6, 0.06, 6, 32 ), ringMaterial[ panorama.kind ] );
			ring.rotation.x = Math.PI / 2;
			ball.add( ring );

		}

		const label = document.createElement( 'div' );
		label.className = `probe-label ${panorama.kind}`;
		label.textContent = panorama.label;
		label.title = `${p.name} (${p.role}): ${panorama.note}`;
		const css = new CSS2DObject( label );
		css.position.y = 0.5;
		ball.add( css );
		markers.add( ball );
		drops.push( p.at[ 0 ], 0, p.at[ 1 ], p.at[ 0 ], kyoto.height, p.at[ 1 ] );

	}

	markers.add( new THREE.LineSegments( new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( drops, 3 ) ), new THREE.LineBasicMaterial( { color: 0x444444 } ) ) );

	const edges: number[] = [];
	const t = mesh!.triangles;
	for ( let k = 0; k < t.length; k += 3 ) {

		for ( const [ a, b ] of [ [ 0, 1 ], [ 1, 2 ], [ 2, 0 ] ] ) edges.push( ...ground( t[ k + a ] ), ...ground( t[ k + b ] ) );

	}

	triangles.geometry.dispose();
	triangles.geometry = new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( edges, 3 ) );
	panoramaTable();

}

/** A probe's point on the map, just above the ground. */
function ground( probe: number ): number[] {

	return [ volume!.positions[ 3 * probe ], 0.03, volume!.positions[ 3 * probe + 2 ] ];

}

function panoramaTable(): void {

	table.textContent = panoramaTableText( [ ...panoramas.values() ], layout().probes.map( ( p ) => p.panorama ), warmupMs );

}

async function addCharacterAndSpheres(): Promise<void> {

	const character = await loadCharacter( assets + 'fox/Fox.glb', FOX_HEIGHT );
	report.character = character.kind;
	if ( character.kind === 'fallback' ) overlay.notice( `Character asset not found at ${assets}fox/Fox.glb — showing a stand-in. ${character.reason}` );
	fox = character.object;
	mixer = character.mixer;
	scene.add( fox );
	lit.push( fox );
	// Three white spheres by default; ?spheres=N for a load test.
	const count = Number( query.get( 'spheres' ) ?? 3 );
	for ( let i = 0; i < count; i ++ ) {

		const sphere = new THREE.Mesh(
			new THREE.SphereGeometry( 0.6, count > 10 ? 16 : 32, count > 10 ? 8 : 16 ),
			new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1, metalness: 0 } )
		);
		spheres.push( sphere );
		scene.add( sphere );
		lit.push( sphere );

	}

}

/** Adds a probe at map point (x, z) captured from the panorama at `url` (also the drop handler's path). */
async function addPanorama( url: string, x: number, z: number, name = url.split( /[/?#]/ ).filter( Boolean ).pop() ?? 'panorama' ): Promise<{ probes: number; ms: number; sh: number[] }> {

	if ( ! Number.isFinite( x ) || ! Number.isFinite( z ) ) throw new RangeError( `addPanorama: map point (${x}, ${z}) is not two finite numbers.` );
	overlay.progress( `projecting ${name} to SH on the GPU…`, 0.5 );
	try {

		const texture = await loadPanorama( url, name );
		const panorama = await project( { id: `drop${panoramas.size}`, label: name.slice( 0, 12 ), kind: 'dropped', note: `dropped file ${name}` }, texture );
		layout().probes.push( { name, at: [ x, z ], panorama: panorama.id, role: 'fill' } );
		delete layout().grid;
		buildVolume();
		overlay.notice( `${name}: projected in ${panorama.ms.toFixed( 0 )} ms, added to "${params.layout}" at (${x.toFixed( 1 )}, ${z.toFixed( 1 )}).` );
		return { probes: volume!.count, ms: panorama.ms, sh: Array.from( panorama.sh ) };

	} finally {

		overlay.progress( '', 1 );

	}

}

/** Where a screen point hits the map, or null. */
function mapPoint( clientX: number, clientY: number ): THREE.Vector3 | null {

	const raycaster = new THREE.Raycaster();
	raycaster.setFromCamera(
		new THREE.Vector2( ( clientX / window.innerWidth ) * 2 - 1, - ( clientY / window.innerHeight ) * 2 + 1 ),
		camera
	);
	return raycaster.intersectObject( map, false )[ 0 ]?.point ?? null;

}

function usePanoramaFile( file: File, x: number, z: number ): void {

	const url = URL.createObjectURL( file );
	addPanorama( url, x, z, file.name )
		.catch( ( error: Error ) => overlay.notice( `Could not use ${file.name}: ${error.message}` ) )
		.finally( () => URL.revokeObjectURL( url ) );

}

window.addEventListener( 'dragover', ( event ) => event.preventDefault() );
window.addEventListener( 'drop', ( event ) => {

	event.preventDefault();
	const file = event.dataTransfer?.files[ 0 ];
	if ( ! file ) return;
	const point = mapPoint( event.clientX, event.clientY );
	if ( point ) usePanoramaFile( file, point.x, point.z ); else overlay.notice( 'Drop the panorama on the map.' );

} );

function createGui(): void {

	if ( query.get( 'hide' ) === 'gui' ) return;
	const gui = new GUI();
	addRendererSwitch( gui, rendererChoice );
	gui.add( params, 'layout', layouts.map( ( l ) => l.name ) ).onChange( buildVolume );
	gui.add( params, 'background', [ 'strongest probe', 'none' ] );
	gui.add( params, 'deringing', 0, 0.5, 0.01 ).name( 'de-ringing strength' ).onFinishChange( buildVolume );
	gui.add( params, 'nonNegative' ).name( 'irradiance never negative' ).onChange( buildVolume );
	gui.add( params, 'exposure', 0, 4, 0.01 ).onChange( ( value: number ) => { renderer.toneMappingExposure = value; } );
	gui.add( params, 'table' ).name( 'show panorama table' );
	gui.add( params, 'triangles' ).name( 'show triangles' ).onChange( showLegend );
	gui.add( params, 'probes' ).name( 'show probes' ).onChange( showLegend );
	gui.add( params, 'labels' ).name( 'show labels' );
	gui.add( params, 'animate' );
	const input = Object.assign( document.createElement( 'input' ), { type: 'file', accept: '.hdr,.jpg,.jpeg,.png' } );
	input.addEventListener( 'change', () => { if ( input.files?.[ 0 ] && fox ) usePanoramaFile( input.files[ 0 ], fox.position.x, fox.position.z ); input.value = ''; } );
	gui.add( { add: () => input.click() }, 'add' ).name( 'add a panorama at the fox…' );
	// On a narrow page the open panel would cover the title (main.css moves the title under it).
	if ( window.innerWidth < 900 ) gui.close();

}

/** The legend of the rings, magenta patches and the fox's triangle, for what is drawn. */
function showLegend(): void {

	overlay.legend( kyotoLegend( params ) );

}

function frame( timestamp: number ): void {

	timer.update( timestamp );
	const delta = timer.getDelta();
	time = frozen !== null ? Number( frozen ) : time + ( params.animate ? delta : 0 );
	const start = performance.now();

	const u = ( ( time / LOOP_SECONDS ) % 1 + 1 ) % 1;
	if ( fox ) {

		kyotoPath.getPointAt( u, fox.position );
		const ahead = kyotoPath.getPointAt( ( u + 0.001 ) % 1 );
		fox.lookAt( ahead.x, 0, ahead.z );
		mixer?.update( params.animate ? delta : 0 );

	}

	spheres.forEach( ( sphere, i ) => {

		kyotoPath.getPointAt( ( ( u + 0.975 - 0.025 * i ) % 1 + 1 ) % 1, sphere.position );
		sphere.position.y = 0.6;

	} );

	volume!.update();

	// The fox's triangle (or, outside the triangulation, the boundary edge it is clamped to).
	const p = fox?.position ?? new THREE.Vector3();
	hint = mesh!.interpolate( p.x, p.y, p.z, indices, weights, hint );
	const inside = indices[ 2 ] !== indices[ 0 ];
	const position = current.geometry.getAttribute( 'position' ) as THREE.BufferAttribute;
	for ( let k = 0; k < 3; k ++ ) {

		position.setXYZ( k, ...( ground( indices[ inside ? k : Math.min( k, 1 ) ] ) as [ number, number, number ] ) );

	}

	position.needsUpdate = true;
	current.visible = currentEdges.visible = triangles.visible = params.triangles;

	let strongest = 0;
	for ( let k = 1; k < 3; k ++ ) if ( weights[ k ] > weights[ strongest ] ) strongest = k;
	const probes = layout().probes;
	scene.background = params.background === 'none' ? null : panoramas.get( probes[ indices[ strongest ] ].panorama )!.texture;
	markers.visible = params.probes;
	table.style.display = params.table ? '' : 'none';
	labelRenderer.domElement.style.display = params.labels && params.probes ? '' : 'none';

	renderer.render( scene, camera );
	labelRenderer.render( scene, camera );
	stats.update();
	report.frameMs.push( performance.now() - start );
	if ( report.frameMs.length > 300 ) report.frameMs.shift();
	if ( delta > 0 ) report.intervalMs.push( delta * 1000 );
	if ( report.intervalMs.length > 300 ) report.intervalMs.shift();
	if ( delta > 0 ) fps += ( 1 / delta - fps ) * 0.05;
	const blend = ( inside ? [ 0, 1, 2 ] : [ 0, 1 ] ).map( ( k ) => `${probes[ indices[ k ] ].name} (${panoramas.get( probes[ indices[ k ] ].panorama )!.label}) ${weights[ k ].toFixed( 2 )}` ).join( ', ' );
	overlay.status( `${params.layout} — 2D Delaunay (delaunator) on the map\n${volume!.count} probes, ${mesh!.cellCount} triangles\n` +
		`fox ${inside ? `in triangle ${hint}` : 'outside, on the boundary'}: ${blend}\n${fps.toFixed( 0 )} fps` );
	if ( ! report.ready && report.frameMs.length >= 5 ) report.ready = true;

}

window.addEventListener( 'resize', () => {

	camera.aspect = window.innerWidth / window.innerHeight;
	camera.updateProjectionMatrix();
	renderer.setSize( window.innerWidth, window.innerHeight );
	labelRenderer.setSize( window.innerWidth, window.innerHeight );

} );

Object.assign( window, {
	__demo: report,
	__kyoto: {
		addPanorama, characterScreenBox: () => screenBox( fox!, camera, renderer.domElement ),
		layoutNames: () => layouts.map( ( l ) => l.name ), panoramas, camera, controls, params, showLegend,
		get fox() { return fox; }, get volume() { return volume; }
	}
} );

async function start(): Promise<void> {

	try {

		overlay.progress( 'loading the panoramas…', 0 );
		await initRenderer( renderer );
		report.renderer = backendLabel( renderer );
		if ( query.get( 'hide' ) !== 'gui' ) overlay.renderer( report.renderer );
		await projectAll();
		await addCharacterAndSpheres();
		// No capture of the scene here (the SH come from the panoramas), so the fox and the spheres
		// can be added at any time; buildVolume adds them to each new volume.
		buildVolume();
		createGui();
		showLegend();
		renderer.setAnimationLoop( frame );

	} catch ( error ) {

		overlay.progress( '', 1 );
		fail( ( error as Error ).message );
		console.error( error );

	}

}

start();
