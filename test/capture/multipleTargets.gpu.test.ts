import { afterAll, describe, expect, it } from 'vitest';
import { SHProjector } from '../../src/capture.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';

const ctx = await createHeadlessRenderer( 4, 4 );

describe.skipIf( ! ctx.renderer )( `SHProjector capability probe${ctx.skipReason ? ' — SKIPPED: ' + ctx.skipReason : ''}`, () => {

	afterAll( () => ctx.dispose() );

	it( 'multiple render targets — not working in headless-gl (only the first is written; GL_INVALID_OPERATION): the probe says so, the projection falls back to four draws, and the MRT path is covered in test/browser/projection.test.ts', () => {

		// If a future headless-gl gets this right, this fails: then the Node GPU tests can cover
		// the MRT path too.
		expect( SHProjector.supportsMultipleTargets( ctx.renderer! ) ).toBe( false );
		expect( new SHProjector( ctx.renderer! ).multipleTargets ).toBe( false );
		expect( ctx.gl!.getError() ).toBe( ctx.gl!.NO_ERROR ); // the probe leaves no error behind

	} );

} );
