import type { Mesh, Object3D } from 'three';
import { gatherWorldGeometry } from '../geometry/gatherWorldGeometry.js';
import { gatherDrawnSides } from '../placement/gatherDrawnSides.js';

/** The static level's triangles, as the placement tests take them. */
export interface StaticGeometry {

	/**
	 * The roots whose subtrees hold the static level: `root` itself when nothing below it is hidden,
	 * else the largest subtrees free of hidden objects (a mesh with a hidden object below it stands
	 * for itself alone, as a childless copy placed where it is drawn).
	 */
	roots: Object3D[];

	/** 9 floats per triangle, world space (`gatherWorldGeometry` over every root, in order). */
	triangles: Float64Array;

	/** Per triangle: the side its material draws (`gatherDrawnSides`: 1 front, −1 back, 0 both). */
	sides: Int8Array;

}

/**
 * The triangles under `root` without those of `hidden` objects (and everything below them) — what
 * a capture that hides the level's moving objects sees, for the open-space tests of probe and fit
 * point placement. Helpers (objects whose `type` ends in `Helper`) are left out, as
 * `gatherWorldGeometry` leaves them.
 */
export function gatherStaticGeometry( root: Object3D, hidden: Iterable<Object3D> = [] ): StaticGeometry {

	const skipped = new Set<Object3D>( hidden );
	root.updateWorldMatrix( true, true );
	// Objects with a hidden object or a helper somewhere below them (or which are one).
	const tainted = new Set<Object3D>();
	root.traverse( ( node ) => {

		if ( ! skipped.has( node ) && ! isHelper( node ) ) return;
		for ( let up: Object3D | null = node; up !== null && ! tainted.has( up ); up = up === root ? null : up.parent ) tainted.add( up );

	} );

	const roots: Object3D[] = [];
	const visit = ( node: Object3D ): void => {

		if ( skipped.has( node ) || isHelper( node ) ) return;
		if ( ! tainted.has( node ) ) {

			roots.push( node );
			return;

		}

		if ( ( node as Mesh ).isMesh === true ) roots.push( alone( node as Mesh ) );
		for ( const child of node.children ) visit( child );

	};

	visit( root );
	const parts = roots.map( ( part ) => ( {
		triangles: gatherWorldGeometry( part ).triangles, sides: gatherDrawnSides( part ).triangleSides,
	} ) );
	const triangles = new Float64Array( parts.reduce( ( sum, part ) => sum + part.triangles.length, 0 ) );
	const sides = new Int8Array( triangles.length / 9 );
	let offset = 0;
	for ( const part of parts ) {

		triangles.set( part.triangles, 9 * offset );
		sides.set( part.sides, offset );
		offset += part.sides.length;

	}

	return { roots, triangles, sides };

}

function isHelper( node: Object3D ): boolean {

	return typeof node.type === 'string' && node.type.endsWith( 'Helper' );

}

/** A childless copy of a mesh drawn where the mesh is (its world matrix fixed, so gathering it alone reads the same triangles). */
function alone( mesh: Mesh ): Mesh {

	const copy = mesh.clone( false );
	copy.matrixAutoUpdate = false;
	copy.matrix.copy( mesh.matrixWorld );
	copy.matrixWorld.copy( mesh.matrixWorld );
	return copy;

}
