/**
 * Spreads integer cell coordinates over 32 bits (the large-prime XOR hash of Teschner et al.,
 * "Optimized Spatial Hashing for Collision Detection of Deformable Objects", 2003): the bucket of a
 * hashed grid is `cellHash( x, y, z ) & mask`. Different cells may share a bucket; callers compare
 * true distances, so a collision costs a test, never a wrong answer.
 */
export function cellHash( x: number, y: number, z: number ): number {

	return ( Math.imul( x, 73856093 ) ^ Math.imul( y, 19349663 ) ^ Math.imul( z, 83492791 ) ) >>> 0;

}
