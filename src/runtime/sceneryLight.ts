import { irradianceMatrices } from '../sh/irradiance.js';
import { SH_FLOATS } from '../validate.js';
import { anchorInWorld } from './anchorInWorld.js';
import { blendProbes } from './gradientBlend.js';
import type { LitObject } from './litObjects.js';
import type { ProbeField } from './ProbeField.js';
import { MAX_WEIGHTS } from './ProbeWeighting.js';

/*
 * The scenery a volume lights itself (objects seen by captures: static props, large objects)
 * during a capture: its probe light switched off, so probes see it as built; or, in a bounce pass,
 * lit by the previous pass's probes through its own lighting (per object, per vertex, per texel),
 * so the bounce off it is the light it shows at run time.
 */

const _indices = new Uint32Array( MAX_WEIGHTS );
const _weights = new Float32Array( MAX_WEIGHTS );
const _sh = new Float32Array( SH_FLOATS );
const _world = new Float64Array( 3 );

/** Switches the probe light of the scenery entries of `lit` off; returns what switches it back on. */
export function switchOffScenery( lit: readonly LitObject[] ): () => void {

	const intensities: [ { value: number }, number ][] = [];
	for ( const entry of lit ) {

		if ( entry.hidden ) continue;
		const all = entry.large ? entry.large.map( ( lighting ) => lighting.uniforms ) : [ entry.uniforms ];
		for ( const uniforms of all ) intensities.push( [ uniforms.probeVolumeIntensity, uniforms.probeVolumeIntensity.value ] );

	}

	for ( const [ uniform ] of intensities ) uniform.value = 0;
	return () => {

		for ( const [ uniform, value ] of intensities ) uniform.value = value;

	};

}

/**
 * Lights the scenery entries of `lit` from `field` (a bounce pass's frozen probes): large objects
 * sample it per vertex or texel, object-mode entries get the blend at their anchor. Zones and the
 * visibility guard are not applied (as for the bounce passes' static meshes). Returns what puts
 * the volume's own light back (resampled from the volume); nothing is left changed when it throws.
 */
export function lightScenery( lit: readonly LitObject[], field: ProbeField ): () => void {

	const undo: ( () => void )[] = [];
	const restore = () => {

		for ( let i = undo.length - 1; i >= 0; i -- ) undo[ i ]();

	};

	try {

		for ( const entry of lit ) {

			if ( entry.hidden ) continue;
			if ( entry.large ) {

				for ( const lighting of entry.large ) {

					const own = lighting.field;
					undo.push( () => {

						lighting.field = own;
						lighting.update();

					} );
					lighting.field = field;
					lighting.update();

				}

			} else {

				const matrices = entry.uniforms.probeVolumeMatrices.value, saved = matrices.slice();
				undo.push( () => matrices.set( saved ) );
				blendAtAnchor( entry, field, matrices );

			}

		}

	} catch ( error ) {

		restore();
		throw error;

	}

	return restore;

}

/**
 * The irradiance matrices of `field` blended at an entry's anchor (world position of its local anchor), by the
 * gradient formula there when the field has gradients.
 */
function blendAtAnchor( entry: LitObject, field: ProbeField, matrices: Float32Array ): void {

	entry.object.updateWorldMatrix( true, false );
	const world = anchorInWorld( entry.object, entry.anchor, _world );
	const x = world[ 0 ], y = world[ 1 ], z = world[ 2 ], interpolator = field.interpolator;
	interpolator.interpolate( x, y, z, _indices, _weights, - 1 );
	const count = interpolator.weightCount;
	irradianceMatrices( blendProbes( _indices, _weights, count, field.sh, field.gradients, field.positions, x, y, z, _sh ), matrices );

}
