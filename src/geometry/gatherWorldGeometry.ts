import { Matrix3, Matrix4, Vector3, type BufferGeometry, type InstancedMesh, type Mesh, type Object3D } from 'three';

/** World-space geometry of every mesh under a root, flattened for the pure placement functions. */
export interface WorldGeometry {

	/** x, y, z per vertex, world space. */
	vertexPositions: Float64Array;

	/** Unit normal per vertex, world space (zero where a vertex touches only degenerate triangles). */
	vertexNormals: Float64Array;

	/** 9 floats (a, b, c) per triangle, world space: the input of `TriangleBVH`. */
	triangles: Float64Array;

}

const _matrix = new Matrix4(), _instance = new Matrix4(), _normalMatrix = new Matrix3();
const _v = new Vector3();

/**
 * Gathers the world-space vertices, vertex normals and triangles of every `Mesh` under `root`
 * (root included). World matrices are brought up to date first (`root.updateWorldMatrix( true,
 * true )`, as three's `Box3.setFromObject` does), so a scene just loaded or edited is read where it
 * will be drawn. Objects that are not meshes (lines, points, sprites, lights, cameras, groups)
 * contribute nothing; an `InstancedMesh` contributes each instance.
 *
 * Normals are transformed by the inverse transpose (correct under non-uniform scale and mirroring)
 * and normalised. A geometry without a `normal` attribute gets area-weighted face normals
 * accumulated per vertex. Skinned and morphed meshes are read in their bind pose; `drawRange` is
 * respected, material groups are not needed. Helpers — objects whose `type` ends in `Helper`, such as
 * three's `LightProbeHelper` or this library's `LightProbeVolumeHelper` — are skipped with their
 * children: they are drawn for the user, not part of the level, and must not block probes.
 */
export function gatherWorldGeometry( root: Object3D ): WorldGeometry {

	if ( root === null || typeof root !== 'object' || ( root as Object3D ).isObject3D !== true ) {

		throw new TypeError( 'gatherWorldGeometry: root must be a three.js Object3D.' );

	}

	root.updateWorldMatrix( true, true );

	// First pass: sizes, so the output is three typed arrays filled once.
	const meshes: Mesh[] = [];
	let vertexCount = 0, triangleCount = 0;
	traverseSceneGeometry( root, ( object ) => {

		const mesh = object as Mesh;
		if ( mesh.isMesh !== true || ( mesh as unknown as { isBatchedMesh?: boolean } ).isBatchedMesh === true ) return;
		const geometry = mesh.geometry as BufferGeometry | undefined;
		if ( ! geometry || ! geometry.getAttribute( 'position' ) ) return;
		const copies = instanceCount( mesh );
		meshes.push( mesh );
		vertexCount += copies * geometry.getAttribute( 'position' ).count;
		triangleCount += copies * Math.floor( drawnIndexCount( geometry ) / 3 );

	} );

	const vertexPositions = new Float64Array( 3 * vertexCount );
	const vertexNormals = new Float64Array( 3 * vertexCount );
	const triangles = new Float64Array( 9 * triangleCount );
	let vertexBase = 0, triangleBase = 0;

	for ( const mesh of meshes ) {

		const geometry = mesh.geometry;
		const position = geometry.getAttribute( 'position' ), normal = geometry.getAttribute( 'normal' );
		const index = geometry.index;
		const start = Math.max( 0, geometry.drawRange.start ), indexCount = drawnIndexCount( geometry );

		for ( let copy = 0, copies = instanceCount( mesh ); copy < copies; copy ++ ) {

			_matrix.copy( mesh.matrixWorld );
			if ( ( mesh as InstancedMesh ).isInstancedMesh === true ) {

				_matrix.multiply( ( mesh as InstancedMesh ).getMatrixAt( copy, _instance ) );

			}

			_normalMatrix.getNormalMatrix( _matrix );

			for ( let v = 0; v < position.count; v ++ ) {

				_v.fromBufferAttribute( position, v ).applyMatrix4( _matrix );
				const o = 3 * ( vertexBase + v );
				vertexPositions[ o ] = _v.x; vertexPositions[ o + 1 ] = _v.y; vertexPositions[ o + 2 ] = _v.z;
				if ( normal ) {

					_v.fromBufferAttribute( normal, v ).applyMatrix3( _normalMatrix ).normalize();
					vertexNormals[ o ] = _v.x; vertexNormals[ o + 1 ] = _v.y; vertexNormals[ o + 2 ] = _v.z;

				}

			}

			for ( let t = 0; 3 * t + 2 < indexCount; t ++ ) {

				const o = 9 * ( triangleBase + t );
				for ( let corner = 0; corner < 3; corner ++ ) {

					const i = start + 3 * t + corner;
					const v = vertexBase + ( index ? index.getX( i ) : i );
					triangles[ o + 3 * corner ] = vertexPositions[ 3 * v ];
					triangles[ o + 3 * corner + 1 ] = vertexPositions[ 3 * v + 1 ];
					triangles[ o + 3 * corner + 2 ] = vertexPositions[ 3 * v + 2 ];

				}

				if ( ! normal ) accumulateFaceNormal( triangles, o, vertexNormals, vertexBase, index, start + 3 * t );

			}

			if ( ! normal ) normalizeRange( vertexNormals, vertexBase, position.count );
			vertexBase += position.count;
			triangleBase += Math.floor( indexCount / 3 );

		}

	}

	return { vertexPositions, vertexNormals, triangles };

}

function instanceCount( mesh: Mesh ): number {

	return ( mesh as InstancedMesh ).isInstancedMesh === true ? ( mesh as InstancedMesh ).count : 1;

}

/** How many indices (or vertices, without an index) the draw range covers. */
function drawnIndexCount( geometry: BufferGeometry ): number {

	const available = geometry.index ? geometry.index.count : geometry.getAttribute( 'position' ).count;
	const start = Math.max( 0, geometry.drawRange.start );
	return Math.max( 0, Math.min( available - start, geometry.drawRange.count ) );

}

/** Adds the triangle's cross product (twice its area times its normal) to its three vertices. */
function accumulateFaceNormal( triangles: Float64Array, o: number, normals: Float64Array, vertexBase: number, index: BufferGeometry[ 'index' ], first: number ): void {

	const e1x = triangles[ o + 3 ] - triangles[ o ], e1y = triangles[ o + 4 ] - triangles[ o + 1 ];
	const e1z = triangles[ o + 5 ] - triangles[ o + 2 ];
	const e2x = triangles[ o + 6 ] - triangles[ o ], e2y = triangles[ o + 7 ] - triangles[ o + 1 ];
	const e2z = triangles[ o + 8 ] - triangles[ o + 2 ];
	const nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
	for ( let corner = 0; corner < 3; corner ++ ) {

		const v = 3 * ( vertexBase + ( index ? index.getX( first + corner ) : first + corner ) );
		normals[ v ] += nx; normals[ v + 1 ] += ny; normals[ v + 2 ] += nz;

	}

}

function normalizeRange( normals: Float64Array, first: number, count: number ): void {

	for ( let v = first; v < first + count; v ++ ) {

		const x = normals[ 3 * v ], y = normals[ 3 * v + 1 ], z = normals[ 3 * v + 2 ];
		const length = Math.sqrt( x * x + y * y + z * z );
		if ( length > 0 ) {

			normals[ 3 * v ] = x / length; normals[ 3 * v + 1 ] = y / length; normals[ 3 * v + 2 ] = z / length;

		}

	}

}

/** `object.traverse`, without the subtrees of helpers (see {@link gatherWorldGeometry}). */
function traverseSceneGeometry( object: Object3D, callback: ( object: Object3D ) => void ): void {

	if ( typeof object.type === 'string' && object.type.endsWith( 'Helper' ) ) return;
	callback( object );
	for ( const child of object.children ) traverseSceneGeometry( child, callback );

}
