import { Data3DTexture, DataUtils, FloatType, HalfFloatType, LinearFilter, RGBAFormat, Vector3 } from 'three';
import { blendProbes } from './gradientBlend.js';
import { GradientTracker } from './gradientTracker.js';
import { assertProbeField, assertUsableProbeField, trackSH, type ProbeField } from './ProbeField.js';
import { assertOptionalBoolean, assertOptions, describeValue } from '../validate.js';

/** Options of {@link ProbeVolumeTexture}. */
export interface ProbeVolumeTextureOptions {

	/**
	 * Grid nodes per axis, one number for all or `[ x, y, z ]`; each clamped to 2..`maxResolution`.
	 * Overrides `texelSize`.
	 */
	resolution?: number | ArrayLike<number>;

	/** World distance between grid nodes. Default: the longest side / 31 (32 nodes along it). */
	texelSize?: number;

	/** Largest node count per axis. Default 64. */
	maxResolution?: number;

	/**
	 * Texel type: `'half'` (default) is filterable on every WebGL2 device; `'float'` needs
	 * `OES_texture_float_linear` for the trilinear filter (without it the texture samples black).
	 */
	type?: 'half' | 'float';

}

/**
 * Checks the options of a {@link ProbeVolumeTexture} (also for `ProbeTextureLighting`, which
 * passes them on), with errors starting with `where`.
 * @returns The texel type and the largest node count per axis, defaults filled in.
 */
export function checkVolumeTextureOptions( where: string, options: unknown ): { type: 'half' | 'float'; maxResolution: number } {

	assertOptions( where, 'options', options );
	const o = ( options ?? {} ) as ProbeVolumeTextureOptions;
	const type = o.type ?? 'half';
	if ( type !== 'half' && type !== 'float' ) throw new RangeError( `${where}: options.type is "${String( type )}"; expected 'half' or 'float'.` );
	const maxResolution = o.maxResolution ?? 64;
	if ( ! Number.isInteger( maxResolution ) || maxResolution < 2 || maxResolution > 256 ) {

		throw new RangeError( `${where}: options.maxResolution must be an integer in 2..256, got ${describeValue( maxResolution )}.` );

	}

	if ( o.texelSize !== undefined && ! ( typeof o.texelSize === 'number' && Number.isFinite( o.texelSize ) && o.texelSize > 0 ) ) {

		throw new RangeError( `${where}: options.texelSize must be a positive finite number, got ${describeValue( o.texelSize )}.` );

	}

	if ( o.resolution !== undefined ) {

		const r = o.resolution as unknown;
		const values = typeof r === 'number' ? [ r ] : Array.isArray( r ) || ArrayBuffer.isView( r ) ? Array.from( r as ArrayLike<unknown> ) : null;
		if ( values === null || ( values.length !== 1 && values.length !== 3 ) || values.some( ( v ) => typeof v !== 'number' || ! Number.isFinite( v ) || v < 1 ) ) {

			throw new RangeError( `${where}: options.resolution must be a number ≥ 1 or [ x, y, z ] of them, got ${describeValue( r )}.` );

		}

	}

	return { type, maxResolution };

}

/** Bounds: a three.js `Box3` or any `{ min: {x,y,z}, max: {x,y,z} }`. */
export interface BoundsLike {

	min: { x: number; y: number; z: number };
	max: { x: number; y: number; z: number };

}

const MAX_WEIGHTS = 8;
const _indices = new Uint32Array( MAX_WEIGHTS );
const _weights = new Float64Array( MAX_WEIGHTS );
const _sh = new Float64Array( 27 );

/**
 * The tetrahedral field resampled on a regular grid over a box, as a 3D SH texture the GPU filters
 * trilinearly — a light probe proxy volume: per-pixel probe light over a large object, at the cost
 * of one texture (7 RGBA texels per node) and 7 texture reads per pixel.
 *
 * The texture uses three.js's `LightProbeGridWebGL` atlas layout, so it can also drive three's
 * built-in per-pixel path (see `toLightProbeGrid`): 7 sub-volumes stacked along z (packed SH: the
 * 27 floats in `SphericalHarmonics3` order and one zero), each with one padding slice at both ends;
 * node (ix, iy, iz) of sub-volume t is texel (ix, iy, t·(nz + 2) + 1 + iz). Nodes sit at texel
 * centres: node i along x is at `min.x + i · (max.x − min.x) / (nx − 1)`.
 */
export class ProbeVolumeTexture {

	/** The SH atlas (RGBA half or float, linear filtering). */
	readonly texture: Data3DTexture;

	/** World position of the first grid node (the box's min corner; flat sides are widened to one texel). */
	readonly min = new Vector3();

	/** World position of the last grid node. */
	readonly max = new Vector3();

	/** Grid nodes per axis (integers ≥ 2). */
	readonly resolution = new Vector3( 2, 2, 2 );

	/**
	 * The probes: a `LightProbeVolume` or any `{ interpolator, sh, gradients?, positions? }` (gradient probes are blended
	 * by the gradient formula at each node). Call `resample()` after replacing it.
	 */
	field: ProbeField;

	/** Texel type, see {@link ProbeVolumeTextureOptions.type}. */
	readonly type: 'half' | 'float';

	private readonly options: ProbeVolumeTextureOptions;
	private shCopy: Float32Array | null = null;
	private readonly gradientTracker = new GradientTracker();
	private disposed = false;

	/**
	 * @param field The probes, e.g. a `LightProbeVolume`.
	 * @param bounds The world box to cover, e.g. `new Box3().setFromObject( floor )`.
	 * @param options See {@link ProbeVolumeTextureOptions}.
	 */
	constructor( field: ProbeField, bounds: BoundsLike, options: ProbeVolumeTextureOptions = {} ) {

		const where = 'ProbeVolumeTexture';
		assertUsableProbeField( where, field );
		const { type, maxResolution } = checkVolumeTextureOptions( where, options );
		const lo = ( bounds as BoundsLike | null )?.min, hi = ( bounds as BoundsLike | null )?.max;
		if ( ! lo || ! hi ) throw new TypeError( `${where}: bounds must be { min, max } (e.g. a Box3), got ${describeValue( bounds )}.` );

		this.field = field;
		this.type = type;
		this.options = { ...options, maxResolution };
		this.texture = new Data3DTexture( null, 1, 1, 1 );
		this.texture.format = RGBAFormat;
		this.texture.type = type === 'half' ? HalfFloatType : FloatType;
		this.texture.minFilter = this.texture.magFilter = LinearFilter;
		this.texture.generateMipmaps = false;
		this.texture.unpackAlignment = 1;
		this.setBounds( bounds );

	}

	/**
	 * Covers a new box: picks the node counts (reallocating the texture when they change) and
	 * resamples. Flat sides (a floor's height) are widened to one texel, centred.
	 */
	setBounds( bounds: BoundsLike ): this {

		const where = 'ProbeVolumeTexture.setBounds';
		if ( this.disposed ) throw new Error( `${where}: called after dispose().` );
		const lo = ( bounds as BoundsLike | null )?.min, hi = ( bounds as BoundsLike | null )?.max;
		const corners = lo && hi ? [ lo.x, lo.y, lo.z, hi.x, hi.y, hi.z ] : [];
		if ( ! lo || ! hi || corners.some( ( v ) => typeof v !== 'number' || ! Number.isFinite( v ) ) ) throw new RangeError( `${where}: bounds must be { min, max } with finite x, y, z (an empty Box3 has infinite corners).` );
		const size = [ hi.x - lo.x, hi.y - lo.y, hi.z - lo.z ];
		if ( size.some( ( s ) => s < 0 ) ) throw new RangeError( `${where}: bounds.min must not exceed bounds.max, got size (${size.join( ', ' )}).` );
		const longest = Math.max( ...size );
		if ( ! ( longest > 0 ) ) throw new RangeError( `${where}: bounds have zero size (a point); there is nothing to resample over.` );

		const { resolution, maxResolution = 64 } = this.options;
		const texel = this.options.texelSize ?? longest / 31;
		const counts = [ 0, 0, 0 ];
		const clamp = ( v: number ) => Math.min( maxResolution, Math.max( 2, Math.round( v ) ) );
		for ( let a = 0; a < 3; a ++ ) {

			if ( resolution !== undefined ) counts[ a ] = clamp( typeof resolution === 'number' ? resolution : resolution[ a ] );
			else counts[ a ] = clamp( size[ a ] / texel + 1 );

		}

		// A flat side gets one texel of thickness, so the shader never divides by zero.
		const minimum = longest / ( Math.max( ...counts ) - 1 );
		const centre = [ ( lo.x + hi.x ) / 2, ( lo.y + hi.y ) / 2, ( lo.z + hi.z ) / 2 ];
		const half = size.map( ( s ) => ( s < minimum * 1e-3 ? minimum : s ) / 2 );
		this.min.set( centre[ 0 ] - half[ 0 ], centre[ 1 ] - half[ 1 ], centre[ 2 ] - half[ 2 ] );
		this.max.set( centre[ 0 ] + half[ 0 ], centre[ 1 ] + half[ 1 ], centre[ 2 ] + half[ 2 ] );

		const [ nx, ny, nz ] = counts;
		const image = this.texture.image as { data: Uint16Array | Float32Array | null; width: number; height: number; depth: number };
		if ( nx !== this.resolution.x || ny !== this.resolution.y || nz !== this.resolution.z || image.data === null ) {

			this.resolution.set( nx, ny, nz );
			const length = 4 * nx * ny * 7 * ( nz + 2 );
			image.data = this.type === 'half' ? new Uint16Array( length ) : new Float32Array( length );
			image.width = nx;
			image.height = ny;
			image.depth = 7 * ( nz + 2 );
			// A new size needs new GL storage: three reallocates a texture only when it is disposed.
			this.texture.dispose();

		}

		this.shCopy = null;
		this.gradientTracker.reset();
		this.resample();
		return this;

	}

	/** World position of grid node (ix, iy, iz). */
	nodePosition( ix: number, iy: number, iz: number, target = new Vector3() ): Vector3 {

		const where = 'ProbeVolumeTexture.nodePosition', r = this.resolution;
		if ( ! [ ix, iy, iz ].every( ( v ) => typeof v === 'number' && Number.isFinite( v ) ) ) {

			throw new RangeError( `${where}: ix, iy, iz must be finite numbers, got (${ix}, ${iy}, ${iz}).` );

		}

		if ( ( target as { isVector3?: boolean } | null )?.isVector3 !== true ) throw new TypeError( `${where}: target must be a Vector3.` );
		return target.set(
			this.min.x + ( this.max.x - this.min.x ) * ix / ( r.x - 1 ),
			this.min.y + ( this.max.y - this.min.y ) * iy / ( r.y - 1 ),
			this.min.z + ( this.max.z - this.min.z ) * iz / ( r.z - 1 ) );

	}

	/**
	 * Samples the field at every node (walking from the previous node's cell) and uploads.
	 * @returns Whether it resampled: false when the field's SH and gradients have not changed since
	 * the last time and `force` is false.
	 */
	resample( force = true ): boolean {

		const where = 'ProbeVolumeTexture.resample';
		if ( this.disposed ) throw new Error( `${where}: called after dispose().` );
		assertOptionalBoolean( where, 'force', force );
		assertProbeField( where, this.field );
		const copy = trackSH( where, this.field.sh, this.shCopy );
		if ( copy !== null ) this.shCopy = copy;
		const gradientsChanged = this.gradientTracker.changed( where, this.field.gradients, this.field.positions );
		if ( copy === null && ! gradientsChanged && ! force ) return false;

		const { x: nx, y: ny, z: nz } = this.resolution;
		const data = ( this.texture.image as { data: Uint16Array | Float32Array } ).data;
		const half = this.type === 'half';
		const field = this.field, interpolator = field.interpolator, probeSH = field.sh, weightCount = interpolator.weightCount;
		const gradients = field.gradients, positions = field.positions;
		const slice = nx * ny, padded = nz + 2, subVolume = slice * padded;
		const x0 = this.min.x, y0 = this.min.y, z0 = this.min.z;
		const dx = ( this.max.x - x0 ) / ( nx - 1 ), dy = ( this.max.y - y0 ) / ( ny - 1 ), dz = ( this.max.z - z0 ) / ( nz - 1 );
		let hint = - 1;
		for ( let iz = 0; iz < nz; iz ++ ) for ( let iy = 0; iy < ny; iy ++ ) for ( let ix = 0; ix < nx; ix ++ ) {

			const x = x0 + ix * dx, y = y0 + iy * dy, z = z0 + iz * dz;
			hint = interpolator.interpolate( x, y, z, _indices, _weights, hint );
			blendProbes( _indices, _weights, weightCount, probeSH, gradients, positions, x, y, z, _sh );
			const texel = ix + nx * iy;
			for ( let t = 0; t < 7; t ++ ) {

				const o = 4 * ( texel + slice * ( 1 + iz ) + subVolume * t );
				for ( let c = 0; c < 4; c ++ ) {

					const k = 4 * t + c;
					const v = k < 27 ? _sh[ k ] : 0;
					data[ o + c ] = half ? DataUtils.toHalfFloat( v ) : v;

				}

			}

		}

		// Padding slices repeat the first and last data slice of each sub-volume: the filter then
		// never blends two sub-volumes.
		for ( let t = 0; t < 7; t ++ ) {

			const base = 4 * subVolume * t, size = 4 * slice;
			data.copyWithin( base, base + size, base + 2 * size );
			data.copyWithin( base + size * ( nz + 1 ), base + size * nz, base + size * ( nz + 1 ) );

		}

		this.texture.needsUpdate = true;
		return true;

	}

	/** Frees the texture's GPU memory. */
	dispose(): void {

		this.disposed = true;
		this.texture.dispose();

	}

}
