/**
 * Strata's independent G-code analyser: parses any slicer's G-code and judges it against the model it was sliced
 * from (layers, walls, stray material, skin, infill density, E bookkeeping, support and raft). It shares no code
 * with the slicer.
 */
export { analyzePrint, analyzeParsed } from './checks.js';
export type { AnalyzeOptions, LayerReport, PrintReport, PrintSummary } from './checks.js';
export type { GapStats, LayerSupport, ModelZSummary, SupportSummary } from './report-types.js';
export { formatLayerSupport, formatReport, formatSupport } from './format-report.js';
export { modelZFrames } from './model-z.js';
export type { LayerFrame, ModelZ } from './model-z.js';
export { meshVolume } from './support-volume.js';
export { createGcodeParser, parseGcode } from './gcode-parse.js';
export type { GcodeParser } from './gcode-parse.js';
export type {
  ETotals,
  ExtrusionTable,
  GcodeExtents,
  GcodeLayer,
  ParsedGcode,
  RetractionBalance,
  RetractionTable,
  TravelTable,
} from './gcode-types.js';
export { RetractionKind } from './gcode-types.js';
export { FEATURE_NAMES, Feature, featureCodeOf, isPartFeature, isSupportFeature } from './feature-names.js';
export type { FeatureName } from './feature-names.js';
export { createSectioner, meshSection, rasterizeSection } from './section.js';
export type { SectionSegments, Sectioner } from './section.js';
export { closeGaps } from './section-gaps.js';
export type { Grid } from './grid.js';
export { gridAround } from './grid.js';
export { beadWidth, coverage, rasterizeExtrusions, stampCapsule, volumeWidth } from './raster.js';
export { layerSvg } from './layer-svg.js';
