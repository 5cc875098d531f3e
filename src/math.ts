/**
 * `three-capture-lighting/math` — the library's pure core, free of three.js so it runs in plain
 * Node (bake tools, workers, tests): SH9 projection of cube maps and panoramas, irradiance and
 * the paper's nᵀMn matrices, de-ringing, the exact 3D Delaunay tetrahedralization (static and
 * incremental), the probe interpolators, `blendSH` and `blendGradientSH`, the least-squares probe
 * fit (`fitProbeSH`), triangle queries, and the irradiance error metric used by placement.
 */

export { SH_FLOATS } from './validate.js';
export { evaluateSHBasis } from './sh/SHBasis.js';
export { cubeFaceDirection } from './sh/cubeFaceDirection.js';
export { projectCubeMapToSH } from './sh/projectCubeMapToSH.js';
export type { CubeSolidAngleMode, CubeMapProjectionOptions } from './sh/projectCubeMapToSH.js';
export { projectEquirectToSH } from './sh/projectEquirectToSH.js';
export type { EquirectProjectionOptions } from './sh/projectEquirectToSH.js';
export { evaluateIrradiance, evaluateRadiance, irradianceMatrices, IRRADIANCE_MATRICES_FLOATS } from './sh/irradiance.js';
export type { DirectionLike, WritableArrayLike } from './sh/irradiance.js';
export { windowSH, windowSHFactors, minIrradiance, minRadiance, makeIrradianceNonNegative, makeRadianceNonNegative } from './sh/windowSH.js';

export { tetrahedralize, DegenerateInputError } from './tetrahedra/tetrahedralize.js';
export type { Tetrahedralization, TetrahedralizeOptions, DegenerateReason } from './tetrahedra/tetrahedralize.js';
export { DynamicTetrahedralization } from './tetrahedra/DynamicTetrahedralization.js';
export type { TetrahedralEdit } from './tetrahedra/DynamicTetrahedralization.js';
export { validateTetrahedralization, TetrahedralizationError } from './tetrahedra/validateTetrahedralization.js';
export type { TetrahedralizationErrorCode } from './tetrahedra/validateTetrahedralization.js';

export type { ProbeInterpolator } from './interpolation/ProbeInterpolator.js';
export { TetrahedralMesh } from './interpolation/TetrahedralMesh.js';
export type { OutsideMode, TetrahedralMeshOptions, FromTetrahedralizationOptions } from './interpolation/TetrahedralMesh.js';
export { IncrementalTetrahedralMesh } from './interpolation/IncrementalTetrahedralMesh.js';
export type { IncrementalTetrahedralMeshOptions } from './interpolation/IncrementalTetrahedralMesh.js';
export { GridInterpolator } from './interpolation/GridInterpolator.js';
export { PlanarMesh } from './interpolation/PlanarMesh.js';
export { createProbeInterpolator } from './interpolation/createProbeInterpolator.js';
export { blendSH } from './interpolation/blendSH.js';
export { blendGradientSH } from './interpolation/blendGradientSH.js';
export { fitProbeSH, evaluateGradientField } from './fitting/index.js';
export type { FitSamples, FitProbeSHOptions, FitProbeSHResult } from './fitting/index.js';

export { TriangleBVH } from './geometry/TriangleBVH.js';
export { intersectRayTriangle } from './geometry/intersectRayTriangle.js';
export { closestPointOnTriangle } from './geometry/closestPointOnTriangle.js';
export { classifyPoints, OPEN_SPACE, INSIDE_GEOMETRY, NEAR_SURFACE, UNREACHABLE, INSIDE_RAY_DIRECTIONS } from './placement/classifyPoints.js';
export { ReachableSpace } from './placement/ReachableSpace.js';
export type { ReachableSpaceOptions } from './placement/ReachableSpace.js';
export type { ClassifyPointsOptions } from './placement/classifyPoints.js';
export { irradianceError, IRRADIANCE_ERROR_NORMALS } from './placement/irradianceError.js';
export type { IrradianceErrorSummary, IrradianceErrorResult } from './placement/irradianceError.js';
