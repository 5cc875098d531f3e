import { PerspectiveCamera } from 'three/webgpu';

/**
 * A `PerspectiveCamera` whose projection also negates clip-space y, whatever the renderer sets
 * its coordinate system to (the renderer recomputes the projection when that changes). On the
 * WebGPU backend, where NDC y = +1 is the first texel row, this stores a face texel for texel
 * where WebGL's CubeCamera face camera (NDC y = −1 at the first row) puts it: the same picture in
 * memory, so the same rasterisation (docs/webgpu-capture.md). It reverses every triangle's
 * winding: {@link WebGPUCubeFaces} flips the front face of the meshes it draws with it.
 */
export class MirroredProjectionCamera extends PerspectiveCamera {

	/** Recomputes the projection (three's), then negates its y row and recomputes its inverse. */
	override updateProjectionMatrix(): void {

		super.updateProjectionMatrix();
		const e = this.projectionMatrix.elements;
		for ( const k of [ 1, 5, 9, 13 ] ) e[ k ] = - e[ k ];
		this.projectionMatrixInverse.copy( this.projectionMatrix ).invert();

	}

}
