import { MeshBasicNodeMaterial } from 'three/webgpu';
import { attribute, float, max, normalWorldGeometry, select, vec3, vec4 } from 'three/tsl';

/** 1 / π: a white Lambertian surface's radiance per unit irradiance. */
const INV_PI = 0.3183098861837907;

/**
 * The TSL counterpart of shaders/probeVolumeHelper.{vert,frag}.glsl for a WebGPURenderer: a white
 * diffuse sphere per instance lit by its probe alone, max( E(n), 0 ) / π for the world normal n,
 * E from the SH in the per-instance attributes probeSH0…6 (the 27 floats of SphericalHarmonics3
 * plus one unused) with SphericalHarmonics3.getIrradianceAt's constants, as the GLSL helper does.
 * A MeshBasicNodeMaterial, so tone mapping and the output colour space apply as to three's own
 * materials; no fog (the GLSL ShaderMaterial has none).
 */
export function createProbeSphereNodeMaterial(): MeshBasicNodeMaterial {

	const s = [ 0, 1, 2, 3, 4, 5, 6 ].map( ( k ) => attribute( `probeSH${k}`, 'vec4' ) );
	const c = [
		s[ 0 ].xyz, vec3( s[ 0 ].w, s[ 1 ].xy ), vec3( s[ 1 ].zw, s[ 2 ].x ), s[ 2 ].yzw,
		s[ 3 ].xyz, vec3( s[ 3 ].w, s[ 4 ].xy ), vec3( s[ 4 ].zw, s[ 5 ].x ), s[ 5 ].yzw, s[ 6 ].xyz,
	];
	// The interpolated normal, renormalised; a NaN or infinite one gets the direction-free part of E.
	const normal = normalWorldGeometry;
	const m = select( float( normal.dot( normal ) ).sub( 1 ).abs().lessThan( 0.5 ), normal, vec3( 0 ) );
	const x = m.x, y = m.y, z = m.z;
	const irradiance = c[ 0 ].mul( 0.886227 )
		.add( c[ 1 ].mul( y.mul( 2 * 0.511664 ) ) )
		.add( c[ 2 ].mul( z.mul( 2 * 0.511664 ) ) )
		.add( c[ 3 ].mul( x.mul( 2 * 0.511664 ) ) )
		.add( c[ 4 ].mul( x.mul( y ).mul( 2 * 0.429043 ) ) )
		.add( c[ 5 ].mul( y.mul( z ).mul( 2 * 0.429043 ) ) )
		.add( c[ 6 ].mul( z.mul( z ).mul( 0.743125 ).sub( 0.247708 ) ) )
		.add( c[ 7 ].mul( x.mul( z ).mul( 2 * 0.429043 ) ) )
		.add( c[ 8 ].mul( x.mul( x ).sub( y.mul( y ) ).mul( 0.429043 ) ) );
	const material = new MeshBasicNodeMaterial();
	material.name = 'LightProbeVolumeHelper';
	material.fog = false;
	// Negative irradiance (SH ringing) shows black rather than passing negative values to tone mapping.
	material.colorNode = vec4( max( irradiance, vec3( 0 ) ).mul( INV_PI ), 1 );
	return material;

}
