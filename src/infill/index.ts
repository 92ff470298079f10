/** Public face of the infill module. */
export { generateInfill, solidFill, LINK_REACH } from './generate.js';
export type { SolidFillOptions } from './generate.js';
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
