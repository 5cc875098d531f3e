/**
 * Child process of the delaunay-triangulate peer (see delaunayTriangulate.ts), so that the parent
 * can kill it at its time limit. Usage: node --import tsx delaunayTriangulateWorker.ts POINTS_FILE
 * Prints JSON: milliseconds for the triangulation alone, tetrahedron count, flat and inverted
 * counts, and the volumes added up (unsigned, to compare with the hull's).
 */

import triangulate from 'delaunay-triangulate';
import { readPointsFile } from '../datasets.js';
import { orientation, signedVolume } from '../geometry.js';

const points = readPointsFile( process.argv[ 2 ] );
const coordinates: number[][] = [];
for ( let i = 0; i < points.length; i += 3 ) coordinates.push( [ points[ i ], points[ i + 1 ], points[ i + 2 ] ] );

const start = performance.now();
const tetrahedra = triangulate( coordinates );
const ms = performance.now() - start;

// Exact orientation of every tetrahedron. The library orients consistently (negatively, in our
// convention), so "inverted" counts those against the orientation most of its output has.
let positive = 0, negative = 0, flat = 0, volume = 0;
for ( const [ a, b, c, d ] of tetrahedra ) {

	const sign = orientation( points, a, b, c, d );
	if ( sign > 0 ) positive ++;
	else if ( sign < 0 ) negative ++;
	else flat ++;
	volume += Math.abs( signedVolume( points, a, b, c, d ) );

}

process.stdout.write( JSON.stringify( { ms, tetrahedra: tetrahedra.length, flat, inverted: Math.min( positive, negative ), volume } ) + '\n' );
