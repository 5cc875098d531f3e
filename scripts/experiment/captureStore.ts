/**
 * The experiment's saved captures (`--captures FILE`, `--save-captures`): every capture a run made
 * (positions, settings, SH and time) and the scene the page loaded (triangles, hand-made layout,
 * grid box), so that a later run reuses them instead of capturing again and `--offline` runs
 * without the browser at all. A capture is looked up by its exact positions and settings; a
 * request that is the start of a saved one (the first n fit points of a longer set) is served from
 * it, because the point sets are drawn one after another from a seed.
 */

import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import type { CaptureRequest, LoadedScene } from './page.js';

/** One saved capture. */
export interface SavedCapture {

	label: string;
	settings: CaptureRequest;
	/** x, y, z per probe, exactly as the run computed them. */
	positions: Float64Array;
	/** 27 per probe. */
	sh: Float32Array;
	/** Wall time of the capture (ms). */
	ms: number;

}

/** A hit of {@link CaptureStore.find}. */
export interface StoredCapture {

	sh: Float32Array;
	/** The saved capture's time, scaled to the probes asked for when it was a longer capture. */
	ms: number;
	/** True when served from a longer capture. */
	prefix: boolean;

}

const FORMAT = 'three-capture-lighting experiment captures';
const VERSION = 1;

/** Saved captures of one scene, in memory; {@link CaptureStore.write} puts them in a file. */
export class CaptureStore {

	/** The scene the page loaded, once known. */
	scene: LoadedScene | null = null;

	/** The browser that loaded it and made the captures (its version string), once known. */
	browser: string | null = null;

	/** Which scene the captures belong to. */
	readonly sceneName: string;

	/** The saved captures, in the order they were made. */
	readonly captures: SavedCapture[] = [];

	constructor( sceneName: string ) {

		this.sceneName = sceneName;

	}

	/** The store in `file`, or an empty one when the file does not exist. */
	static read( file: string, sceneName: string ): CaptureStore {

		const store = new CaptureStore( sceneName );
		if ( ! existsSync( file ) ) return store;
		const json = JSON.parse( readFileSync( file, 'utf8' ) );
		if ( json.format !== FORMAT || json.version !== VERSION ) throw new Error( `CaptureStore: ${file} is not a version ${VERSION} captures file.` );
		if ( json.scene !== sceneName ) throw new Error( `CaptureStore: ${file} holds captures of ${json.scene}, not ${sceneName}.` );
		store.scene = json.loaded ?? null;
		store.browser = json.browser ?? null;
		for ( const c of json.captures ) {

			store.captures.push( {
				label: c.label, settings: c.settings, ms: c.ms,
				positions: decodeBase64( c.positions, Float64Array ), sh: decodeBase64( c.sh, Float32Array ),
			} );

		}

		return store;

	}

	/** The saved SH for exactly these positions and settings (or the start of a longer saved capture), else null. */
	find( positions: ArrayLike<number>, settings: CaptureRequest ): StoredCapture | null {

		const count = positions.length / 3;
		for ( const saved of this.captures ) {

			if ( ! sameSettings( saved.settings, settings ) || saved.positions.length < positions.length ) continue;
			let same = true;
			for ( let i = 0; i < positions.length && same; i ++ ) same = saved.positions[ i ] === positions[ i ];
			if ( ! same ) continue;
			const savedCount = saved.positions.length / 3;
			return { sh: saved.sh.slice( 0, 27 * count ), ms: saved.ms * count / savedCount, prefix: savedCount > count };

		}

		return null;

	}

	/**
	 * The longest saved capture (same settings) whose positions are the start of `positions`, or
	 * null: a longer fit set then needs only its new points captured.
	 */
	findStartOf( positions: ArrayLike<number>, settings: CaptureRequest ): SavedCapture | null {

		let best: SavedCapture | null = null;
		for ( const saved of this.captures ) {

			if ( ! sameSettings( saved.settings, settings ) || saved.positions.length >= positions.length ) continue;
			if ( best && saved.positions.length <= best.positions.length ) continue;
			let same = true;
			for ( let i = 0; i < saved.positions.length && same; i ++ ) same = saved.positions[ i ] === positions[ i ];
			if ( same ) best = saved;

		}

		return best;

	}

	/** Removes a saved capture (one that a longer one now contains). */
	remove( saved: SavedCapture ): void {

		const index = this.captures.indexOf( saved );
		if ( index >= 0 ) this.captures.splice( index, 1 );

	}

	/** Adds a capture (positions copied as float64). */
	add( label: string, settings: CaptureRequest, positions: ArrayLike<number>, sh: Float32Array, ms: number ): void {

		this.captures.push( { label, settings: { ...settings }, positions: Float64Array.from( positions ), sh: sh.slice(), ms } );

	}

	/** Writes the store to `file` (JSON; typed arrays as base64 of their bytes). */
	write( file: string ): void {

		writeFileSync( file, JSON.stringify( {
			format: FORMAT, version: VERSION, scene: this.sceneName, browser: this.browser, loaded: this.scene,
			captures: this.captures.map( ( c ) => ( {
				label: c.label, settings: c.settings, ms: c.ms, positions: encodeBase64( c.positions ), sh: encodeBase64( c.sh ),
			} ) ),
		} ) + '\n' );

	}

}

function sameSettings( a: CaptureRequest, b: CaptureRequest ): boolean {

	return a.resolution === b.resolution && a.near === b.near && a.far === b.far;

}

/** The bytes of a typed array as base64. */
export function encodeBase64( array: Float64Array | Float32Array | Int8Array ): string {

	return Buffer.from( array.buffer, array.byteOffset, array.byteLength ).toString( 'base64' );

}

/** Decodes base64 text of a typed array's bytes (a copy, aligned). */
export function decodeBase64<T extends Float64Array | Float32Array | Int8Array>(
	text: string, type: { new( buffer: ArrayBuffer ): T }
): T {

	const bytes = Buffer.from( text, 'base64' );
	const copy = new ArrayBuffer( bytes.length );
	new Uint8Array( copy ).set( bytes );
	return new type( copy );

}
