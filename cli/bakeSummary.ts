import type { BakeOptions } from './args.js';
import type { BakeSceneInfo } from './bakePage/protocol.js';
import type { CaptureLightKind } from '../src/capture/prepareCaptureScene.js';

/*
 * The lines of `capture-lighting bake`'s summary that describe the scene's light and what the bake
 * did to the scene and the SH.
 */

const KIND_NAMES: Record<CaptureLightKind, string> = {
	directional: 'directional light', point: 'point light', spot: 'spot light', rectArea: 'rect area light',
	hemisphere: 'hemisphere light', ambient: 'ambient light', probe: 'light probe',
};

const SOURCES = [ 'file', 'flags', 'layout' ] as const;

/**
 * The lights that lit the capture by kind, each with where it came from, and the emission seen:
 * "1 point light (flags), 3 spot lights (file 2, layout 1); 1 emissive material".
 */
export function describeLights( info: BakeSceneInfo ): string {

	const parts: string[] = [];
	for ( const kind of Object.keys( KIND_NAMES ) as CaptureLightKind[] ) {

		const lights = info.lights.filter( ( light ) => light.kind === kind );
		if ( lights.length === 0 ) continue;
		const bySource = SOURCES.map( ( source ) => [ source, lights.filter( ( light ) => light.source === source ).length ] as const )
			.filter( ( [ , n ] ) => n > 0 );
		const where = bySource.length === 1 ? bySource[ 0 ][ 0 ] : bySource.map( ( [ source, n ] ) => `${source} ${n}` ).join( ', ' );
		parts.push( `${plural( lights.length, KIND_NAMES[ kind ] )} (${where})` );

	}

	const emission: string[] = [];
	if ( info.emissiveMaterials > 0 ) emission.push( plural( info.emissiveMaterials, 'emissive material' ) );
	if ( info.unlitMaterials > 0 ) emission.push( plural( info.unlitMaterials, 'unlit material' ) );
	return `${parts.length > 0 ? parts.join( ', ' ) : 'no lights'}; ${emission.length > 0 ? emission.join( ', ' ) : 'no emissive materials'}`;

}

/** What prepareCaptureScene did about shadows, or which flag turned it off. */
export function describeShadows( info: BakeSceneInfo, prepare: BakeOptions[ 'prepare' ] ): string {

	if ( ! prepare.shadows ) return `off (--no-shadows; ${plural( info.shadowLights, 'light' )} cast shadows as the file says)`;
	if ( info.shadowLights === 0 ) return 'none (no directional, point or spot light)';
	const details = [
		`${prepare.shadowMapSize}² maps`, `bias ${prepare.shadowBias}`,
		prepare.fitShadowCameras ? 'directional cameras fitted' : 'cameras as given',
		prepare.doubleSidedShadows ? `${plural( info.doubleSidedMaterials, 'material' )} double-sided` : 'shadow sides as given',
	];
	return `${plural( info.shadowLights, 'light' )}, ${plural( info.shadowMeshes, 'mesh', 'meshes' )} cast and receive (${details.join( ', ' )})`;

}

/** The SH post-processing: de-ringing and the non-negative switch. */
export function describePostProcessing( options: BakeOptions, raised: number ): string {

	const parts: string[] = [];
	if ( options.deringing > 0 ) parts.push( `de-ringing ${options.deringing}` );
	if ( options.nonNegative ) parts.push( `non-negative (${plural( raised, 'probe' )} windowed more)` );
	return parts.length > 0 ? parts.join( '; ' ) : 'as captured (no --deringing, no --non-negative)';

}

/** The sky as given: "#rrggbb", the panorama's file name, or "black". */
export function describeSky( sky: BakeOptions[ 'sky' ], name: ( file: string ) => string ): string {

	if ( ! sky ) return 'black';
	if ( 'hdr' in sky ) return name( sky.hdr );
	return '#' + sky.color.map( ( c ) => Math.round( c * 255 ).toString( 16 ).padStart( 2, '0' ) ).join( '' );

}

function plural( count: number, singular: string, several = singular + 's' ): string {

	return `${count.toLocaleString( 'en-US' )} ${count === 1 ? singular : several}`;

}
