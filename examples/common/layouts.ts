import type { ProbeZoneDefinition } from 'three-capture-lighting';
import type { ProbeLayout } from '@scenes/layout.js';

export type { ProbeLayout };

/** A copy of the layout without the probes named in `names` (the query's `drop`). */
export function dropProbes( layout: ProbeLayout, names: string[] ): ProbeLayout {

	const keep = ( _: unknown, i: number ) => ! names.includes( layout.names?.[ i ] ?? '' );
	const positions = layout.positions.filter( ( _, k ) => keep( null, Math.floor( k / 3 ) ) );
	if ( positions.length === layout.positions.length ) {

		return { ...layout, positions: layout.positions.slice(), names: layout.names?.slice(), roles: layout.roles?.slice() };

	}

	return { name: layout.name, positions, names: layout.names?.filter( keep ), roles: layout.roles?.filter( keep ) };

}

/** A layout's lighting zones (boxes as arrays in the scene files) as `LightProbeVolume` takes them. */
export function zonesOf( layout: ProbeLayout ): ProbeZoneDefinition[] | undefined {

	return layout.zones?.map( ( { name, probes, bounds: { min, max } } ) => ( {
		name, probes, bounds: { min: { x: min[ 0 ], y: min[ 1 ], z: min[ 2 ] }, max: { x: max[ 0 ], y: max[ 1 ], z: max[ 2 ] } },
	} ) );

}
