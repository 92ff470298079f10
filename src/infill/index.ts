/** Public face of the infill module. */
export { generateInfill, LINK_REACH } from './generate.js';
export { solidFill } from './solid-fill.js';
export type { SolidFillOptions } from './solid-fill.js';
export { monotonicFill } from './monotonic.js';
export type { MonotonicOptions } from './monotonic.js';
export { SKIN_PATTERNS, concentricLoops } from './skin-patterns.js';
export type { SkinFill, SkinPattern } from './skin-patterns.js';
export { PATTERNS, regionPattern } from './registry.js';
export { extrudedAreaUm2, lineDensity, measuredDensity, pathLengthUm } from './measure.js';
export { clipSweep } from './sweep.js';
export { clipPolylines, clipToRegion } from './clip-polylines.js';
export { linkPieces } from './link.js';
export { regionGeom, indexRegion } from './region-index.js';
export { PATTERN_IDS, SKIN_PATTERN_IDS } from './types.js';
export type {
  Centering,
  DensityModel,
  InfillLayerInput,
  InfillModelInput,
  InfillParams,
  InfillPattern,
  InfillResult,
  PatternId,
  PatternOutput,
  SkinPatternId,
  Sweep,
} from './types.js';
