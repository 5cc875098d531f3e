/**
 * Writes the hand-placed probe layouts of the Sponza and Sibenik pages (scenes/sponza.json,
 * scenes/sibenik.json) from the rules of the paper (2.1.1): a sky probe above the roof, bounce
 * probes near the floor, probes where the lighting changes (corners, under arches, in the arcades
 * of both floors, at the sun patch's edge) and colour-bleeding probes next to coloured or sunlit
 * surfaces. Coordinates come from the models' geometry (floor heights, pillar and column lines:
 * see the comments); `checkLayouts.ts` then proves every probe is in open space.
 *
 *   node --import tsx scripts/layouts/placeProbes.ts            # write both JSON files
 *   node --import tsx scripts/layouts/checkLayouts.ts            # check them
 *
 * The pages can edit a layout and export it as JSON; re-running this script overwrites such edits.
 */
import { writeFileSync } from 'node:fs';
import type { ProbeRole } from '../../src/runtime/LightProbeVolume.js';

interface Layout { name: string; positions: number[]; names: string[]; roles: ProbeRole[] }

function layout( name: string ): Layout & { add( probeName: string, role: ProbeRole, x: number, y: number, z: number ): void } {

	const result = {
		name, positions: [] as number[], names: [] as string[], roles: [] as ProbeRole[],
		add( probeName: string, role: ProbeRole, x: number, y: number, z: number ) {

			result.positions.push( x, y, z );
			result.names.push( probeName );
			result.roles.push( role );

		},
	};
	return result;

}

const side = ( z: number ) => z < 0 ? 'south' : 'north';
const end = ( x: number ) => x < 0 ? 'west' : 'east';

// Sponza (Dabrovic). Ground floor y = 0.09, first floor y = 4.82, roof y = 15.65. The open
// courtyard is |x| < 11.6, |z| < 3.18; arcades run round it to the outer walls (|x| 16.2, |z| 7.22)
// on both floors. Ground-floor pillars stand on z = ±3.0 at x = ±2.2, ±6.6 and corner pillars at
// ±11.1; the first-floor columns stand twice as close. Above the first floor the courtyard walls
// close into attic rooms, which no probe needs. The sun comes from the east, high, so the west
// half of the courtyard and its west facade are sunlit.
function sponza(): Layout {

	const l = layout( 'Sponza' );
	const floor0 = 0.09 + 0.45, floor1 = 4.82 + 0.45;
	l.add( 'sky above the roof', 'sky', 0, 17.5, 0 );
	for ( const x of [ - 10.2, - 5.5, 0, 5.5, 10.2 ] ) for ( const z of [ - 2, 2 ] ) l.add( `courtyard floor ${x} ${side( z )}`, 'bounce', x, floor0, z );
	for ( const x of [ - 8.25, - 2.75 ] ) l.add( `sun patch edge ${x}`, 'bounce', x, floor0, - 0.4 );
	for ( const x of [ - 8.7, 0, 8.7 ] ) l.add( `courtyard low ${x}`, 'fill', x, 3, 0 );
	for ( const x of [ - 8.7, 0, 8.7 ] ) l.add( `courtyard middle ${x}`, 'fill', x, 7, 0 );
	for ( const x of [ - 5.5, 5.5 ] ) l.add( `courtyard high ${x}`, 'fill', x, 11.5, 0 );
	for ( const x of [ - 10, 0, 10 ] ) l.add( `atrium opening ${x}`, 'fill', x, 15, 0 );
	// Under the ground-floor arches, between the pillars: sun on one side, shade on the other.
	for ( const z of [ - 3, 3 ] ) for ( const x of [ - 8.7, - 4.35, 0.05, 4.45, 8.8 ] ) l.add( `arch ${x} ${side( z )}`, 'fill', x, 2, z );
	for ( const x of [ - 11.6, 11.6 ] ) l.add( `${end( x )} end arch`, 'fill', x, 2, 0 );
	// Both floors of arcades: corners, floor (bounce) and vaults.
	for ( const [ y, floorName ] of [ [ floor0, 'ground' ], [ floor1, 'first' ] ] as const ) {

		for ( const x of [ - 15.5, 15.5 ] ) for ( const z of [ - 6.5, 6.5 ] ) l.add( `${floorName} floor corner ${end( x )} ${side( z )}`, 'bounce', x, y, z );
		for ( const x of [ - 8.7, 0, 8.8 ] ) for ( const z of [ - 5.3, 5.3 ] ) l.add( `${floorName} floor arcade ${x} ${side( z )}`, 'bounce', x, y, z );
		for ( const x of [ - 13.9, 13.9 ] ) l.add( `${floorName} floor ${end( x )} arcade`, 'bounce', x, y, 0 );

	}

	for ( const [ y, floorName ] of [ [ 3.5, 'ground' ], [ 8.8, 'first' ] ] as const ) {

		for ( const x of [ - 4.35, 4.45 ] ) for ( const z of [ - 5.3, 5.3 ] ) l.add( `${floorName} vault ${x} ${side( z )}`, 'fill', x, y, z );
		for ( const x of [ - 13.9, 13.9 ] ) l.add( `${floorName} vault ${end( x )}`, 'fill', x, y, 0 );

	}

	// The first-floor galleries open onto the courtyard between columns.
	for ( const z of [ - 3, 3 ] ) for ( const x of [ - 7.6, 1.15, 7.75 ] ) l.add( `gallery arch ${x} ${side( z )}`, 'fill', x, 7, z );
	// Colour bleeding: the wooden doors, the sunlit west facade, the relief, the round door.
	for ( const z of [ - 6.6, 6.6 ] ) l.add( `${side( z )} door`, 'bleed', 0, 1.5, z );
	l.add( 'sunlit west facade low', 'bleed', - 9.9, 5.5, - 1.2 );
	l.add( 'sunlit west facade middle', 'bleed', - 9.9, 9.8, 1 );
	l.add( 'sunlit west facade high', 'bleed', - 9.9, 13.5, - 0.8 );
	l.add( 'relief', 'bleed', 10, 12.5, 0 );
	l.add( 'round door', 'bleed', 15.5, 6.6, 0 );
	return l;

}

// Sibenik (Dabrovic). The nave (|z| < 3.6) has its floor at y = −15.3 and its vault at y ≈ 3–4;
// its arcade columns stand on z = ±3.95 at x = −15.8, −12.1, −8.4, −4.7, 0.0. The aisles
// (4.3 < |z| < 7.3) have their floor at −15.15 and their vaults at −8; above them are closed roof
// spaces. Steps rise east of x = 1.5 to the crossing (floor −14.16, dome up to 15.1) and the apse
// (floor −13.15 … −12.73). The rose window (stained glass) is in the west wall at y ≈ −2.6. The sun
// shines in from the north (−z) through the clerestory and aisle windows onto the aisle floors.
function sibenik(): Layout {

	const l = layout( 'Sibenik' );
	const nave = - 15.3 + 0.3, aisle = - 15.15 + 0.3;
	l.add( 'sky above the nave roof', 'sky', - 8, 8, 0 );
	for ( const x of [ - 17.5, - 10.25, - 2.3 ] ) l.add( `nave floor ${x}`, 'bounce', x, nave, 0 );
	for ( const x of [ - 13.9, - 6.55 ] ) for ( const z of [ - 2.4, 2.4 ] ) l.add( `nave floor ${x} ${side( z )}`, 'bounce', x, nave, z );
	for ( const x of [ - 17.5, - 10.25, - 2.3 ] ) for ( const z of [ - 5.8, 5.8 ] ) l.add( `${side( z )} aisle floor ${x}`, 'bounce', x, aisle, z );
	for ( const x of [ - 13.9, - 6.55 ] ) for ( const z of [ - 5.8, 5.8 ] ) l.add( `${side( z )} aisle upper ${x}`, 'fill', x, - 10, z );
	// Under the arcade arches, between nave and aisles.
	for ( const x of [ - 13.9, - 6.55 ] ) for ( const z of [ - 3.95, 3.95 ] ) l.add( `arch ${x} ${side( z )}`, 'fill', x, - 12, z );
	for ( const x of [ - 16, - 8.4, - 0.5 ] ) l.add( `nave middle ${x}`, 'fill', x, - 8, 0 );
	// At the clerestory windows, where the daylight comes in.
	for ( const x of [ - 14, - 6, 1 ] ) l.add( `clerestory ${x}`, 'fill', x, - 2, 0 );
	l.add( 'rose window', 'bleed', - 18.4, - 2.6, 0 );
	for ( const z of [ - 6.6, 6.6 ] ) l.add( `west corner ${side( z )}`, 'bounce', - 18.7, aisle, z );
	l.add( 'crossing floor', 'bounce', 6.8, - 13.6, 0 );
	l.add( 'crossing middle', 'fill', 6.8, - 6, 0 );
	l.add( 'dome', 'fill', 6.8, 6, 0 );
	for ( const z of [ - 6, 6 ] ) l.add( `transept ${side( z )}`, 'fill', 6.8, - 11, z );
	l.add( 'apse floor', 'bounce', 14.5, - 12.2, 0 );
	l.add( 'apse middle', 'fill', 14.5, - 6, 0 );
	l.add( 'altar lamp', 'bleed', 16.5, - 10.5, 0 );
	return l;

}

const json = ( l: Layout ) => {

	const rows: string[] = [];
	for ( let i = 0; i < l.names.length; i ++ ) rows.push( '\t\t' + l.positions.slice( 3 * i, 3 * i + 3 ).map( ( v ) => Math.round( v * 1000 ) / 1000 ).join( ', ' ) );
	return `{\n\t"name": ${JSON.stringify( l.name )},\n\t"positions": [\n${rows.join( ',\n' )}\n\t],\n\t"names": ${JSON.stringify( l.names, null, '\t' ).replace( /\n/g, '\n\t' )},\n\t"roles": ${JSON.stringify( l.roles )}\n}\n`;

};

const root = new URL( '../../scenes/', import.meta.url );
for ( const [ file, l ] of [ [ 'sponza.json', sponza() ], [ 'sibenik.json', sibenik() ] ] as const ) {

	l.name = `${l.names.length} probes placed with meaning`;
	writeFileSync( new URL( file, root ), json( l ) );
	console.log( `${file}: ${l.name}` );

}
