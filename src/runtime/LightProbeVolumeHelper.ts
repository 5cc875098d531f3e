import { BufferGeometry, Float32BufferAttribute, LineBasicMaterial, LineSegments, Object3D } from 'three';
import { assertNumber, describeValue } from '../validate.js';
import { hideLinesFromCubeCameras } from './cubeCameraHiding.js';
import type { LightProbeVolume } from './LightProbeVolume.js';
import { ProbeCellHighlight, type HighlightTarget } from './ProbeCellHighlight.js';
import { cellEdges, medianNearestDistance } from './probeCellEdges.js';
import { ProbeSphereMesh } from './ProbeSphereMesh.js';

/** Default sphere radius as a fraction of the median distance between nearest probes. */
const SIZE_PER_SPACING = 0.15;

/**
 * Draws a {@link LightProbeVolume}: a sphere per probe shaded by that probe's own SH, the cells
 * (tetrahedra, or the triangles, segments or grid boxes of flat, linear and grid volumes) as a
 * wireframe, and the cell an object samples, highlighted. Each sphere is a white diffuse ball lit
 * by its probe alone — the radiance E(n) / π for its normal n, as three's `LightProbeHelper` draws
 * a `LightProbe`, so a sphere looks like what the probe does to a white object there — tone
 * mapped and converted to the output colour space as three's own materials are.
 *
 * ```js
 * await volume.capture( renderer, scene );
 * const helper = new LightProbeVolumeHelper( volume );
 * scene.add( helper );
 * helper.highlight( character ); // optional: the cell it is lit from, every frame
 * // after a recapture or probe edits:
 * helper.update();
 * ```
 *
 * One draw call for all spheres (an `InstancedMesh`: instance i is probe id i, so a raycast's
 * `instanceId` is the probe id) and one each for the wireframe and the highlight. Cube cameras do
 * not draw the helper, so a capture never sees it. Probe positions are world positions: keep the
 * helper untransformed, under the scene or an untransformed group.
 */
export class LightProbeVolumeHelper extends Object3D {

	/** 'LightProbeVolumeHelper', to find the helper in a scene. */
	override readonly type: string = 'LightProbeVolumeHelper';

	/** The volume drawn. */
	readonly volume: LightProbeVolume;

	/** The probe spheres (instance i = probe id i; removed probes are scaled to nothing). */
	readonly probes: ProbeSphereMesh;

	/** The wireframe of the cells: unique edges as line segments. */
	readonly cells: LineSegments<BufferGeometry, LineBasicMaterial>;

	/** The highlighted cell (see {@link LightProbeVolumeHelper.highlight}). */
	readonly cell: ProbeCellHighlight;

	private sphereSize: number;

	/**
	 * @param volume The volume to draw; call {@link LightProbeVolumeHelper.update} after it is
	 * captured again or its probes are edited.
	 * @param size Sphere radius in world units. Default: 0.15 × the median distance between
	 * nearest probes (1 for a single probe).
	 */
	constructor( volume: LightProbeVolume, size?: number ) {

		super();
		const where = 'LightProbeVolumeHelper';
		const candidate = volume as Partial<LightProbeVolume> | null;
		if ( ! candidate || typeof candidate.isProbeActive !== 'function' || ! ( candidate.positions instanceof Float64Array ) ) {

			throw new TypeError( `${where}: volume must be a LightProbeVolume, got ${describeValue( volume )}.` );

		}

		if ( size !== undefined ) assertSize( where, size );
		this.volume = volume;
		this.name = where;
		this.probes = new ProbeSphereMesh();
		const wireframe = new LineBasicMaterial( { color: 0xaaaaaa, transparent: true, opacity: 0.3, toneMapped: false } );
		this.cells = new LineSegments( new BufferGeometry(), wireframe );
		this.cells.name = 'cells';
		this.cells.raycast = () => {}; // picking is for the probe spheres
		hideLinesFromCubeCameras( this.cells );
		this.cell = new ProbeCellHighlight( volume );
		this.add( this.probes, this.cells, this.cell );
		const edges = this.writeCells();
		this.sphereSize = size ?? ( SIZE_PER_SPACING * medianNearestDistance( volume.positions, edges, volume.count ) || 1 );
		this.probes.setProbes( volume, this.sphereSize );

	}

	/** Sphere radius in world units; setting it redraws the spheres. */
	get size(): number {

		return this.sphereSize;

	}

	set size( value: number ) {

		assertSize( 'LightProbeVolumeHelper', value );
		this.sphereSize = value;
		this.probes.setProbes( this.volume, value );

	}

	/** Whether the cells' wireframe is drawn (default true). */
	get tetrahedra(): boolean {

		return this.cells.visible;

	}

	set tetrahedra( value: boolean ) {

		this.cells.visible = value === true;

	}

	/**
	 * Highlights the cell `target` is lit from, found again before every render: for an object,
	 * the probes blended at its bounding-box centre (where `volume.add()` samples it, unless given
	 * an `anchor`) in the zone the volume used for it at the last `update()` — a tetrahedron, the
	 * hull triangle of an outer cell, a triangle or a segment, or a grid box; for a position
	 * (`{ x, y, z }` such as a `Vector3`, or `[ x, y, z ]`, read by reference), the cell there.
	 * null turns it off.
	 * @throws TypeError for another kind of target (the highlight then stays as it was).
	 */
	highlight( target: HighlightTarget ): this {

		this.cell.follow( target );
		return this;

	}

	/**
	 * Reads the volume again — positions, SH, removed probes, cells — after a capture, probe edits
	 * (`moveProbe`, `addProbe`, `removeProbe`) or SH written by hand. Not needed per frame.
	 */
	update(): this {

		this.writeCells();
		this.probes.setProbes( this.volume, this.sphereSize );
		this.cell.invalidate();
		return this;

	}

	/** Frees every geometry, material and GPU buffer of the helper (three's helper convention). */
	override dispose(): void {

		super.dispose();
		this.probes.dispose();
		this.cells.geometry.dispose();
		this.cells.material.dispose();
		this.cell.geometry.dispose();
		this.cell.material.dispose();

	}

	/** Writes the wireframe of the volume's cells; returns the edges (pairs of probe ids). */
	private writeCells(): Uint32Array {

		const volume = this.volume, positions = volume.positions;
		const edges = cellEdges( volume.interpolator, volume.zones, volume.count );
		const vertices = new Float32Array( 3 * edges.length );
		for ( let v = 0; v < edges.length; v ++ ) {

			const p = 3 * edges[ v ];
			vertices[ 3 * v ] = positions[ p ]; vertices[ 3 * v + 1 ] = positions[ p + 1 ]; vertices[ 3 * v + 2 ] = positions[ p + 2 ];

		}

		// A new geometry (three cannot resize a buffer); the old one's GPU buffers are freed.
		this.cells.geometry.dispose();
		this.cells.geometry = new BufferGeometry().setAttribute( 'position', new Float32BufferAttribute( vertices, 3 ) );
		return edges;

	}

}

/** A sphere radius: a finite number > 0. */
function assertSize( where: string, size: unknown ): void {

	assertNumber( where, 'size', size );
	if ( ! ( size > 0 ) ) throw new RangeError( `${where}: size must be > 0, got ${size}.` );

}
