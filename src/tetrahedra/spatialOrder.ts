/**
 * Insertion order for incremental Delaunay: a biased randomized insertion order (BRIO, Amenta,
 * Choi & Rote 2003) whose rounds are each sorted along a 3D Hilbert curve. Randomness between
 * rounds keeps the expected work optimal; the curve inside a round keeps consecutive points close,
 * so the point-location walk from the previous insertion is a few steps long.
 */

const HILBERT_BITS = 10;

/** Deterministic 32-bit PRNG (mulberry32); the same seed gives the same order on every machine. */
export function mulberry32( seed: number ): () => number {

	let a = seed >>> 0;
	return function () {

		a = ( a + 0x6D2B79F5 ) >>> 0;
		let t = a;
		t = Math.imul( t ^ ( t >>> 15 ), t | 1 );
		t ^= t + Math.imul( t ^ ( t >>> 7 ), t | 61 );
		return ( ( t ^ ( t >>> 14 ) ) >>> 0 ) / 4294967296;

	};

}

/**
 * Hilbert index of integer coordinates in [0, 2^bits) (Skilling, "Programming the Hilbert curve", 2004).
 */
export function hilbertIndex3( x: number, y: number, z: number, bits: number ): number {

	// Scalars X0, X1, X2 instead of an array (no allocation per point), and masks instead of
	// branches: the tested bits are random, so branches would be mispredicted half of the time.
	let X0 = x, X1 = y, X2 = z;
	// Inverse undo of the Gray code, from the top bit down.
	for ( let b = bits - 1; b > 0; b -- ) {

		const p = ( 1 << b ) - 1;
		// For each axis i: bit b set → invert the low bits of X0; clear → exchange them between X0 and X[ i ].
		X0 ^= p & - ( ( X0 >>> b ) & 1 ); // i = 0: the exchange with itself does nothing
		let m = - ( ( X1 >>> b ) & 1 );
		let t = ( X0 ^ X1 ) & p & ~ m;
		X0 ^= ( p & m ) | t;
		X1 ^= t;
		m = - ( ( X2 >>> b ) & 1 );
		t = ( X0 ^ X2 ) & p & ~ m;
		X0 ^= ( p & m ) | t;
		X2 ^= t;

	}

	// Gray encode.
	X1 ^= X0;
	X2 ^= X1;
	let t = 0;
	for ( let b = bits - 1; b > 0; b -- ) t ^= ( ( 1 << b ) - 1 ) & - ( ( X2 >>> b ) & 1 );

	X0 ^= t; X1 ^= t; X2 ^= t;

	// Interleave the transposed bits into one index, most significant first: bit b of X0, X1, X2 goes
	// to bit 3b + 2, 3b + 1, 3b (by spreading each over every third bit when the index fits 30 bits).
	if ( bits <= 10 ) return ( spreadBits( X0 ) << 2 ) | ( spreadBits( X1 ) << 1 ) | spreadBits( X2 );
	let index = 0;
	for ( let b = bits - 1; b >= 0; b -- ) {

		index = index * 8 + ( ( ( X0 >>> b ) & 1 ) << 2 ) + ( ( ( X1 >>> b ) & 1 ) << 1 ) + ( ( X2 >>> b ) & 1 );

	}

	return index;

}

/** The low 10 bits of x moved to bits 0, 3, 6, … 27. */
function spreadBits( x: number ): number {

	x &= 0x3FF;
	x = ( x | ( x << 16 ) ) & 0x30000FF;
	x = ( x | ( x << 8 ) ) & 0x300F00F;
	x = ( x | ( x << 4 ) ) & 0x30C30C3;
	return ( x | ( x << 2 ) ) & 0x9249249;

}

/**
 * Returns `indices` reordered for insertion: shuffled with `seed`, split into rounds of doubling
 * size, each round sorted along a Hilbert curve over the points' bounding box.
 */
export function insertionOrder( points: Float64Array, indices: Uint32Array, seed = 1 ): Uint32Array {

	const n = indices.length;
	const order = indices.slice();
	const random = mulberry32( seed );
	for ( let i = n - 1; i > 0; i -- ) {

		const j = Math.floor( random() * ( i + 1 ) );
		const t = order[ i ]; order[ i ] = order[ j ]; order[ j ] = t;

	}

	let minX = Infinity, minY = Infinity, minZ = Infinity, maxX = - Infinity, maxY = - Infinity, maxZ = - Infinity;
	for ( let i = 0; i < n; i ++ ) {

		const k = 3 * order[ i ];
		const x = points[ k ], y = points[ k + 1 ], z = points[ k + 2 ];
		if ( x < minX ) minX = x; if ( x > maxX ) maxX = x;
		if ( y < minY ) minY = y; if ( y > maxY ) maxY = y;
		if ( z < minZ ) minZ = z; if ( z > maxZ ) maxZ = z;

	}

	const cells = ( 1 << HILBERT_BITS ) - 1;
	const size = Math.max( maxX - minX, maxY - minY, maxZ - minZ ) || 1;
	const scale = cells / size;

	// The Hilbert index (30 bits) of each point, by position in the shuffled order.
	const keys = new Uint32Array( n );
	for ( let i = 0; i < n; i ++ ) {

		const k = 3 * order[ i ];
		const hx = Math.min( cells, Math.floor( ( points[ k ] - minX ) * scale ) );
		const hy = Math.min( cells, Math.floor( ( points[ k + 1 ] - minY ) * scale ) );
		const hz = Math.min( cells, Math.floor( ( points[ k + 2 ] - minZ ) * scale ) );
		keys[ i ] = hilbertIndex3( hx, hy, hz, HILBERT_BITS );

	}

	// Rounds: [0, n/2^r) … [n/4, n/2), [n/2, n); tiny first round left as is.
	const result = new Uint32Array( n );
	let end = n;
	const bounds: number[] = [];
	while ( end > 64 ) {

		bounds.push( end );
		end = end >>> 1;

	}

	bounds.push( end );
	bounds.reverse();

	// Each round sorted by key, equal keys in shuffled order (a stable sort).
	const from = new Uint32Array( n ), to = new Uint32Array( n );
	let start = 0;
	for ( const stop of bounds ) {

		if ( stop - start < RADIX_MIN ) sortSmallRound( keys, start, stop, from );
		else radixSortRound( keys, start, stop, from, to );
		for ( let i = start; i < stop; i ++ ) result[ i ] = order[ from[ i ] ];
		start = stop;

	}

	return result;

}

// Rounds of at least this many points are radix sorted (three passes over 1024 buckets); smaller ones sort packed doubles.
const RADIX_MIN = 128;
const POSITION_RANGE = 2 ** 23;
const _histogram = new Int32Array( 1024 );

/** Positions start … stop − 1 into `out[ start … stop − 1 ]`, sorted by key then position (fewer than 2^23 of them). */
function sortSmallRound( keys: Uint32Array, start: number, stop: number, out: Uint32Array ): void {

	// Key and offset in the round packed in one double: 30 + 23 bits ≤ 53, exact.
	const packed = new Float64Array( stop - start );
	for ( let i = 0; i < packed.length; i ++ ) packed[ i ] = keys[ start + i ] * POSITION_RANGE + i;
	packed.sort();
	for ( let i = 0; i < packed.length; i ++ ) {

		const v = packed[ i ];
		out[ start + i ] = start + v - Math.floor( v / POSITION_RANGE ) * POSITION_RANGE;

	}

}

/** As sortSmallRound, by a least-significant-digit radix sort (three stable passes of 10 key bits). */
function radixSortRound( keys: Uint32Array, start: number, stop: number, out: Uint32Array, scratch: Uint32Array ): void {

	let source = out, target = scratch;
	for ( let i = start; i < stop; i ++ ) source[ i ] = i;
	const histogram = _histogram;
	for ( let shift = 0; shift < 30; shift += 10 ) {

		histogram.fill( 0 );
		for ( let i = start; i < stop; i ++ ) histogram[ ( keys[ source[ i ] ] >>> shift ) & 1023 ] ++;
		let sum = start;
		for ( let d = 0; d < 1024; d ++ ) {

			const count = histogram[ d ];
			histogram[ d ] = sum;
			sum += count;

		}

		for ( let i = start; i < stop; i ++ ) {

			const position = source[ i ];
			target[ histogram[ ( keys[ position ] >>> shift ) & 1023 ] ++ ] = position;

		}

		const swap = source; source = target; target = swap;

	}

	// Three passes end in `scratch`.
	for ( let i = start; i < stop; i ++ ) out[ i ] = source[ i ];

}
