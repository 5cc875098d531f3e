/**
 * Checks the probe layouts and character paths of the Sponza and Sibenik pages against the real
 * geometry (the OBJ files of the asset folder), in plain Node:
 *
 * - every probe is in open space: of 64 rays cast from it in all directions, no more than 10 % first
 *   meet the back side of a surface (a point inside a closed solid meets only back sides) and no
 *   more than 60 % cross an odd number of surfaces (ray parity); and it is at least 0.25 m from
 *   the nearest surface. A probe whose rays mostly escape is outside the building: allowed for
 *   the sky probe, reported for grid probes, an error otherwise. A regular grid cannot step round
 *   geometry, so its probes inside geometry are counted and reported, not failed;
 * - the layout tetrahedralizes, and every point of the character's path (at half its height)
 *   lies in a tetrahedron (`TetrahedralMesh.locate`);
 * - the path runs on the floor, clear of pillars and walls.
 *
 *   node --import tsx scripts/layouts/checkLayouts.ts [sponza|sibenik] [--verbose] [--self-test]
 *
 * `--self-test` first compares the BVH's ray hits with three's Raycaster on the loaded meshes.
 * Exits non-zero when a check fails. Assets: $CAPTURE_LIGHTING_ASSETS or ../shared/assets.
 */
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import * as THREE from 'three';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import type { ProbeLayout } from '../../scenes/layout.js';
import { examinePoint, loadTriangles, sphereDirections, TriangleBVH, type PointReport } from './meshQuery.js';

const root = fileURLToPath( new URL( '../..', import.meta.url ) );
const assets = resolve( process.env.CAPTURE_LIGHTING_ASSETS ?? resolve( root, '../shared/assets' ) );
const args = process.argv.slice( 2 );
const verbose = args.includes( '--verbose' );
const only = args.filter( ( a ) => ! a.startsWith( '--' ) );

/** Thresholds (see the file comment). */
const MAX_BACK = 0.1, MAX_ODD = 0.6, MIN_CLEARANCE = 0.25, MAX_ESCAPE = 0.5, PATH_CLEARANCE = 0.3;

interface SceneToCheck { name: string; obj: string; layouts: ProbeLayout[]; path: THREE.Curve<THREE.Vector3>; characterHeight: number }

const scenes: SceneToCheck[] = [];
if ( only.length === 0 || only.includes( 'sponza' ) ) {

	const m = await import( '../../scenes/sponza.js' );
	scenes.push( { name: 'sponza', obj: 'sponza/sponza.obj', layouts: m.sponzaLayouts, path: m.sponzaPath, characterHeight: m.SPONZA_CHARACTER_HEIGHT } );

}

if ( only.length === 0 || only.includes( 'sibenik' ) ) {

	const m = await import( '../../scenes/sibenik.js' );
	scenes.push( { name: 'sibenik', obj: 'sibenik/sibenik.obj', layouts: m.sibenikLayouts, path: m.sibenikPath, characterHeight: m.SIBENIK_CHARACTER_HEIGHT } );

}

let failures = 0;
const fail = ( message: string ) => { failures ++; console.log( `  FAIL ${message}` ); };
const f2 = ( v: number ) => v.toFixed( 2 );

for ( const scene of scenes ) {

	const start = performance.now();
	const soup = loadTriangles( resolve( assets, scene.obj ) );
	const bvh = new TriangleBVH( soup );
	console.log( `\n${scene.name}: ${soup.positions.length / 9} triangles, ${soup.materials.length} materials (${( performance.now() - start ).toFixed( 0 )} ms to load)` );
	if ( args.includes( '--self-test' ) ) selfTest( bvh );

	for ( const layout of scene.layouts ) {

		const count = layout.positions.length / 3;
		console.log( `\n layout "${layout.name}": ${count} probes${layout.grid ? ` (grid ${layout.grid.counts.join( '×' )})` : ''}` );
		let outside = 0, worst = Infinity, gridProblems = 0;
		for ( let i = 0; i < count; i ++ ) {

			const [ x, y, z ] = layout.positions.slice( 3 * i, 3 * i + 3 );
			const name = layout.names?.[ i ] ?? `probe ${i}`, role = layout.roles?.[ i ] ?? 'fill';
			const r = examinePoint( bvh, x, y, z );
			worst = Math.min( worst, r.clearance );
			const where = `${i} "${name}" (${role}) at ${f2( x )}, ${f2( y )}, ${f2( z )}`;
			const seen = describe( r );
			// A regular grid cannot step round geometry: its bad probes are counted, not failed.
			const problem = layout.grid ? ( message: string ) => { gridProblems ++; if ( verbose ) console.log( `  grid probe ${message}` ); } : fail;
			if ( r.backFraction > MAX_BACK || r.oddFraction > MAX_ODD ) problem( `${where} is inside geometry: ${seen}` );
			else if ( r.clearance < MIN_CLEARANCE ) problem( `${where} is ${f2( r.clearance )} m from ${r.nearestMaterial} (< ${MIN_CLEARANCE}): ${seen}` );
			else if ( r.escapeFraction > MAX_ESCAPE && role !== 'sky' ) {

				outside ++;
				if ( ! layout.grid ) fail( `${where} is outside the building: ${seen}` );
				else if ( verbose ) console.log( `  outside ${where}: ${seen}` );

			} else if ( verbose ) console.log( `  ok ${where}: ${seen}` );

		}

		console.log( `  probes: all checked; nearest surface ${f2( worst )} m${outside ? `; ${outside} grid probes outside the building (in open air)` : ''}` );
		if ( gridProblems ) console.log( `  WARNING ${gridProblems} grid probes are inside geometry or closer than ${MIN_CLEARANCE} m to it (a regular grid cannot avoid them; --verbose lists them)` );

		// The tetrahedralization and the character's walk inside it.
		let mesh: TetrahedralMesh;
		try {

			mesh = new TetrahedralMesh( layout.positions );

		} catch ( error ) {

			fail( `tetrahedralization: ${( error as Error ).message}` );
			continue;

		}

		let outsideHull = 0, hint = - 1;
		const samples = 400, p = new THREE.Vector3();
		for ( let s = 0; s < samples; s ++ ) {

			scene.path.getPointAt( s / samples, p );
			hint = mesh.locate( p.x, p.y + scene.characterHeight / 2, p.z, hint );
			if ( hint < 0 ) { outsideHull ++; hint = - 1; if ( outsideHull <= 3 ) fail( `path point ${f2( p.x )}, ${f2( p.z )} is outside the tetrahedra` ); }

		}

		console.log( `  tetrahedra: ${mesh.cellCount}${mesh.duplicates.length ? `, ${mesh.duplicates.length} duplicate probes merged` : ''}; path in a tetrahedron at ${samples - outsideHull} / ${samples} points` );

	}

	checkPath( scene, bvh );

}

console.log( failures === 0 ? '\nall checks passed' : `\n${failures} check(s) failed` );
process.exit( failures === 0 ? 0 : 1 );

function describe( r: PointReport ): string {

	return `nearest ${f2( r.clearance )} m (${r.nearestMaterial}), back ${( 100 * r.backFraction ).toFixed( 0 )} %, odd ${( 100 * r.oddFraction ).toFixed( 0 )} %, escape ${( 100 * r.escapeFraction ).toFixed( 0 )} %`;

}

/** The path: on a floor (within 0.2 below), clear of walls and pillars, no wall between samples. */
function checkPath( scene: SceneToCheck, bvh: TriangleBVH ): void {

	const samples = 400, h = scene.characterHeight;
	const p = new THREE.Vector3(), q = new THREE.Vector3();
	let nearest = Infinity, problems = 0;
	for ( let s = 0; s < samples; s ++ ) {

		scene.path.getPointAt( s / samples, p );
		scene.path.getPointAt( ( s + 1 ) / samples, q );
		const floor = bvh.raycastAll( [ p.x, p.y + 0.3, p.z ], [ 0, - 1, 0 ] )[ 0 ];
		if ( ! floor || floor.t > 0.5 ) { if ( problems ++ < 3 ) fail( `path point ${f2( p.x )}, ${f2( p.y )}, ${f2( p.z )} is not on a floor (${floor ? f2( 0.3 - floor.t ) + ' m above the surface below' : 'nothing below'})` ); continue; }
		for ( const lift of [ 0.5 * h, 0.9 * h ] ) {

			const d = bvh.nearest( p.x, p.y + lift, p.z ).distance;
			nearest = Math.min( nearest, d );
			if ( d < PATH_CLEARANCE && problems ++ < 3 ) fail( `path point ${f2( p.x )}, ${f2( p.z )} at +${f2( lift )} m is ${f2( d )} m from a surface` );

		}

		const direction = q.clone().sub( p );
		const length = direction.length();
		const hit = bvh.raycastAll( [ p.x, p.y + 0.5 * h, p.z ], direction.normalize().toArray() )[ 0 ];
		if ( hit && hit.t < length && problems ++ < 3 ) fail( `the path crosses a surface after ${f2( p.x )}, ${f2( p.z )}` );

	}

	console.log( `\n path: ${samples} samples, length ${f2( scene.path.getLength() )} m, nearest surface ${f2( nearest )} m${problems ? `, ${problems} problems` : ', on the floor and clear'}` );

}

/** The BVH against three's Raycaster on the loaded meshes: same first hit along 200 rays. */
function selfTest( bvh: TriangleBVH ): void {

	const raycaster = new THREE.Raycaster();
	const meshes: THREE.Mesh[] = [];
	bvh.soup.object.traverse( ( child ) => {

		if ( ( child as THREE.Mesh ).isMesh ) {

			const m = child as THREE.Mesh;
			( Array.isArray( m.material ) ? m.material : [ m.material ] ).forEach( ( material ) => { material.side = THREE.DoubleSide; } );
			meshes.push( m );

		}

	} );
	const box = new THREE.Box3().setFromObject( bvh.soup.object );
	const directions = sphereDirections( 200 );
	let worst = 0;
	for ( let i = 0; i < directions.length; i ++ ) {

		const origin = new THREE.Vector3(
			THREE.MathUtils.lerp( box.min.x, box.max.x, ( i * 0.618 ) % 1 ),
			THREE.MathUtils.lerp( box.min.y, box.max.y, ( i * 0.382 ) % 1 ),
			THREE.MathUtils.lerp( box.min.z, box.max.z, ( i * 0.271 ) % 1 )
		);
		raycaster.set( origin, new THREE.Vector3( ...directions[ i ] ) );
		const three = raycaster.intersectObjects( meshes, false )[ 0 ]?.distance ?? Infinity;
		const ours = bvh.raycastAll( origin.toArray(), directions[ i ] )[ 0 ]?.t ?? Infinity;
		const error = three === ours ? 0 : Math.abs( three - ours );
		worst = Math.max( worst, error );

	}

	console.log( `  self-test: BVH vs three's Raycaster, 200 rays, largest first-hit difference ${worst.toExponential( 1 )} m` );
	if ( worst > 1e-4 ) fail( 'the BVH disagrees with three\'s Raycaster' );

}
