/**
 * Open space for probe candidates (issue 14, item 4), through the candidate step `placeProbes` and
 * `LightProbeVolume.fromScene` share (`placeCandidates` over `gatherStaticGeometry`), judged
 * against the scenes' analytic geometry: inside a closed prop is rejected, the inside of a closed
 * room drawn from inside (scenes/basic.ts) and of a room of single-sided quads with a missing wall
 * are kept, every candidate keeps `clearance` from every surface, and hidden objects (a
 * character) neither block nor reject candidates. No GPU: nothing is captured.
 */
import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { placeCandidates } from '../../src/runtime/probeCandidates.js';
import { gatherStaticGeometry } from '../../src/runtime/staticGeometry.js';
import { placeProbes } from '../../src/runtime/placeProbes.js';
import { createBasicRoom } from '../../scenes/basic.js';
import { boxDistance } from '../placement/helpers.js';
import { blockMesh, cornellBox, insideBlock, type Block } from '../placement/openScenes.js';

/** Signed distance from a point to a turned block's surface (negative inside). */
function blockDistance( block: Block, x: number, y: number, z: number ): number {

	const dx = x - block.centre[ 0 ], dz = z - block.centre[ 2 ];
	const c = Math.cos( block.angle ), s = Math.sin( block.angle );
	return boxDistance( c * dx - s * dz, y, s * dx + c * dz, 0, block.centre[ 1 ], 0, ...block.half );

}

function points( positions: Float64Array ): number[][] {

	const out: number[][] = [];
	for ( let i = 0; i < positions.length; i += 3 ) out.push( [ positions[ i ], positions[ i + 1 ], positions[ i + 2 ] ] );
	return out;

}

describe( 'probe candidates in open space', () => {

	// The Basic room (a closed BackSide box, 4 × 3 × 4) with a closed prop on its floor (FrontSide, outward normals).
	const prop: Block = { centre: [ 0.6, 0.5, - 0.5 ], half: [ 0.5, 0.5, 0.5 ], angle: 0 };
	const basicWithProp = () => {

		const scene = new THREE.Scene();
		scene.add( createBasicRoom().room, blockMesh( prop, new THREE.MeshStandardMaterial() ) );
		return scene;

	};

	it( 'the Basic room with a closed prop: the prop\'s inside is rejected, the room\'s air is kept, a quarter spacing clear of every surface', () => {

		const scene = basicWithProp();
		const placed = placeCandidates( 'test', gatherStaticGeometry( scene ), { candidates: 256, reachableFrom: Float64Array.of( 0, 1.6, 0 ) } );
		const kept = points( placed.positions );
		// The prop is 1 m³ of the room's 48: grid centres inside it are rejected as inside geometry.
		expect( placed.rejected.insideGeometry ).toBeGreaterThan( 0 );
		expect( placed.rejected.unreachable ).toBe( 0 );
		expect( placed.clearance ).toBeCloseTo( placed.spacing / 4, 12 );
		const bulb = [ 0.2, 2.1, 0.3 ];
		for ( const [ x, y, z ] of kept ) {

			expect( - boxDistance( x, y, z, 0, 1.5, 0, 2, 1.5, 2 ) ).toBeGreaterThanOrEqual( placed.clearance - 1e-9 );
			expect( blockDistance( prop, x, y, z ) ).toBeGreaterThanOrEqual( placed.clearance - 1e-9 );
			// The bulb's tessellation lies within 0.0015 of its sphere (radius 0.08).
			expect( Math.hypot( x - bulb[ 0 ], y - bulb[ 1 ], z - bulb[ 2 ] ) - 0.08 ).toBeGreaterThanOrEqual( placed.clearance - 0.002 );

		}

		// Most of the room is open: of the grid centres (7 × 5 × 7 = 245 at the default spacing), all
		// but those inside the prop or within a quarter spacing of a surface are kept.
		const spacing = placed.spacing;
		let open = 0;
		for ( const [ x, y, z ] of points( cellGrid( [ - 2, 0, - 2, 2, 3, 2 ], spacing ) ) ) {

			const clear = - boxDistance( x, y, z, 0, 1.5, 0, 2, 1.5, 2 ) >= placed.clearance
				&& blockDistance( prop, x, y, z ) >= placed.clearance
				&& Math.hypot( x - bulb[ 0 ], y - bulb[ 1 ], z - bulb[ 2 ] ) - 0.08 >= placed.clearance;
			if ( clear ) open ++;

		}

		expect( open ).toBeGreaterThan( 150 );
		expect( kept.length ).toBeGreaterThanOrEqual( open );

	} );

	it( 'a room of single-sided quads with its front wall missing (the Cornell box): open inside, its closed blocks rejected', () => {

		const { root, blocks } = cornellBox( THREE.FrontSide );
		const scene = new THREE.Scene().add( root );
		const placed = placeCandidates( 'test', gatherStaticGeometry( scene ), { candidates: 512, spacing: 0.25 } );
		const kept = points( placed.positions );
		expect( placed.clearance ).toBe( 0.0625 );
		// 8 × 8 × 8 cells of 0.25 over the 2 × 2 × 2 box: 512 centres; the blocks hold 0.648 m³, about 41
		// cells, those deeper than the clearance inside geometry (measured: 26; the others are near a surface).
		expect( placed.rejected.insideGeometry ).toBeGreaterThan( 15 );
		// The open room: 1/16 (the clearance) or more from the five quads, the lamp quad (y = 1.99) and the blocks.
		const clear = ( [ x, y, z ]: number[] ) => - boxDistance( x, y, z, 0, 1, 0, 1, 1, 1 ) >= 0.0625 - 1e-9
			&& boxDistance( x, y, z, 0, 1.99, 0, 0.25, 0, 0.25 ) >= 0.0625 - 1e-9
			&& blocks.every( ( block ) => blockDistance( block, x, y, z ) >= 0.0625 - 1e-9 );
		for ( const p of kept ) {

			expect( clear( p ) ).toBe( true );
			expect( blocks.some( ( block ) => insideBlock( block, p[ 0 ], p[ 1 ], p[ 2 ] ) ) ).toBe( false );

		}

		// Every open grid centre is kept, or was thinned away for a kept candidate within half a spacing
		// (a block's or the lamp's vertex moved off it): the missing wall lets no quad's undrawn side vote "inside".
		const open = points( cellGrid( [ - 1, 0, - 1, 1, 2, 1 ], 0.25 ) ).filter( clear );
		expect( open.length ).toBeGreaterThan( 300 );
		for ( const [ x, y, z ] of open ) {

			const nearest = Math.min( ...kept.map( ( [ a, b, c ] ) => Math.hypot( a - x, b - y, c - z ) ) );
			expect( nearest ).toBeLessThan( 0.125 );

		}

	} );

	it( 'clearance: every candidate at least that far from every surface, and a larger clearance keeps fewer', () => {

		const scene = basicWithProp();
		const geometry = gatherStaticGeometry( scene );
		const near = placeCandidates( 'test', geometry, { candidates: 256, clearance: 0.1 } );
		const far = placeCandidates( 'test', geometry, { candidates: 256, clearance: 0.5 } );
		expect( far.positions.length ).toBeLessThan( near.positions.length );
		for ( const [ placed, clearance ] of [ [ near, 0.1 ], [ far, 0.5 ] ] as const ) {

			for ( const [ x, y, z ] of points( placed.positions ) ) {

				expect( - boxDistance( x, y, z, 0, 1.5, 0, 2, 1.5, 2 ) ).toBeGreaterThanOrEqual( clearance - 1e-9 );
				expect( blockDistance( prop, x, y, z ) ).toBeGreaterThanOrEqual( clearance - 1e-9 );

			}

		}

		// At 0.5 the open air is the room shrunk by 0.5 each side (3 × 2 × 3) less the prop grown by 0.5:
		// candidates remain there.
		expect( far.positions.length / 3 ).toBeGreaterThan( 20 );

	} );

	it( 'hidden objects (a character standing in the room) neither reject candidates nor count as geometry', () => {

		const scene = basicWithProp();
		// A closed box "character" 0.6 × 1.2 × 0.6 at the room's centre.
		const character = new THREE.Mesh( new THREE.BoxGeometry( 0.6, 1.2, 0.6 ), new THREE.MeshStandardMaterial() );
		character.position.set( - 0.8, 0.6, 0.8 );
		scene.add( character );
		const withCharacter = placeCandidates( 'test', gatherStaticGeometry( scene ), { candidates: 256 } );
		const hidden = placeCandidates( 'test', gatherStaticGeometry( scene, [ character ] ), { candidates: 256 } );
		const withoutCharacter = placeCandidates( 'test', gatherStaticGeometry( basicWithProp() ), { candidates: 256 } );
		expect( Array.from( hidden.positions ) ).toEqual( Array.from( withoutCharacter.positions ) );
		const inCharacter = ( [ x, y, z ]: number[] ) => boxDistance( x, y, z, - 0.8, 0.6, 0.8, 0.3, 0.6, 0.3 ) < 0;
		expect( points( hidden.positions ).filter( inCharacter ).length ).toBeGreaterThan( 0 );
		expect( points( withCharacter.positions ).filter( inCharacter ).length ).toBe( 0 );

	} );

	it( 'gatherStaticGeometry: a mesh with a hidden child keeps its own triangles, a helper is left out', () => {

		const scene = new THREE.Scene();
		const table = new THREE.Mesh( new THREE.BoxGeometry( 1, 1, 1 ), new THREE.MeshStandardMaterial() );
		table.position.set( 3, 0, 0 );
		const cup = new THREE.Mesh( new THREE.BoxGeometry( 0.1, 0.1, 0.1 ), new THREE.MeshStandardMaterial() );
		cup.position.set( 0, 0.55, 0 );
		table.add( cup );
		scene.add( table, new THREE.AxesHelper() );
		const all = gatherStaticGeometry( scene );
		const withoutCup = gatherStaticGeometry( scene, [ cup ] );
		expect( all.triangles.length / 9 ).toBe( 24 );
		expect( withoutCup.triangles.length / 9 ).toBe( 12 );
		expect( withoutCup.sides.length ).toBe( 12 );
		// The table's own triangles where it is drawn: x in [ 2.5, 3.5 ].
		for ( let i = 0; i < withoutCup.triangles.length; i += 3 ) {

			expect( Math.abs( withoutCup.triangles[ i ] - 3 ) ).toBeCloseTo( 0.5, 12 );

		}


	} );

	it( 'placeProbes names a bad clearance', async () => {

		const renderer = { isWebGLRenderer: true, getContext() {} } as unknown as THREE.WebGLRenderer;
		await expect( placeProbes( renderer, basicWithProp(), { count: 8, clearance: - 1 } ) ).rejects.toThrow( /^placeProbes: options.clearance must be ≥ 0, got -1/ );
		await expect( placeProbes( renderer, basicWithProp(), { count: 8, clearance: NaN } ) ).rejects.toThrow( /^placeProbes: options.clearance must be a finite number/ );
		await expect( placeProbes( renderer, basicWithProp(), { count: 400, clearance: 1.4 } ) )
			.rejects.toThrow( /^placeProbes: only \d+ of \d+ candidates are in open space .*fewer than options.count \(400\); pass a smaller options.spacing or options.clearance/ );

	} );

} );

/** Cell centres of a grid over a box, as `placeCandidates` lays them out. */
function cellGrid( box: number[], spacing: number ): Float64Array {

	const counts = [ 0, 1, 2 ].map( ( a ) => Math.max( 2, Math.round( ( box[ 3 + a ] - box[ a ] ) / spacing ) ) );
	const out: number[] = [];
	for ( let k = 0; k < counts[ 2 ]; k ++ ) for ( let j = 0; j < counts[ 1 ]; j ++ ) for ( let i = 0; i < counts[ 0 ]; i ++ ) {

		const at = [ i, j, k ].map( ( n, a ) => box[ a ] + ( n + 0.5 ) * ( box[ 3 + a ] - box[ a ] ) / counts[ a ] );
		out.push( ...at );

	}

	return Float64Array.from( out );

}
