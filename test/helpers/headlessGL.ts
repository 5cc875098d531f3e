import * as THREE from 'three';

/**
 * A three.js WebGLRenderer on a headless-gl WebGL2 context, for GPU tests in Node. headless-gl
 * needs an X display: `npm test` runs the suite under xvfb-run. When none is available the
 * renderer is null and `skipReason` says why — tests put it in their suite name.
 */
export interface HeadlessGL {

	renderer: THREE.WebGLRenderer | null;
	gl: WebGL2RenderingContext | null;
	skipReason: string;
	dispose(): void;

}

/** A canvas stand-in: three reads its size and (un)registers context-loss listeners. */
function fakeCanvas( width: number, height: number ): HTMLCanvasElement {

	return { width, height, style: {}, addEventListener() {}, removeEventListener() {} } as unknown as HTMLCanvasElement;

}

export async function createHeadlessRenderer( width = 64, height = 64 ): Promise<HeadlessGL> {

	if ( ! process.env.DISPLAY ) return { renderer: null, gl: null, skipReason: 'no X display (DISPLAY unset): run `npm test`, which uses xvfb-run', dispose() {} };
	let gl: WebGL2RenderingContext | null = null;
	try {

		const createGL = ( await import( 'gl' ) ).default;
		gl = createGL( width, height, { createWebGL2Context: true, preserveDrawingBuffer: true } ) as WebGL2RenderingContext | null;

	} catch ( error ) {

		return { renderer: null, gl: null, skipReason: `headless-gl failed to load: ${( error as Error ).message}`, dispose() {} };

	}

	if ( ! gl ) return { renderer: null, gl: null, skipReason: 'headless-gl could not create a WebGL2 context', dispose() {} };
	const renderer = new THREE.WebGLRenderer( { context: gl, canvas: fakeCanvas( width, height ) } );
	renderer.setSize( width, height, false );
	return {
		renderer, gl, skipReason: '',
		dispose() {

			renderer.dispose();
			( gl as unknown as { getExtension( name: string ): { destroy(): void } | null } ).getExtension( 'STACKGL_destroy_context' )?.destroy();

		},
	};

}
