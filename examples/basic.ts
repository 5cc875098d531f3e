import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import Stats from 'three/addons/libs/stats.module.js';
import GUI from 'lil-gui';
import { GridInterpolator, LightProbeVolume, evaluateIrradiance, type TetrahedralMesh } from 'three-capture-lighting';

// The paper's Basic scene: a room with red, green and blue walls, lit by one lamp. Probes capture
// the room on the GPU; the moving sphere is lit by the probes around it. Compare 13 probes placed
// with meaning (tetrahedral) with the 4x4x4 grid (trilinear), as in the paper's Table 4.

const ARBITRARY = [
	0, 2.7, 0, // sky: the lamp's light from above
	- 1.7, 0.2, - 1.7, 1.7, 0.2, - 1.7, - 1.7, 0.2, 1.7, 1.7, 0.2, 1.7, 0, 0.2, 0, // bounce: the floor
	- 1.8, 1.3, 0, 1.8, 1.3, 0, 0, 1.3, - 1.8, // bleed: the red, green and blue walls
	0, 1.5, 1.8, - 1.7, 2.7, - 1.7, 1.7, 2.7, 1.7, 1.7, 2.7, - 1.7, // fill
];
const GRID = new GridInterpolator( [ - 1.8, 0.2, - 1.8 ], [ 1.8, 2.8, 1.8 ], [ 4, 4, 4 ] );

const renderer = new THREE.WebGLRenderer( { antialias: true, preserveDrawingBuffer: true } );
renderer.setPixelRatio( window.devicePixelRatio );
renderer.setSize( window.innerWidth, window.innerHeight );
renderer.toneMapping = THREE.ACESFilmicToneMapping;
document.body.appendChild( renderer.domElement );

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera( 60, window.innerWidth / window.innerHeight, 0.05, 50 );
camera.position.set( 0, 1.6, 3.9 );
const controls = new OrbitControls( camera, renderer.domElement );
controls.target.set( 0, 1.1, 0 );
controls.update();

// Room: −x red, +x green, −z blue, the rest white. BoxGeometry's groups are +x, −x, +y, −y, +z, −z.
const wall = ( color: number ) => new THREE.MeshStandardMaterial( { color, roughness: 0.9, side: THREE.BackSide } );
const room = new THREE.Mesh( new THREE.BoxGeometry( 4, 3, 4 ), [ wall( 0x30c030 ), wall( 0xd02020 ), wall( 0xffffff ), wall( 0xdddddd ), wall( 0xffffff ), wall( 0x2040e0 ) ] );
room.position.y = 1.5;
scene.add( room );
const lamp = new THREE.PointLight( 0xfff2e0, 12, 0, 2 );
lamp.position.set( 0.4, 2.6, 0.3 );
scene.add( lamp, new THREE.Mesh( new THREE.SphereGeometry( 0.08 ), new THREE.MeshBasicMaterial( { color: 0xfff2e0 } ) ) );
scene.children[ scene.children.length - 1 ].position.copy( lamp.position );

const sphere = new THREE.Mesh( new THREE.SphereGeometry( 0.35, 48, 24 ), new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 0.8 } ) );
scene.add( sphere );

const volumes = {
	'13 probes, tetrahedral': new LightProbeVolume( { positions: ARBITRARY } ),
	'64 probes, trilinear': new LightProbeVolume( { positions: GRID.positions, interpolator: GRID } ),
	'64 probes, tetrahedral': new LightProbeVolume( { positions: GRID.positions } ),
};
type Layout = keyof typeof volumes;

const params = { layout: '13 probes, tetrahedral' as Layout, resolution: 32, probeLight: true, directLight: true, showProbes: true, showCells: true, animate: true, recapture };
const status = document.createElement( 'div' );
status.id = 'status';
document.body.appendChild( status );
const stats = new Stats();
document.body.appendChild( stats.dom );

// Probe markers shaded by their own SH, and the tetrahedra as wireframe with the current cell lit.
const markers = new THREE.Group();
const wireframe = new THREE.LineSegments( new THREE.BufferGeometry(), new THREE.LineBasicMaterial( { color: 0x999999, transparent: true, opacity: 0.35 } ) );
const current = new THREE.LineSegments( new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( new Float32Array( 36 ), 3 ) ), new THREE.LineBasicMaterial( { color: 0xffff00 } ) );
scene.add( markers, wireframe, current );
const EDGES = [ [ 0, 1 ], [ 0, 2 ], [ 0, 3 ], [ 1, 2 ], [ 1, 3 ], [ 2, 3 ] ];

function showLayout(): void {

	const volume = volumes[ params.layout ];
	markers.children.forEach( ( marker ) => { ( marker as THREE.Mesh ).geometry.dispose(); ( ( marker as THREE.Mesh ).material as THREE.Material ).dispose(); } );
	markers.clear();
	for ( let i = 0; i < volume.count; i ++ ) {

		// A white diffuse ball lit by this probe alone: colour E(n) / π per vertex, no lamp.
		const geometry = new THREE.SphereGeometry( 0.06, 16, 8 );
		const normals = geometry.getAttribute( 'normal' );
		const colors = new Float32Array( 3 * normals.count ), e = new Float32Array( 3 );
		for ( let v = 0; v < normals.count; v ++ ) {

			evaluateIrradiance( volume.sh, [ normals.getX( v ), normals.getY( v ), normals.getZ( v ) ], e, 27 * i );
			colors.set( [ e[ 0 ] / Math.PI, e[ 1 ] / Math.PI, e[ 2 ] / Math.PI ], 3 * v );

		}

		geometry.setAttribute( 'color', new THREE.BufferAttribute( colors, 3 ) );
		const marker = new THREE.Mesh( geometry, new THREE.MeshBasicMaterial( { vertexColors: true } ) );
		marker.position.fromArray( volume.positions, 3 * i );
		markers.add( marker );

	}

	const edges: number[] = [];
	const mesh = volume.interpolator as TetrahedralMesh;
	if ( mesh.tetrahedra ) {

		for ( let t = 0; t < mesh.cellCount; t ++ ) {

			for ( const [ a, b ] of EDGES ) edges.push( ...volume.positions.subarray( 3 * mesh.tetrahedra[ 4 * t + a ], 3 * mesh.tetrahedra[ 4 * t + a ] + 3 ), ...volume.positions.subarray( 3 * mesh.tetrahedra[ 4 * t + b ], 3 * mesh.tetrahedra[ 4 * t + b ] + 3 ) );

		}

	}

	wireframe.geometry.setAttribute( 'position', new THREE.Float32BufferAttribute( edges, 3 ) );
	for ( const v of Object.values( volumes ) ) v.remove( sphere );
	volume.add( sphere );

}

async function recapture(): Promise<void> {

	const start = performance.now();
	let probes = 0;
	for ( const [ name, volume ] of Object.entries( volumes ) ) {

		await volume.capture( renderer, scene, { resolution: params.resolution, exclude: [ sphere, markers, wireframe, current ], onProgress: ( done, total ) => { status.textContent = `capturing ${name}: ${done} / ${total}`; } } );
		probes += volume.count;

	}

	captureInfo = `${probes} probes captured at ${params.resolution}² in ${( performance.now() - start ).toFixed( 0 )} ms`;
	showLayout();

}

let captureInfo = '';
const gui = new GUI();
gui.add( params, 'layout', Object.keys( volumes ) ).onChange( showLayout );
gui.add( params, 'resolution', [ 8, 16, 32, 64, 128 ] ).name( 'capture resolution' ).onChange( recapture );
gui.add( params, 'probeLight' ).name( 'probe light' );
gui.add( params, 'directLight' ).name( 'direct light' );
gui.add( params, 'showProbes' ).name( 'show probes' );
gui.add( params, 'showCells' ).name( 'show tetrahedra' );
gui.add( params, 'animate' );
gui.add( params, 'recapture' );

const timer = new THREE.Timer();
let time = 0, frames = 0;

function render( timestamp?: number ): void {

	timer.update( timestamp );
	if ( params.animate ) time += timer.getDelta();
	sphere.position.set( 1.2 * Math.cos( time * 0.5 ), 0.9 + 0.4 * Math.sin( time * 0.8 ), 1.2 * Math.sin( time * 0.5 ) );

	const volume = volumes[ params.layout ];
	volume.update();
	const uniforms = volume.getUniforms( sphere );
	if ( uniforms ) uniforms.probeVolumeIntensity.value = params.probeLight ? 1 : 0;
	lamp.intensity = params.directLight ? 12 : 0;

	markers.visible = params.showProbes;
	const mesh = volume.interpolator as TetrahedralMesh;
	wireframe.visible = current.visible = params.showCells && mesh.tetrahedra !== undefined;
	if ( current.visible ) {

		const cell = mesh.locate( sphere.position.x, sphere.position.y, sphere.position.z );
		const attribute = current.geometry.getAttribute( 'position' ) as THREE.BufferAttribute;
		let o = 0;
		for ( const [ a, b ] of EDGES ) {

			for ( const k of [ a, b ] ) {

				const v = cell >= 0 ? 3 * mesh.tetrahedra[ 4 * cell + k ] : 0;
				attribute.setXYZ( o ++, volume.positions[ v ], volume.positions[ v + 1 ], volume.positions[ v + 2 ] );

			}

		}

		attribute.needsUpdate = true;

	}

	renderer.render( scene, camera );
	stats.update();
	if ( captureInfo ) status.textContent = `${params.layout}: ${volume.interpolator.cellCount} ${mesh.tetrahedra ? 'tetrahedra' : 'boxes'}\n${captureInfo}`;
	if ( captureInfo && ++ frames === 10 ) Object.assign( window, { __ready: true } );

}

window.addEventListener( 'resize', () => {

	camera.aspect = window.innerWidth / window.innerHeight;
	camera.updateProjectionMatrix();
	renderer.setSize( window.innerWidth, window.innerHeight );

} );

recapture().then( () => renderer.setAnimationLoop( render ), ( error ) => {

	status.textContent = `capture failed: ${error.message}`;
	console.error( error );

} );
