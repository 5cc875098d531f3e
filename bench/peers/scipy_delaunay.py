"""
Child process of the Qhull peer (see scipyQhull.ts): scipy.spatial.Delaunay (Qhull) on the points
of a float64 xyz file, several times in one process, timed inside Python (file I/O excluded).
Usage: python3 scipy_delaunay.py POINTS_FILE REPEATS
Prints JSON: seconds per run, simplex count, flat count (|volume| <= 1e-12 of the box), the
unsigned volumes added up, and the versions. (Qhull does not orient its simplices consistently,
so there is no "inverted" count.)
"""

import json
import sys
import time

import numpy as np
import scipy
from scipy.spatial import Delaunay

points = np.fromfile( sys.argv[ 1 ], dtype = '<f8' ).reshape( - 1, 3 )
repeats = int( sys.argv[ 2 ] )

seconds = []
triangulation = None
for _ in range( repeats ):
	start = time.perf_counter()
	triangulation = Delaunay( points )
	seconds.append( time.perf_counter() - start )

simplices = triangulation.simplices
p = points[ simplices ]
determinants = np.einsum( 'ij,ij->i', p[ :, 1 ] - p[ :, 0 ], np.cross( p[ :, 2 ] - p[ :, 0 ], p[ :, 3 ] - p[ :, 0 ] ) )
box = float( np.prod( points.max( axis = 0 ) - points.min( axis = 0 ) ) )
flat = int( np.count_nonzero( np.abs( determinants ) / 6 <= 1e-12 * box ) )

print( json.dumps( {
	'seconds': seconds,
	'tetrahedra': int( len( simplices ) ),
	'flat': flat,
	'volume': float( np.abs( determinants ).sum() / 6 ),
	'coplanar': int( len( triangulation.coplanar ) ),
	'scipy': scipy.__version__,
	'numpy': np.__version__,
} ) )
