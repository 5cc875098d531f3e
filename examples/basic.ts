import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import GUI from 'lil-gui';
import { GridInterpolator, TetrahedralMesh, blendSH, projectEquirectToSH, type ProbeInterpolator } from 'three-capture-lighting';

// The paper's Basic scene: a room with red, green and blue walls. Until GPU capture lands, each
// probe "captures" the room analytically on the CPU: a panorama of the walls seen from the probe,
// projected to SH9 with projectEquirectToSH. The moving sphere is lit by the probes around it.

const ROOM_MIN = [ - 2, 0, - 2 ], ROOM_MAX = [ 2, 3, 2 ];
type Wall = '-x' | '+x' | '-y' | '+y' | '-z' | '+z';
const WALLS: Record<Wall, number[]> = { // radiance of each wall, as if lit evenly by the glowing ceiling
	'-x': [ 0.6, 0.05, 0.05 ], '+x': [ 0.05, 0.6, 0.05 ], '-z': [ 0.05, 0.05, 0.6 ],
	'+z': [ 0.5, 0.5, 0.5 ], '-y': [ 0.4, 0.4, 0.4 ], '+y': [ 2, 2, 2 ],
};

// 13 probes placed with meaning (paper 2.1.1): sky above, bounce at the floor, bleed by each coloured wall.
const ARBITRARY = [
	0, 2.8, 0, // sky
	- 1.7, 0.2, - 1.7, 1.7, 0.2, - 1.7, - 1.7, 0.2, 1.7, 1.7, 0.2, 1.7, 0, 0.2, 0, // bounce
	- 1.8, 1.3, 0, 1.8, 1.3, 0, 0, 1.3, - 1.8, // bleed: red, green, blue
	0, 1.5, 1.8, - 1.7, 2.7, - 1.7, 1.7, 2.7, 1.7, 1.7, 2.7, - 1.7, // fill
];
const GRID = new GridInterpolator( [ - 1.8, 0.2, - 1.8 ], [ 1.8, 2.8, 1.8 ], [ 4, 4, 4 ] );

/** Radiance seen from `origin` along `dir`: the wall the ray leaves the room through. */
function roomRadiance( origin: number[], dir: number[] ): number[] {

	let best = Infinity, wall: Wall = '+y';
	for ( let a = 0; a < 3; a ++ ) {

		if ( dir[ a ] === 0 ) continue;
		const positive = dir[ a ] > 0;
		const t = ( ( positive ? ROOM_MAX[ a ] : ROOM_MIN[ a ] ) - origin[ a ] ) / dir[ a ];
		if ( t < best ) { best = t; wall = `${positive ? '+' : '-'}${'xyz'[ a ]}` as Wall; }

	}

	return WALLS[ wall ];

}

/** The room as a panorama from `origin` (three.js equirectangular convention), projected to SH9. */
function captureRoom( origin: number[], width = 64, height = 32 ): Float32Array {

	const pixels = new Float32Array( width * height * 4 );
	for ( let row = 0; row < height; row ++ ) {

		const latitude = ( 0.5 - ( row + 0.5 ) / height ) * Math.PI;
		for ( let column = 0; column < width; column ++ ) {

			const longitude = ( ( column + 0.5 ) / width - 0.5 ) * 2 * Math.PI;
			const dir = [ Math.cos( latitude ) * Math.cos( longitude ), Math.sin( latitude ), Math.cos( latitude ) * Math.sin( longitude ) ];
			pixels.set( roomRadiance( origin, dir ), 4 * ( row * width + column ) );

		}

	}

	return projectEquirectToSH( pixels, width, height );

}

function captureAll( positions: ArrayLike<number> ): Float32Array {

	const sh = new Float32Array( 27 * positions.length / 3 );
	for ( let i = 0; i < positions.length / 3; i ++ ) sh.set( captureRoom( [ positions[ 3 * i ], positions[ 3 * i + 1 ], positions[ 3 * i + 2 ] ] ), 27 * i );
	return sh;

}

const layouts = {
	tetrahedral: { interpolator: new TetrahedralMesh( ARBITRARY ) as ProbeInterpolator, positions: Float64Array.from( ARBITRARY ) },
	trilinear: { interpolator: GRID as ProbeInterpolator, positions: GRID.positions },
};
const captured = { tetrahedral: captureAll( layouts.tetrahedral.positions ), trilinear: captureAll( layouts.trilinear.positions ) };

// Scene: unlit walls in their radiance colours, one lit sphere.
const renderer = new THREE.WebGLRenderer( { antialias: true, preserveDrawingBuffer: true } );
renderer.setPixelRatio( window.devicePixelRatio );
renderer.setSize( window.innerWidth, window.innerHeight );
renderer.toneMapping = THREE.ACESFilmicToneMapping;
document.body.appendChild( renderer.domElement );

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera( 60, window.innerWidth / window.innerHeight, 0.05, 50 );
camera.position.set( 0, 1.6, 3.6 );
const controls = new OrbitControls( camera, renderer.domElement );
controls.target.set( 0, 1.1, 0 );
controls.update();

const size = new THREE.Vector3( 4, 3, 4 );
const faceColors = [ '+x', '-x', '+y', '-y', '+z', '-z' ].map( ( key ) => new THREE.MeshBasicMaterial( {
	color: new THREE.Color().fromArray( WALLS[ key as Wall ] ).multiplyScalar( key === '+y' ? 0.5 : 1 ),
	side: THREE.BackSide,
} ) );
faceColors[ 4 ].visible = false; // the wall behind the camera
const room = new THREE.Mesh( new THREE.BoxGeometry( size.x, size.y, size.z ), faceColors );
room.position.set( 0, 1.5, 0 );
scene.add( room );

const lightProbe = new THREE.LightProbe();
scene.add( lightProbe );
const sphere = new THREE.Mesh( new THREE.SphereGeometry( 0.35, 48, 24 ), new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1 } ) );
scene.add( sphere );

// Probe markers and the tetrahedra as wireframe, the current cell highlighted.
const probeGroups = { tetrahedral: new THREE.Group(), trilinear: new THREE.Group() };
for ( const key of [ 'tetrahedral', 'trilinear' ] as const ) {

	const p = layouts[ key ].positions;
	for ( let i = 0; i < p.length / 3; i ++ ) {

		const marker = new THREE.Mesh( new THREE.SphereGeometry( 0.05, 12, 6 ), new THREE.MeshBasicMaterial( { color: new THREE.Color().fromArray( captured[ key ], 27 * i ).multiplyScalar( 0.6 ) } ) );
		marker.position.fromArray( p, 3 * i );
		probeGroups[ key ].add( marker );

	}

	scene.add( probeGroups[ key ] );

}

const mesh = layouts.tetrahedral.interpolator as TetrahedralMesh;
const edges: number[] = [];
for ( let t = 0; t < mesh.cellCount; t ++ ) {

	const v = mesh.tetrahedra.subarray( 4 * t, 4 * t + 4 );
	for ( const [ a, b ] of [ [ 0, 1 ], [ 0, 2 ], [ 0, 3 ], [ 1, 2 ], [ 1, 3 ], [ 2, 3 ] ] ) edges.push( ...mesh.positions.subarray( 3 * v[ a ], 3 * v[ a ] + 3 ), ...mesh.positions.subarray( 3 * v[ b ], 3 * v[ b ] + 3 ) );

}

const wireframe = new THREE.LineSegments( new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( edges, 3 ) ), new THREE.LineBasicMaterial( { color: 0x888888, transparent: true, opacity: 0.35 } ) );
const current = new THREE.LineSegments( new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( new Float32Array( 36 ), 3 ) ), new THREE.LineBasicMaterial( { color: 0xffff00 } ) );
scene.add( wireframe, current );

const params = { interpolation: 'tetrahedral' as 'tetrahedral' | 'trilinear', showProbes: true, showCells: true, animate: true };
const gui = new GUI();
gui.add( params, 'interpolation', [ 'tetrahedral', 'trilinear' ] ).name( 'layout' );
gui.add( params, 'showProbes' ).name( 'show probes' );
gui.add( params, 'showCells' ).name( 'show tetrahedra' );
gui.add( params, 'animate' );

// Per-frame state, allocated once.
const indices = new Uint32Array( 8 ), weights = new Float64Array( 8 ), blended = new Float32Array( 27 );
let hint = - 1, time = 0, frames = 0;
const status = document.getElementById( 'status' )!;
const timer = new THREE.Timer();

function render( timestamp?: number ): void {

	timer.update( timestamp );
	if ( params.animate ) time += timer.getDelta();
	sphere.position.set( 1.3 * Math.cos( time * 0.5 ), 1 + 0.4 * Math.sin( time * 0.8 ), 1.3 * Math.sin( time * 0.5 ) );

	const layout = layouts[ params.interpolation ];
	hint = layout.interpolator.interpolate( sphere.position.x, sphere.position.y, sphere.position.z, indices, weights, params.interpolation === 'tetrahedral' ? hint : - 1 );
	blendSH( indices, weights, captured[ params.interpolation ], blended, layout.interpolator.weightCount );
	lightProbe.sh.fromArray( blended );

	probeGroups.tetrahedral.visible = params.showProbes && params.interpolation === 'tetrahedral';
	probeGroups.trilinear.visible = params.showProbes && params.interpolation === 'trilinear';
	wireframe.visible = current.visible = params.showCells && params.interpolation === 'tetrahedral';
	if ( current.visible ) {

		const attribute = current.geometry.getAttribute( 'position' ) as THREE.BufferAttribute;
		let o = 0;
		for ( const [ a, b ] of [ [ 0, 1 ], [ 0, 2 ], [ 0, 3 ], [ 1, 2 ], [ 1, 3 ], [ 2, 3 ] ] ) {

			attribute.setXYZ( o ++, mesh.positions[ 3 * indices[ a ] ], mesh.positions[ 3 * indices[ a ] + 1 ], mesh.positions[ 3 * indices[ a ] + 2 ] );
			attribute.setXYZ( o ++, mesh.positions[ 3 * indices[ b ] ], mesh.positions[ 3 * indices[ b ] + 1 ], mesh.positions[ 3 * indices[ b ] + 2 ] );

		}

		attribute.needsUpdate = true;

	}

	renderer.render( scene, camera );
	status.textContent = `${params.interpolation}: ${layout.interpolator.probeCount} probes, ${layout.interpolator.cellCount} ${params.interpolation === 'tetrahedral' ? 'tetrahedra' : 'boxes'}`;
	if ( ++ frames === 10 ) Object.assign( window, { __ready: true } );

}

window.addEventListener( 'resize', () => {

	camera.aspect = window.innerWidth / window.innerHeight;
	camera.updateProjectionMatrix();
	renderer.setSize( window.innerWidth, window.innerHeight );

} );

renderer.setAnimationLoop( render );
