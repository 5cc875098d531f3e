import type { ProbeRole } from 'three-capture-lighting';

/** A probe layout as stored in scenes/*.json: positions with optional names and roles. */
export interface ProbeLayout {

	name: string;
	positions: number[];
	names?: string[];
	roles?: ProbeRole[];
	/** For a regular grid: its box and counts, so it can also be interpolated trilinearly. */
	grid?: { min: number[]; max: number[]; counts: number[] };
	/** Lighting zones: named groups of probe indices, each with the box where it applies. */
	zones?: { name: string; probes: number[]; bounds: { min: number[]; max: number[] } }[];

}
