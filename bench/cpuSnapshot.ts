import { readdirSync, readFileSync } from 'node:fs';

/** Busy CPU seconds of the whole machine and of this process + the Chromium tree, from /proc; null elsewhere. */
export function cpuSnapshot( browserPid: number | null ): { busy: number, ours: number } | null {

	try {

		const tick = 100; // USER_HZ on Linux
		const fields = readFileSync( '/proc/stat', 'utf8' ).split( '\n' )[ 0 ].trim().split( /\s+/ ).slice( 1 ).map( Number );
		const busy = ( fields.reduce( ( a, b ) => a + b, 0 ) - fields[ 3 ] - ( fields[ 4 ] ?? 0 ) ) / tick; // minus idle, iowait
		const parents = new Map<number, number>(), times = new Map<number, number>();
		for ( const entry of readdirSync( '/proc' ) ) {

			if ( ! /^\d+$/.test( entry ) ) continue;
			try {

				const stat = readFileSync( `/proc/${entry}/stat`, 'utf8' );
				const rest = stat.slice( stat.lastIndexOf( ')' ) + 2 ).split( ' ' );
				parents.set( Number( entry ), Number( rest[ 1 ] ) );
				times.set( Number( entry ), ( Number( rest[ 11 ] ) + Number( rest[ 12 ] ) ) / tick ); // utime + stime

			} catch { /* exited */ }

		}

		const mine = new Set<number>( [ process.pid ] );
		if ( browserPid !== null ) mine.add( browserPid );
		for ( let grown = true; grown; ) {

			grown = false;
			for ( const [ pid, parent ] of parents ) if ( ! mine.has( pid ) && mine.has( parent ) ) { mine.add( pid ); grown = true; }

		}

		let ours = 0;
		for ( const pid of mine ) ours += times.get( pid ) ?? 0;
		return { busy, ours };

	} catch {

		return null;

	}

}

/** CPU seconds of the Chromium tree under `root`: its GPU process, its renderer process(es) and the rest, from /proc. */
export function cpuByType( root: number ): { gpu: number, renderer: number, other: number } {

	const parents = new Map<number, number>(), times = new Map<number, number>(), types = new Map<number, string>();
	for ( const entry of readdirSync( '/proc' ) ) {

		if ( ! /^\d+$/.test( entry ) ) continue;
		try {

			const stat = readFileSync( `/proc/${entry}/stat`, 'utf8' );
			const rest = stat.slice( stat.lastIndexOf( ')' ) + 2 ).split( ' ' );
			parents.set( Number( entry ), Number( rest[ 1 ] ) );
			times.set( Number( entry ), ( Number( rest[ 11 ] ) + Number( rest[ 12 ] ) ) / 100 );
			const type = /--type=([a-z-]+)/.exec( readFileSync( `/proc/${entry}/cmdline`, 'utf8' ) );
			types.set( Number( entry ), type ? type[ 1 ] : 'browser' );

		} catch { /* exited */ }

	}

	const tree = new Set<number>( [ root ] );
	for ( let grown = true; grown; ) {

		grown = false;
		for ( const [ pid, parent ] of parents ) if ( ! tree.has( pid ) && tree.has( parent ) ) { tree.add( pid ); grown = true; }

	}

	const result = { gpu: 0, renderer: 0, other: 0 };
	for ( const pid of tree ) {

		const type = types.get( pid );
		const key = type === 'gpu-process' ? 'gpu' : type === 'renderer' ? 'renderer' : 'other';
		result[ key ] += times.get( pid ) ?? 0;

	}

	return result;

}
