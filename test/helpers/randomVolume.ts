import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';

/**
 * A volume with every field a baked file holds: `count` seeded random probes in a 10 m cube with
 * random SH, names, all four roles, two zones (one with bounds), capture settings with a per-role
 * override, and `metadata`. The baked-file tests round-trip it.
 */
export function randomVolume( count: number, seed: number, metadata: string ): LightProbeVolume {

	const random = mulberry32( seed );
	const positions = Array.from( { length: 3 * count }, () => 10 * random() );
	const sh = Array.from( { length: 27 * count }, () => random() - 0.3 );
	const names = Array.from( { length: count }, ( _, i ) => `probe ${i}` );
	const roles = Array.from( { length: count }, ( _, i ) => ( [ 'sky', 'bounce', 'bleed', 'fill' ] as const )[ i % 4 ] );
	const zones = [
		{
			name: 'west', probes: Array.from( { length: count }, ( _, i ) => i ).filter( ( i ) => positions[ 3 * i ] < 6 ),
			bounds: { min: { x: 0, y: 0, z: 0 }, max: { x: 5, y: 10, z: 10 } },
		},
		{ name: 'all', probes: Array.from( { length: count }, ( _, i ) => i ) },
	];
	const volume = new LightProbeVolume( { positions, sh, names, roles, zones } );
	volume.captureSettings = { resolution: 64, near: 0.1, far: 500, type: 'half', solidAngle: 'exact', roles: { sky: { far: 5000 } } };
	volume.metadata = metadata;
	return volume;

}
