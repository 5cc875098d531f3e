/**
 * Least-squares probe fitting (pure, no three.js): probe SH, and optionally spatial gradients,
 * fitted so the interpolated field matches captured samples. docs/fitting.md.
 */

export { fitProbeSH } from './fitProbeSH.js';
export type { FitSamples, FitProbeSHOptions, FitProbeSHResult } from './fitProbeSH.js';
export { evaluateGradientField } from './evaluateGradientField.js';
