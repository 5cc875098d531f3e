import * as THREE from 'three';
import { type LightProbeVolume } from 'three-capture-lighting';
import { evaluateIrradiance, type TetrahedralMesh } from 'three-capture-lighting/math';

const EDGES = [ [ 0, 1 ], [ 0, 2 ], [ 0, 3 ], [ 1, 2 ], [ 1, 3 ], [ 2, 3 ] ];

/**
 * What a scene page draws of its volume: a marker per probe shaded by that probe's own SH, the
 * tetrahedra (or triangles) as a faint wireframe, and the cell holding the character in yellow.
 */
export class ProbeMarkers {

	/** One ball per probe, `userData.probe` its index: what probe editing picks and drags. */
	readonly markers = new THREE.Group();
	private readonly wireframe = new THREE.LineSegments(
		new THREE.BufferGeometry(),
		new THREE.LineBasicMaterial( { color: 0xaaaaaa, transparent: true, opacity: 0.3 } ),
	);
	private readonly current = new THREE.LineSegments(
		new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( new Float32Array( 36 ), 3 ) ),
		new THREE.LineBasicMaterial( { color: 0xffff00 } ),
	);
	private readonly radius: number;

	/** Adds the markers to `parent` (a group left out of captures); `radius` of each probe's ball. */
	constructor( parent: THREE.Object3D, radius: number ) {

		this.radius = radius;
		parent.add( this.markers, this.wireframe, this.current );

	}

	/** The marker of probe `index`, if it has one. */
	markerOf( index: number ): THREE.Object3D | undefined {

		return this.markers.children.find( ( marker ) => marker.userData.probe === index );

	}

	/** Rebuilds the markers and the wireframe for `volume` (after a capture or an edit). */
	update( volume: LightProbeVolume ): void {

		for ( const marker of this.markers.children as THREE.Mesh[] ) {

			marker.geometry.dispose();
			( marker.material as THREE.Material ).dispose();

		}

		this.markers.clear();
		const e = new Float32Array( 3 );
		for ( let i = 0; i < volume.count; i ++ ) {

			// A white diffuse ball lit by this probe alone: vertex colour E(n) / π, no other light.
			const geometry = new THREE.SphereGeometry( this.radius, 12, 6 );
			const normals = geometry.getAttribute( 'normal' );
			const colors = new Float32Array( 3 * normals.count );
			for ( let v = 0; v < normals.count; v ++ ) {

				evaluateIrradiance( volume.sh, [ normals.getX( v ), normals.getY( v ), normals.getZ( v ) ], e, 27 * i );
				colors.set( [ Math.max( 0, e[ 0 ] ) / Math.PI, Math.max( 0, e[ 1 ] ) / Math.PI, Math.max( 0, e[ 2 ] ) / Math.PI ], 3 * v );

			}

			geometry.setAttribute( 'color', new THREE.BufferAttribute( colors, 3 ) );
			const marker = new THREE.Mesh( geometry, new THREE.MeshBasicMaterial( { vertexColors: true } ) );
			marker.position.fromArray( volume.positions, 3 * i );
			marker.userData.probe = i;
			this.markers.add( marker );

		}

		const edges: number[] = [];
		const mesh = volume.interpolator as TetrahedralMesh;
		const cells = mesh.tetrahedra ?? ( volume.interpolator as unknown as { triangles: Uint32Array } ).triangles;
		const stride = mesh.tetrahedra ? 4 : 3;
		for ( let t = 0; t < cells.length / stride; t ++ ) {

			for ( const [ a, b ] of EDGES ) {

				if ( b >= stride ) continue;
				for ( const k of [ a, b ] ) {

					const v = 3 * cells[ stride * t + k ];
					edges.push( ...volume.positions.subarray( v, v + 3 ) );

				}

			}

		}

		this.wireframe.geometry.dispose();
		this.wireframe.geometry = new THREE.BufferGeometry().setAttribute( 'position', new THREE.Float32BufferAttribute( edges, 3 ) );

	}

	/** Every frame: markers and cells shown or not; with cells, the one holding `point` in yellow. */
	show( showProbes: boolean, showCells: boolean, volume: LightProbeVolume, point: THREE.Vector3 ): void {

		this.markers.visible = showProbes;
		this.wireframe.visible = this.current.visible = showCells;
		if ( showCells ) this.highlightCell( volume, point );

	}

	private highlightCell( volume: LightProbeVolume, point: THREE.Vector3 ): void {

		const mesh = volume.interpolator as TetrahedralMesh;
		const attribute = this.current.geometry.getAttribute( 'position' ) as THREE.BufferAttribute;
		const cell = mesh.locate ? mesh.locate( point.x, point.y, point.z ) : - 1;
		let o = 0;
		for ( const [ a, b ] of EDGES ) {

			for ( const k of [ a, b ] ) {

				const v = cell >= 0 ? 3 * mesh.tetrahedra[ 4 * cell + k ] : 0;
				attribute.setXYZ( o ++, volume.positions[ v ], volume.positions[ v + 1 ], volume.positions[ v + 2 ] );

			}

		}

		attribute.needsUpdate = true;
		this.current.visible = cell >= 0;

	}

}
