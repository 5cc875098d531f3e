import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname } from 'node:path';
import { PNG } from 'pngjs';

/** RGBA pixels of a PNG file or buffer. */
export function readPNG( source: string | Buffer ): { width: number; height: number; data: Uint8Array } {

	const png = PNG.sync.read( typeof source === 'string' ? readFileSync( source ) : source );
	return { width: png.width, height: png.height, data: new Uint8Array( png.data.buffer, png.data.byteOffset, png.data.length ) };

}

export function writePNG( path: string, width: number, height: number, data: Uint8Array ): void {

	mkdirSync( dirname( path ), { recursive: true } );
	const png = new PNG( { width, height } );
	png.data = Buffer.from( data );
	writeFileSync( path, PNG.sync.write( png ) );

}

/**
 * Compares an image with its golden. Returns the mean absolute channel difference (0..255) and the
 * fraction of pixels whose largest channel difference exceeds `pixelThreshold`. On a mismatch
 * beyond the limits it writes `<name>.actual.png` and `<name>.diff.png` under test/output/.
 * A missing golden is written to test/output/<name>.new.png and reported, never created in place:
 * goldens are accepted by a person who looked at them.
 */
export function compareWithGolden(
	name: string, goldenPath: string, actual: { width: number; height: number; data: Uint8Array },
	limits = { mean: 2, pixelThreshold: 24, fraction: 0.01 }
): { ok: boolean; mean: number; fraction: number; message: string } {

	if ( ! existsSync( goldenPath ) ) {

		writePNG( `test/output/${name}.new.png`, actual.width, actual.height, actual.data );
		return { ok: false, mean: NaN, fraction: NaN, message: `no golden at ${goldenPath}; the render is at test/output/${name}.new.png — look at it, and if it is right copy it there.` };

	}

	const golden = readPNG( goldenPath );
	if ( golden.width !== actual.width || golden.height !== actual.height ) {

		return { ok: false, mean: NaN, fraction: NaN, message: `size ${actual.width}×${actual.height} differs from the golden's ${golden.width}×${golden.height}` };

	}

	const diff = new Uint8Array( actual.data.length );
	let sum = 0, over = 0;
	for ( let i = 0; i < actual.data.length; i += 4 ) {

		let worst = 0;
		for ( let c = 0; c < 3; c ++ ) {

			const d = Math.abs( actual.data[ i + c ] - golden.data[ i + c ] );
			sum += d;
			worst = Math.max( worst, d );

		}

		if ( worst > limits.pixelThreshold ) over ++;
		diff[ i ] = diff[ i + 1 ] = diff[ i + 2 ] = Math.min( 255, worst * 4 );
		diff[ i + 3 ] = 255;

	}

	const pixels = actual.data.length / 4;
	const mean = sum / ( 3 * pixels ), fraction = over / pixels;
	const ok = mean <= limits.mean && fraction <= limits.fraction;
	if ( ! ok ) {

		writePNG( `test/output/${name}.actual.png`, actual.width, actual.height, actual.data );
		writePNG( `test/output/${name}.diff.png`, actual.width, actual.height, diff );

	}

	return { ok, mean, fraction, message: `mean difference ${mean.toFixed( 2 )}/255, ${( 100 * fraction ).toFixed( 2 )} % of pixels off by more than ${limits.pixelThreshold}/255${ok ? '' : ` — see test/output/${name}.actual.png and .diff.png`}` };

}
