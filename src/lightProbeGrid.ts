/**
 * `three-capture-lighting/lightProbeGrid` — feeds three's own `LightProbeGridWebGL` (three r186+)
 * from a probe volume, without a bake. A separate entry so the main one loads with older three
 * releases too.
 */

export { toLightProbeGrid } from './runtime/toLightProbeGrid.js';
