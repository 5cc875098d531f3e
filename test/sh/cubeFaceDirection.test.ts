import { describe, expect, it } from 'vitest';
import { CubeCamera, PerspectiveCamera, Vector3, WebGLCoordinateSystem, WebGLCubeRenderTarget } from 'three';
import { CUBE_FACE_AXES, cubeFaceDirection } from '../../src/sh/index.js';

describe( 'cube face texel → direction mapping', () => {

	it( 'the centre texel of each face (odd size) looks straight along that face\'s axis', () => {

		// three's face order is +X, −X, +Y, −Y, +Z, −Z; the centre of a face is its axis whatever
		// the in-face orientation is, so this pins the face order independently of u/v signs.
		const axes = [ [ 1, 0, 0 ], [ - 1, 0, 0 ], [ 0, 1, 0 ], [ 0, - 1, 0 ], [ 0, 0, 1 ], [ 0, 0, - 1 ] ];
		for ( let f = 0; f < 6; f ++ ) {

			const d = cubeFaceDirection( f, 4, 4, 9 );
			for ( let c = 0; c < 3; c ++ ) expect( d[ c ] ).toBeCloseTo( axes[ f ][ c ], 12 );

		}

	} );

	it( '+X: the FIRST readback row is world up (y > 0), the last row world down, column 0 is +Z', () => {

		// readPixels returns window rows bottom-up, so buffer row 0 is y_ndc ≈ −1. CubeCamera's
		// fov is −90°, which mirrors y_ndc = −y_camera/depth, and the +X camera's up is +Y: so the
		// bottom window row shows world +Y. Likewise x_ndc = −x_camera/depth and the +X camera's
		// x axis is up × (−look) = +Z, so the left column (x_ndc ≈ −1) shows world +Z.
		const size = 32;
		const firstRow = cubeFaceDirection( 0, size / 2, 0, size );
		const lastRow = cubeFaceDirection( 0, size / 2, size - 1, size );
		const firstColumn = cubeFaceDirection( 0, 0, size / 2, size );
		expect( firstRow[ 1 ] ).toBeGreaterThan( 0.6 );
		expect( lastRow[ 1 ] ).toBeLessThan( - 0.6 );
		expect( firstColumn[ 2 ] ).toBeGreaterThan( 0.6 );

		// And the sign flip really comes from three's projection matrix: element [5] (y scale) < 0.
		const camera = new PerspectiveCamera( - 90, 1, 0.1, 10 );
		expect( camera.projectionMatrix.elements[ 5 ] ).toBeLessThan( 0 );
		expect( camera.projectionMatrix.elements[ 0 ] ).toBeLessThan( 0 );

	} );

	it( 'matches unprojecting every texel centre through three\'s own CubeCamera face cameras (WebGL system)', () => {

		// Independent of the table in cubeFaceDirection.ts: let three orient its six cameras, then
		// unproject the NDC point of texel (i, j) — x_ndc from the column, y_ndc from the readback
		// row (bottom-up) — and take the ray from the camera. The only assumption left is the
		// readPixels row order, which the GPU test checks on a real context.
		const cubeCamera = new CubeCamera( 0.1, 10, new WebGLCubeRenderTarget( 1 ) );
		cubeCamera.coordinateSystem = WebGLCoordinateSystem;
		cubeCamera.updateCoordinateSystem();
		cubeCamera.updateMatrixWorld( true );
		const size = 7;
		const point = new Vector3();
		let maxError = 0;
		for ( let f = 0; f < 6; f ++ ) {

			const camera = cubeCamera.children[ f ] as PerspectiveCamera;
			for ( let j = 0; j < size; j ++ ) {

				for ( let i = 0; i < size; i ++ ) {

					point.set( - 1 + ( i + 0.5 ) * 2 / size, - 1 + ( j + 0.5 ) * 2 / size, 0.5 ).unproject( camera ).normalize();
					const d = cubeFaceDirection( f, i, j, size );
					maxError = Math.max(
						maxError, Math.abs( d[ 0 ] - point.x ), Math.abs( d[ 1 ] - point.y ), Math.abs( d[ 2 ] - point.z )
					);

				}

			}

		}

		expect( maxError ).toBeLessThan( 1e-9 );

	} );

	it( 'every texel of a face has that face\'s axis as its dominant component', () => {

		const size = 6;
		for ( let f = 0; f < 6; f ++ ) {

			const axis = f >> 1;
			const sign = f % 2 === 0 ? 1 : - 1;
			for ( let j = 0; j < size; j ++ ) {

				for ( let i = 0; i < size; i ++ ) {

					const d = cubeFaceDirection( f, i, j, size );
					expect( d[ axis ] * sign ).toBeGreaterThan(
						Math.max( Math.abs( d[ ( axis + 1 ) % 3 ] ), Math.abs( d[ ( axis + 2 ) % 3 ] ) )
					);
					expect( Math.hypot( d[ 0 ], d[ 1 ], d[ 2 ] ) ).toBeCloseTo( 1, 14 );

				}

			}

		}

		expect( CUBE_FACE_AXES ).toHaveLength( 6 );

	} );

} );
