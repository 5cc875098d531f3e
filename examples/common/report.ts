/** State a page leaves on `window.__demo` for tests and benchmarks. */
export interface DemoReport {

	ready: boolean;
	captureMs: number;
	probes: number;
	cells: number;
	/** CPU time of the last frames' work (update + render call), ms. */
	frameMs: number[];
	/** Time between the last frames (what the user sees, GPU included), ms. */
	intervalMs: number[];
	character: 'fox' | 'fallback' | 'none';
	/** With `?volume=`: ms to decode and validate the baked file into a volume (no capture). */
	loadMs?: number;
	/** With the visibility guard on: tetrahedra with an edge through static geometry. */
	leakingCells?: number;
	/** Which backend runs ('WebGLRenderer', 'WebGPU', 'WebGPURenderer (WebGL2 backend)'); '' until the renderer is ready. */
	renderer?: string;
	error: string;

}

/** How many frames `frameMs` and `intervalMs` keep. */
const KEPT_FRAMES = 300;

/** Records one frame's work and interval (0 when time did not advance) in a report. */
export function recordFrame( report: DemoReport, workMs: number, intervalMs: number ): void {

	report.frameMs.push( workMs );
	if ( report.frameMs.length > KEPT_FRAMES ) report.frameMs.shift();
	if ( intervalMs > 0 ) report.intervalMs.push( intervalMs );
	if ( report.intervalMs.length > KEPT_FRAMES ) report.intervalMs.shift();
	if ( ! report.ready && report.frameMs.length >= 5 ) report.ready = true;

}
