// delaunay3.cpp timed by the process's CPU clock instead of the wall clock, for
// bench/tetrahedralizePaired.ts --cpu: on an oversubscribed machine the wall clock also counts the
// time the process waited for a core, which CPU time does not.
//
// Usage: delaunay3Cpu POINTS_FILE [REPEATS]
//   POINTS_FILE holds little-endian float64 x, y, z per point.
// Prints one JSON object: the CPU seconds each triangulation took (timed here, file I/O excluded),
// the number of finite cells and vertices, the volume of the finite cells added up (the convex
// hull's volume, to cross-check ours) and whether CGAL's is_valid() passed on the last one.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>

#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Delaunay_triangulation_3<Kernel> Delaunay;
typedef Kernel::Point_3 Point;

int main( int argc, char ** argv ) {

	if ( argc < 2 ) {

		std::fprintf( stderr, "usage: %s POINTS_FILE [REPEATS]\n", argv[ 0 ] );
		return 2;

	}

	const int repeats = argc > 2 ? std::atoi( argv[ 2 ] ) : 1;

	std::ifstream file( argv[ 1 ], std::ios::binary | std::ios::ate );
	if ( ! file ) {

		std::fprintf( stderr, "cannot open %s\n", argv[ 1 ] );
		return 1;

	}

	const std::streamsize bytes = file.tellg();
	file.seekg( 0 );
	std::vector<double> xyz( bytes / sizeof( double ) );
	file.read( reinterpret_cast<char *>( xyz.data() ), xyz.size() * sizeof( double ) );

	std::vector<Point> points;
	points.reserve( xyz.size() / 3 );
	for ( size_t i = 0; i + 2 < xyz.size(); i += 3 ) points.emplace_back( xyz[ i ], xyz[ i + 1 ], xyz[ i + 2 ] );

	std::printf( "{\"seconds\":[" );

	Delaunay triangulation;
	for ( int run = 0; run < repeats; run ++ ) {

		triangulation.clear();
		timespec start, end;
		clock_gettime( CLOCK_PROCESS_CPUTIME_ID, &start );
		triangulation.insert( points.begin(), points.end() ); // spatially sorts the range first
		clock_gettime( CLOCK_PROCESS_CPUTIME_ID, &end );
		std::printf( "%s%.9f", run ? "," : "", ( end.tv_sec - start.tv_sec ) + 1e-9 * ( end.tv_nsec - start.tv_nsec ) );

	}

	double volume = 0;
	for ( auto cell = triangulation.finite_cells_begin(); cell != triangulation.finite_cells_end(); ++ cell ) {

		volume += triangulation.tetrahedron( cell ).volume();

	}

	std::printf( "],\"cells\":%zu,\"vertices\":%zu,\"volume\":%.17g,\"valid\":%s}\n",
		triangulation.number_of_finite_cells(), triangulation.number_of_vertices(), volume,
		triangulation.is_valid() ? "true" : "false" );

	return 0;

}
