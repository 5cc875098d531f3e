/**
 * A tiny least-recently-used map for the per-resolution projection tables. Tables for a 256²
 * cube are ~14 MB, so only a handful are kept; a capture loop at one resolution hits the same
 * entry every time and never rebuilds it.
 * @internal
 */
export class LRUCache<K, V> {

	private readonly entries = new Map<K, V>();

	/**
	 * @param capacity Maximum number of entries kept; the least recently used one is dropped first.
	 */
	constructor( readonly capacity: number ) {}

	/**
	 * The cached value for `key`, built with `create` (and cached) when missing.
	 */
	getOrCreate( key: K, create: () => V ): V {

		const entries = this.entries;
		let value = entries.get( key );
		if ( value !== undefined ) {

			// Map iteration order is insertion order: re-inserting marks the entry as most recent.
			entries.delete( key );
			entries.set( key, value );
			return value;

		}

		value = create();
		entries.set( key, value );
		if ( entries.size > this.capacity ) {

			const oldest = entries.keys().next().value as K;
			entries.delete( oldest );

		}

		return value;

	}

	/** Drops every entry. */
	clear(): void {

		this.entries.clear();

	}

}
