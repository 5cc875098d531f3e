declare module 'delaunay-triangulate' {

	/** Delaunay triangulation in any dimension; each cell lists d + 1 point indices. */
	export default function triangulate( points: number[][], includePointAtInfinity?: boolean ): number[][];

}
