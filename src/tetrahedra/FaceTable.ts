/**
 * A small open-addressing hash table from a triangle (three vertex ids, any order, −1 allowed for
 * the vertex at infinity) to an integer, for matching the faces of a re-triangulated hole.
 * Internal to src/tetrahedra.
 */
export class FaceTable {

	/** Number of live entries. */
	size = 0;

	private keyA = new Int32Array( 256 );
	private keyB = new Int32Array( 256 );
	private keyC = new Int32Array( 256 );
	private value = new Int32Array( 256 );
	private stamp = new Int32Array( 256 );
	private current = 1;
	private mask = 255;

	/** Empties the table, sized for up to `entries` entries. */
	clear( entries: number ): void {

		let size = this.stamp.length;
		if ( size < entries * 2 ) {

			while ( size < entries * 2 ) size *= 2;
			this.keyA = new Int32Array( size );
			this.keyB = new Int32Array( size );
			this.keyC = new Int32Array( size );
			this.value = new Int32Array( size );
			this.stamp = new Int32Array( size );
			this.current = 0;

		}

		this.mask = size - 1;
		this.current ++;
		this.size = 0;

	}

	/** The value stored for triangle abc, or −1 (values must be ≥ 0). */
	get( a: number, b: number, c: number ): number {

		const h = this.find( a, b, c );
		return h >= 0 && this.stamp[ h ] === this.current ? this.value[ h ] : - 1;

	}

	/** Stores `value` (≥ 0) for triangle abc; false when abc is already present. */
	set( a: number, b: number, c: number, value: number ): boolean {

		const h = this.find( a, b, c );
		if ( this.stamp[ h ] === this.current ) return false;
		this.stamp[ h ] = this.current;
		this.keyA[ h ] = _sorted[ 0 ]; this.keyB[ h ] = _sorted[ 1 ]; this.keyC[ h ] = _sorted[ 2 ];
		this.value[ h ] = value;
		this.size ++;
		return true;

	}

	/**
	 * Pairs faces: when abc is present, returns its value and retires the entry; otherwise stores
	 * `value` and returns −1.
	 */
	pair( a: number, b: number, c: number, value: number ): number {

		const h = this.find( a, b, c );
		if ( this.stamp[ h ] === this.current ) {

			const other = this.value[ h ];
			this.keyA[ h ] = this.keyB[ h ] = this.keyC[ h ] = - 3; // tombstone: keeps probe chains intact
			this.size --;
			return other;

		}

		this.stamp[ h ] = this.current;
		this.keyA[ h ] = _sorted[ 0 ]; this.keyB[ h ] = _sorted[ 1 ]; this.keyC[ h ] = _sorted[ 2 ];
		this.value[ h ] = value;
		this.size ++;
		return - 1;

	}

	/** The slot holding abc, or the empty slot where it would go (sorted key left in `_sorted`). */
	private find( a: number, b: number, c: number ): number {

		let s: number;
		if ( a > b ) { s = a; a = b; b = s; }
		if ( b > c ) { s = b; b = c; c = s; }
		if ( a > b ) { s = a; a = b; b = s; }
		_sorted[ 0 ] = a; _sorted[ 1 ] = b; _sorted[ 2 ] = c;
		let h = ( Math.imul( a + 2, 0x9E3779B1 ) ^ Math.imul( b + 2, 0x85EBCA77 ) ^ Math.imul( c + 2, 0xC2B2AE3D ) ) & this.mask;
		for ( ;; ) {

			if ( this.stamp[ h ] !== this.current ) return h;
			if ( this.keyA[ h ] === a && this.keyB[ h ] === b && this.keyC[ h ] === c ) return h;
			h = ( h + 1 ) & this.mask;

		}

	}

}

const _sorted = new Int32Array( 3 );
