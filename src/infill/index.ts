/** Public face of the infill module. */
export { generateInfill, LINK_REACH } from './generate.js';
export { solidFill } from './solid-fill.js';
export type { SolidFillOptions } from './solid-fill.js';
export { PATTERNS } from './registry.js';
export { extrudedArea, lineDensity, measuredDensity, pathLength } from './measure.js';
export { clipSweep } from './sweep.js';
export { clipPolylines, clipToRegion } from './clip-polylines.js';
export { linkPieces } from './link.js';
export { orderPaths, travelLength } from './order.js';
export { regionGeom, indexRegion } from './region-index.js';
export { PATTERN_IDS } from './types.js';
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
  Sweep,
} from './types.js';
