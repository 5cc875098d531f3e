/**
 * Spherical harmonics (order 2, 9 RGB coefficients) in three.js `SphericalHarmonics3` layout:
 * basis, CPU projection of captured cube maps and panoramas, and irradiance reconstruction.
 * Free of three.js imports so it runs in plain Node (bakers, tests, workers).
 */

export {
	SH_Y00, SH_Y1, SH_Y2_PRODUCT, SH_Y20, SH_Y22,
	IRRADIANCE_C1, IRRADIANCE_C2, IRRADIANCE_C3, IRRADIANCE_C4, IRRADIANCE_C5,
	evaluateSHBasis,
} from './SHBasis.js';
export { CUBE_FACE_AXES, cubeFaceDirection } from './cubeFaceDirection.js';
export { cubeTexelSolidAngle, paperTexelSolidAngle } from './cubeTexelSolidAngle.js';
export { projectCubeMapToSH, getCubeProjectionTable, clearCubeProjectionCache } from './projectCubeMapToSH.js';
export type { CubeSolidAngleMode, CubeMapProjectionOptions, CubeProjectionTable } from './projectCubeMapToSH.js';
export { projectEquirectToSH } from './projectEquirectToSH.js';
export type { EquirectProjectionOptions } from './projectEquirectToSH.js';
export { evaluateIrradiance, evaluateRadiance, irradianceMatrices, IRRADIANCE_MATRICES_FLOATS } from './irradiance.js';
export type { DirectionLike, WritableArrayLike } from './irradiance.js';
export { windowSH, windowSHFactors, minIrradiance, minRadiance, makeIrradianceNonNegative, makeRadianceNonNegative } from './windowSH.js';
