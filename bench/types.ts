/**
 * What a benchmark module gives back to bench/run.ts. Each `*.bench.ts` file exports `title`,
 * optionally `notes`, and `run( log )` resolving to rows; run.ts turns them into the tables of
 * bench/results/latest.md and the rows of latest.json.
 */

/** One measured (or skipped) figure: one subject on one case. */
export interface BenchRow {
	/** The input, e.g. `'random 10k'` or `'1k probes, coherent'`. */
	case: string;
	/** Who was measured, e.g. `'ours'`, `'CGAL 5.5.1'`, `'delaunay-triangulate'`. */
	subject: string;
	/** Unit of median/min/max, e.g. `'ms'` or `'M queries/s'`. */
	unit: string;
	/** Null when the subject could not be measured; `status` says why. */
	median: number | null;
	min: number | null;
	max: number | null;
	runs: number;
	/** What the subject produced, e.g. `'6,000 tetrahedra'`. */
	output?: string;
	/** Outcome of the checks, or why the figure is missing: `'valid'`, `'timeout >60 s'`, … */
	status?: string;
	/** Subject compared against, and median / peer median. */
	peer?: string;
	ratio?: number;
	/** More peers compared against, each with median / its median, printed after `ratio`. */
	ratios?: { peer: string, ratio: number }[];
	/** Targets for the figure, printed beside it (never asserted). */
	targets?: Target[];
}

export interface Target {
	/** E.g. `'≤ 250 ms'`. */
	text: string;
	/** Undefined when it could not be judged (no figure, or no peer to compare with). */
	met?: boolean;
}

export interface BenchModule {
	title: string;
	notes?: string[];
	run( log: ( message: string ) => void ): Promise<BenchRow[]>;
}
