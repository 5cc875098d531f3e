/**
 * Where a run's captures come from: the saved captures when they hold the positions asked for,
 * else the browser (started on the first capture that is not saved, the scene loaded then), whose
 * captures are added to the store. Offline, a capture that is not saved is an error and nothing
 * starts the browser.
 */

import type { ExperimentSession } from './browser.js';
import type { CaptureStore } from './captureStore.js';
import type { CaptureRequest, LoadedScene } from './page.js';

/** A capture the run asked for. */
export interface SourcedCapture {

	sh: Float32Array;
	ms: number;
	/** True when it came from the saved captures. */
	saved: boolean;

}

/** What a run needs from its captures ({@link CaptureSource}, or a stand-in in tests). */
export interface CaptureProvider {

	/** The browser's version string. */
	readonly browserVersion: string;

	/** Captures made in the browser during this run. */
	readonly newCaptures: number;

	/** The scene: triangles, hand-made layout, grid box. */
	scene(): Promise<LoadedScene>;

	/** The SH of probes at `positions`. */
	capture( positions: ArrayLike<number>, settings: CaptureRequest, label: string ): Promise<SourcedCapture>;

}

/** Options of {@link CaptureSource}. */
export interface CaptureSourceOptions {

	/** Never start the browser: every capture must be saved, no PNG is drawn. */
	offline: boolean;

	/** Starts the browser session (called at most once). */
	start: () => Promise<ExperimentSession>;

	log: ( message: string ) => void;

	/** Called after each new capture is added to the store (run.ts writes the file: a stopped run keeps what it made). */
	saved?: () => void;

}

/** Captures from a {@link CaptureStore}, falling back to the browser. */
export class CaptureSource implements CaptureProvider {

	readonly store: CaptureStore;

	/** Captures made in the browser during this run. */
	newCaptures = 0;

	private readonly options: CaptureSourceOptions;
	private session: ExperimentSession | null = null;
	private sceneLoaded = false;

	constructor( store: CaptureStore, options: CaptureSourceOptions ) {

		this.store = store;
		this.options = options;

	}

	/** The browser's version string: the saved one, else the session's. */
	get browserVersion(): string {

		return this.store.browser ?? this.session?.browserVersion ?? 'unknown';

	}

	/** The scene: the saved one, else loaded in the browser. */
	async scene(): Promise<LoadedScene> {

		if ( this.store.scene ) return this.store.scene;
		return this.loadInPage();

	}

	/** The SH of probes at `positions`: saved, else captured in the browser (and saved). */
	async capture( positions: ArrayLike<number>, settings: CaptureRequest, label: string ): Promise<SourcedCapture> {

		const saved = this.store.find( positions, settings );
		if ( saved ) {

			this.options.log( `${label}: ${positions.length / 3} probes from the saved captures${saved.prefix ? ' (the start of a longer capture)' : ''}` );
			return { sh: saved.sh, ms: saved.ms, saved: true };

		}

		if ( this.options.offline ) throw new Error( `--offline: the saved captures do not hold "${label}" (${positions.length / 3} probes); run once without --offline to capture it.` );
		if ( ! this.sceneLoaded ) await this.loadInPage();
		// A longer point set whose start is saved (more fit points): capture only the new points.
		const start = this.store.findStartOf( positions, settings );
		const from = start ? start.positions.length : 0;
		const rest = await this.session!.capture( Array.prototype.slice.call( positions, from ), settings, start ? `${label} (the ${( positions.length - from ) / 3} not saved)` : label );
		const sh = new Float32Array( 9 * positions.length );
		if ( start ) sh.set( start.sh );
		sh.set( rest.sh, 9 * from );
		const ms = ( start?.ms ?? 0 ) + rest.ms;
		if ( start ) this.store.remove( start );
		this.store.add( label, settings, positions, sh, ms );
		this.newCaptures ++;
		this.options.saved?.();
		return { sh, ms, saved: false };

	}

	/** Renders the SVG to a PNG file in the browser; false (nothing written) offline. */
	async rasterize( svg: string, width: number, height: number, file: string ): Promise<boolean> {

		if ( this.options.offline ) return false;
		await ( await this.open() ).rasterize( svg, width, height, file );
		return true;

	}

	/** Closes the browser if it was started. */
	async close(): Promise<void> {

		await this.session?.close();
		this.session = null;

	}

	private async open(): Promise<ExperimentSession> {

		if ( ! this.session ) {

			this.session = await this.options.start();
			this.store.browser ??= this.session.browserVersion;

		}

		return this.session;

	}

	private async loadInPage(): Promise<LoadedScene> {

		const session = await this.open();
		const loaded = await session.load( this.store.sceneName );
		this.sceneLoaded = true;
		const saved = this.store.scene;
		const changed = saved && ( saved.triangles !== loaded.triangles || saved.sides !== loaded.sides ||
			JSON.stringify( saved.hand ) !== JSON.stringify( loaded.hand ) );
		if ( changed ) {

			// Saved captures of another build of the scene must not be mixed with new ones.
			throw new Error( `the ${this.store.sceneName} scene the page builds differs from the one of the saved captures; remove the captures file to start over.` );

		}

		this.store.scene ??= loaded;
		this.options.log( `${loaded.info.renderer}; ${loaded.info.triangles} triangles` );
		return this.store.scene;

	}

}
