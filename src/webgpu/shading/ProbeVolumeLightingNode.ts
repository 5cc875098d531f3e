import { LightingNode } from 'three/webgpu';
import type { ProbeNodeVariant } from './probeMaterialRecords.js';
import { probeIrradianceNode } from './probeVolumeNodes.js';


/**
 * Adds a variant's probe irradiance to the lighting context's indirect diffuse irradiance — where
 * three's LightProbeNode and LightProbeGridNode put theirs — as one of a material's own lightings
 * (so a scene without lights still gets a lighting context). One instance per variant, shared.
 */
export class ProbeVolumeLightingNode extends LightingNode {

	/** Which graph it adds. */
	readonly variant: ProbeNodeVariant;

	/** @param variant Which graph it adds. */
	constructor( variant: ProbeNodeVariant ) {

		super();
		this.variant = variant;

	}

	/** Node type name (three's convention). */
	static get type(): string {

		return 'ProbeVolumeLightingNode';

	}

	/** Adds the irradiance to `builder.context.irradiance`. */
	override setup( builder: any ): undefined {

		builder.context.irradiance.addAssign( probeIrradianceNode( this.variant ) );
		return undefined;

	}

}

const nodes = new Map<ProbeNodeVariant, ProbeVolumeLightingNode>();

/** The shared lighting node of a variant. */
export function probeLightingNode( variant: ProbeNodeVariant ): ProbeVolumeLightingNode {

	let node = nodes.get( variant );
	if ( node === undefined ) {

		node = new ProbeVolumeLightingNode( variant );
		nodes.set( variant, node );

	}

	return node;

}
