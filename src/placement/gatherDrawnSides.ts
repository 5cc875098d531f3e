import type { BufferGeometry, InstancedMesh, Material, Mesh, Object3D } from 'three';

// three's `Side` constants (FrontSide 0, BackSide 1, DoubleSide 2), stable since r1xx: read by
// value so that this file loads no three.js.
const BACK_SIDE = 1, DOUBLE_SIDE = 2;

/** Per-vertex flags of {@link DrawnSides.vertexSides}. */
export const DRAWN_ALONG_NORMAL = 1, DRAWN_AGAINST_NORMAL = 2;

/** The side(s) each triangle's material draws, in `gatherWorldGeometry`'s triangle and vertex order. */
export interface DrawnSides {

	/**
	 * Per triangle of `gatherWorldGeometry( root ).triangles`: 1 when the side its world winding
	 * calls front (counter-clockwise) is drawn, −1 the back, 0 both (or a triangle no material
	 * draws: outside every group of a multi-material mesh).
	 */
	triangleSides: Int8Array;

	/**
	 * Per vertex of `gatherWorldGeometry( root ).vertexPositions`: {@link DRAWN_ALONG_NORMAL} when a
	 * triangle using it is drawn on the side its normal points to (`FrontSide`),
	 * {@link DRAWN_AGAINST_NORMAL} on the other (`BackSide`, a room seen from inside), both bits for
	 * `DoubleSide`, 0 when no drawn triangle uses it.
	 */
	vertexSides: Uint8Array;

}

/**
 * The drawn side of every triangle and vertex under `root`, as three renders them: a material's
 * `side` (per group for multi-material meshes), flipped for triangles when the mesh's world matrix
 * mirrors (three then swaps the front face: the drawn side stays the one the normals face, while
 * the world winding turns over). Walks the meshes exactly as `gatherWorldGeometry` does (same
 * meshes, instances, draw ranges and order), after bringing the world matrices up to date as it does.
 */
export function gatherDrawnSides( root: Object3D ): DrawnSides {

	root.updateWorldMatrix( true, true );

	const meshes: Mesh[] = [];
	let vertexCount = 0, triangleCount = 0;
	root.traverse( ( object ) => {

		const mesh = object as Mesh;
		if ( mesh.isMesh !== true || ( mesh as unknown as { isBatchedMesh?: boolean } ).isBatchedMesh === true ) return;
		const geometry = mesh.geometry as BufferGeometry | undefined;
		if ( ! geometry || ! geometry.getAttribute( 'position' ) ) return;
		meshes.push( mesh );
		vertexCount += instanceCount( mesh ) * geometry.getAttribute( 'position' ).count;
		triangleCount += instanceCount( mesh ) * Math.floor( drawnIndexCount( geometry ) / 3 );

	} );

	const triangleSides = new Int8Array( triangleCount ), vertexSides = new Uint8Array( vertexCount );
	let vertexBase = 0, triangleBase = 0;
	for ( const mesh of meshes ) {

		const geometry = mesh.geometry, index = geometry.index;
		const vertices = geometry.getAttribute( 'position' ).count;
		const start = Math.max( 0, geometry.drawRange.start ), indexCount = drawnIndexCount( geometry );
		const mirrored = mesh.matrixWorld.determinant() < 0;
		const materials = Array.isArray( mesh.material ) ? mesh.material : null;
		for ( let copy = 0, copies = instanceCount( mesh ); copy < copies; copy ++ ) {

			for ( let t = 0; 3 * t + 2 < indexCount; t ++ ) {

				const first = start + 3 * t;
				const material = materials === null ? mesh.material as Material : groupMaterial( geometry, materials, first );
				if ( material === undefined ) continue; // not drawn: side 0, no vertex flags
				const side = material.side === DOUBLE_SIDE ? 0 : material.side === BACK_SIDE ? - 1 : 1;
				triangleSides[ triangleBase + t ] = mirrored ? - side : side;
				const flags = side === 0 ? DRAWN_ALONG_NORMAL | DRAWN_AGAINST_NORMAL : side > 0 ? DRAWN_ALONG_NORMAL : DRAWN_AGAINST_NORMAL;
				for ( let corner = 0; corner < 3; corner ++ ) {

					vertexSides[ vertexBase + ( index ? index.getX( first + corner ) : first + corner ) ] |= flags;

				}

			}

			vertexBase += vertices;
			triangleBase += Math.floor( indexCount / 3 );

		}

	}

	return { triangleSides, vertexSides };

}

/** The material of the group holding index `first` (three draws a multi-material mesh group by group), or undefined. */
function groupMaterial( geometry: BufferGeometry, materials: Material[], first: number ): Material | undefined {

	for ( const group of geometry.groups ) {

		if ( first >= group.start && first < group.start + group.count ) return materials[ group.materialIndex ?? 0 ];

	}

	return undefined;

}

function instanceCount( mesh: Mesh ): number {

	return ( mesh as InstancedMesh ).isInstancedMesh === true ? ( mesh as InstancedMesh ).count : 1;

}

/** How many indices (or vertices, without an index) the draw range covers (as `gatherWorldGeometry` counts them). */
function drawnIndexCount( geometry: BufferGeometry ): number {

	const available = geometry.index ? geometry.index.count : geometry.getAttribute( 'position' ).count;
	const start = Math.max( 0, geometry.drawRange.start );
	return Math.max( 0, Math.min( available - start, geometry.drawRange.count ) );

}
