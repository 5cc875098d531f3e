import * as THREE from 'three';
import { LightProbeVolumeHelper, type LightProbeVolume } from 'three-capture-lighting';

const _matrix = new THREE.Matrix4();
const _sphere = new THREE.Sphere();
const _hit = new THREE.Vector3();

/**
 * What a scene page draws of its volume: the library's `LightProbeVolumeHelper` (a ball per probe
 * shaded by that probe's own SH, the tetrahedra or triangles as a faint wireframe, the cell
 * holding the character in yellow), plus an invisible handle per probe for probe editing to pick
 * and drag.
 */
export class ProbeMarkers {

	/**
	 * One handle per probe, `userData.probe` its id: what probe editing picks (a raycast hits the
	 * handle's ball) and drags; the ball drawn follows a dragged handle.
	 */
	readonly markers = new THREE.Group();
	private helper: LightProbeVolumeHelper | null = null;
	private readonly parent: THREE.Object3D;
	private readonly radius: number;
	private highlighted: THREE.Vector3 | THREE.Object3D | null = null;

	/** Adds the markers to `parent` (a group left out of captures); `radius` of each probe's ball. */
	constructor( parent: THREE.Object3D, radius: number ) {

		this.parent = parent;
		this.radius = radius;
		parent.add( this.markers );

	}

	/** The marker of probe `index`, if it has one. */
	markerOf( index: number ): THREE.Object3D | undefined {

		return this.markers.children.find( ( marker ) => marker.userData.probe === index );

	}

	/** Redraws the probes and cells of `volume` (after a capture or an edit; a new volume gets a new helper). */
	update( volume: LightProbeVolume ): void {

		if ( this.helper?.volume === volume ) {

			this.helper.update();

		} else {

			this.helper?.removeFromParent();
			this.helper?.dispose();
			this.helper = new LightProbeVolumeHelper( volume, this.radius );
			this.highlighted = null;
			this.parent.add( this.helper );

		}

		this.markers.clear();
		for ( let i = 0; i < volume.count; i ++ ) {

			if ( ! volume.isProbeActive( i ) ) continue;
			const handle = new THREE.Object3D();
			handle.position.fromArray( volume.positions, 3 * i );
			handle.userData.probe = i;
			handle.raycast = ( raycaster, intersects ) => hitBall( handle, this.radius, raycaster, intersects );
			this.markers.add( handle );

		}

	}

	/**
	 * Every frame: probes and cells shown or not; with cells, the one holding `target` (a point read
	 * every frame, or an object: the cell it samples) in yellow. A dragged handle moves its ball.
	 */
	show( showProbes: boolean, showCells: boolean, volume: LightProbeVolume, target: THREE.Vector3 | THREE.Object3D ): void {

		if ( this.helper?.volume !== volume ) this.update( volume );
		const helper = this.helper!;
		helper.probes.visible = showProbes;
		helper.tetrahedra = showCells;
		const highlighted = showCells ? target : null;
		if ( highlighted !== this.highlighted ) {

			helper.highlight( highlighted );
			this.highlighted = highlighted;

		}

		if ( showProbes ) this.followHandles( helper );

	}

	/** Moves the ball of any handle that is not where its ball is (during a drag, or after a failed move). */
	private followHandles( helper: LightProbeVolumeHelper ): void {

		const matrices = helper.probes.instanceMatrix, array = matrices.array, handles = this.markers.children;
		for ( let h = 0; h < handles.length; h ++ ) {

			const i = handles[ h ].userData.probe as number, p = handles[ h ].position, o = 16 * i;
			// Instance matrices are float32: compare with the handle's position rounded the same way.
			const x = Math.fround( p.x ), y = Math.fround( p.y ), z = Math.fround( p.z );
			if ( array[ o + 12 ] === x && array[ o + 13 ] === y && array[ o + 14 ] === z ) continue;
			helper.probes.setMatrixAt( i, _matrix.makeScale( helper.size, helper.size, helper.size ).setPosition( p ) );
			matrices.needsUpdate = true;
			helper.probes.computeBoundingSphere();

		}

	}

}

/** A raycast against the ball of radius `radius` around `handle`. */
function hitBall( handle: THREE.Object3D, radius: number, raycaster: THREE.Raycaster, intersects: THREE.Intersection[] ): void {

	_sphere.set( handle.getWorldPosition( _hit ), radius );
	if ( raycaster.ray.intersectSphere( _sphere, _hit ) === null ) return;
	const distance = raycaster.ray.origin.distanceTo( _hit );
	if ( distance < raycaster.near || distance > raycaster.far ) return;
	intersects.push( { distance, point: _hit.clone(), object: handle } );

}
