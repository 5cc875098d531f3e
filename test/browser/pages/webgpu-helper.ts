import { NoToneMapping, OrthographicCamera, RenderTarget, Scene, Vector3, WebGPURenderer } from 'three/webgpu';
import { LightProbeVolume, LightProbeVolumeHelper } from 'three-capture-lighting';
// The helper's node material, as the webgpu entry installs it (src/webgpu.ts is to import it too).
import '../../../src/webgpu/installHelper.js';

// LightProbeVolumeHelper on a WebGPURenderer (?backend=webgpu, or webgl2: forceWebGL): four probes
// with known SH, each sphere looked at head-on along directions where the sphere mesh has a vertex,
// so the centre pixel's normal is that direction exactly. For each (probe, direction) the centre
// pixel's sRGB bytes go to window.__result for test/browser/webgpuHelper.test.ts, which compares
// them with max( E(n), 0 ) / π from three's SphericalHarmonics3.getIrradianceAt.

const SIZE = 65; // odd: the middle pixel's centre is the view's centre
const backend = new URLSearchParams( location.search ).get( 'backend' ) === 'webgl2' ? 'webgl2' : 'webgpu';

/** The SH of the probes (27 floats each, SphericalHarmonics3 order), every coefficient nonzero. */
function probeSH( k: number ): number[] {

	const sh: number[] = [];
	for ( let i = 0; i < 9; i ++ ) for ( let c = 0; c < 3; c ++ ) {

		sh.push( i === 0 ? 1.2 + 0.3 * c - 0.2 * k : 0.25 * Math.sin( 1.7 * i + 2.3 * c + 0.9 * k ) );

	}

	return sh;

}

/** Vertices of SphereGeometry( 1, 16, 12 ): +z (u = 4 / 16, v = 6 / 12) and (u = 2 / 16, v = 3 / 12). */
function sphereVertex( i: number, j: number ): number[] {

	const phi = ( i / 16 ) * 2 * Math.PI, theta = ( j / 12 ) * Math.PI;
	return [ - Math.cos( phi ) * Math.sin( theta ), Math.cos( theta ), Math.sin( phi ) * Math.sin( theta ) ];

}

async function run(): Promise<unknown> {

	const positions = [ 0, 0, 0, 3, 0, 0, 0, 3, 0, 0, 0, 3 ];
	const sh = new Float32Array( [ 0, 1, 2, 3 ].flatMap( probeSH ) );
	const volume = new LightProbeVolume( { positions, sh } );
	const helper = new LightProbeVolumeHelper( volume, 0.5 );
	helper.tetrahedra = false;
	const scene = new Scene();
	scene.add( helper );

	const renderer = new WebGPURenderer( { forceWebGL: backend === 'webgl2' } );
	renderer.setPixelRatio( 1 );
	renderer.setSize( SIZE, SIZE );
	renderer.toneMapping = NoToneMapping;
	document.body.appendChild( renderer.domElement );
	await renderer.init();
	const running = ( renderer.backend as { isWebGPUBackend?: boolean } ).isWebGPUBackend ? 'webgpu' : 'webgl2';

	// Near and far keep the other probes (3 apart) out of each view.
	const camera = new OrthographicCamera( - 0.6, 0.6, 0.6, - 0.6, 0.1, 2 );
	// Drawn into a render target set as the output target, so that three applies the output colour
	// space (and tone mapping) in the shader as for the canvas — an 8-bit target without a colour
	// space of its own, so the sRGB encoding is applied once — then read back: headless Chromium's
	// screenshots do not show a WebGPU canvas.
	const target = new RenderTarget( SIZE, SIZE );
	renderer.setOutputRenderTarget( target );
	renderer.setRenderTarget( target );
	const directions = [ sphereVertex( 4, 6 ), sphereVertex( 2, 3 ), sphereVertex( 11, 8 ) ];
	const pixels: { probe: number; normal: number[]; rgb: number[] }[] = [];
	const centre = new Vector3();
	for ( let probe = 0; probe < 4; probe ++ ) {

		for ( const normal of directions ) {

			centre.fromArray( positions, 3 * probe );
			camera.position.copy( centre ).addScaledVector( new Vector3( ...normal ), 1 );
			camera.up.set( 0, 1, 0 );
			camera.lookAt( centre );
			renderer.render( scene, camera );
			const data = await renderer.readRenderTargetPixelsAsync( target, ( SIZE - 1 ) / 2, ( SIZE - 1 ) / 2, 1, 1 ) as Uint8Array;
			pixels.push( { probe, normal, rgb: [ data[ 0 ], data[ 1 ], data[ 2 ] ] } );

		}

	}

	const material = helper.probes.material as { isNodeMaterial?: boolean; type: string };
	return { backend: running, material: material.type, nodeMaterial: material.isNodeMaterial === true, sh: Array.from( sh ), pixels };

}

run().then( ( result ) => Object.assign( window, { __result: result } ) )
	.catch( ( error: Error ) => Object.assign( window, { __result: { error: `${error.message}\n${error.stack}` } } ) );
