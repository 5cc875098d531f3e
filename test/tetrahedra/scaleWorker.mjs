// Runs the cases of scaleCases.ts for scale.test.ts in a worker thread, which the test terminates
// when a case exceeds its time limit. Plain JavaScript: it registers tsx to load the TypeScript.
import { parentPort, workerData } from 'node:worker_threads';
import { register } from 'tsx/esm/api';

register();
const { runCase } = await import( './scaleCases.ts' );
for ( const index of workerData.indices ) {

	parentPort.postMessage( { type: 'start', index } );
	const started = performance.now();
	let result;
	try {

		result = runCase( workerData.cases[ index ] );

	} catch ( error ) {

		result = { failures: [ `the case threw ${error && error.stack ? error.stack : error}` ], outcome: 'error' };

	}

	parentPort.postMessage( { type: 'done', index, result, ms: performance.now() - started } );

}
