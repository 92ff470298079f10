/** Options and report of analyzePrint. Lengths in mm, areas in mm², fractions 0..1. */
import type { FeatureName } from './feature-names.js';
import type { ETotals, GcodeExtents, RetractionBalance } from './gcode-types.js';

export interface AnalyzeOptions {
  layerHeight: number;
  firstLayerHeight: number;
  /** Nominal line width (mm): tolerances and the nominal width model use it. */
  lineWidth: number;
  filamentDiameter: number;
  /** Raster cell size (mm), default 0.05; grown automatically when a layer would exceed the cell budget. */
  cellSize?: number;
  /**
   * Width of the wall zone (mm), default 2 × lineWidth. The infill region starts a line width further in, past
   * where infill overlaps or runs along the innermost wall.
   */
  wallThickness?: number;
  /** Skin thickness that defines top / bottom surfaces (mm), default 0.8 each. */
  topThickness?: number;
  bottomThickness?: number;
  /** Bead widths from the extruded volume ('flow', default) or the nominal line width for every line. */
  widthSource?: 'flow' | 'nominal';
  /** Analyse every k-th layer (plus the first and last) with the raster checks; default 1 (all). */
  sampleEvery?: number;
  /**
   * Variable layer height (adaptive layers, a layer range's own height): each layer may be any thickness in
   * [min, max] mm. The Z grid check then judges each part layer's thickness (zMismatch: outside the range by
   * more than zTolerance) and counts as missing the layers a gap thicker than max leaves out (and a top left
   * more than half of max above the last layer). Default none: every layer layerHeight above the last.
   */
  layerHeightRange?: [number, number];
  /** A layer whose Z is off the expected grid by more than this is reported (mm), default 0.005. */
  zTolerance?: number;
  /**
   * The infill region keeps this far (mm; default 1) from the model's skin — sideways, and in Z beyond the skin
   * thickness — and a line width from the solid infill (SKIN) the G-code prints.
   */
  skinMargin?: number;
  /** A layer with outline coverage below this is listed as missing walls; default 0.95. */
  wallCoverageThreshold?: number;
  /** A layer shifted by more than this is listed (mm); default 0.1. */
  shiftTolerance?: number;
  /**
   * Print Z minus model Z (mm): how far a raft raises the part. Default: detected from the G-code (see
   * model-z.ts); 0 when no layer with support or raft material comes before the part's first layer.
   */
  modelZOffset?: number;
  /** Run the support checks (overhangs, material over nothing, support in the part, Z gaps); default true. */
  supportChecks?: boolean;
  /** Overhang angle from vertical beyond which the model needs material under it (degrees), default 50. */
  overhangAngleDeg?: number;
  /** Material up to this many layers below still holds what is above (the support's top Z gap), default 2. */
  supportGapLayers?: number;
  /**
   * Lines, branches or walls below that are at most this far apart (mm) hold the area between them, default 3:
   * sparse support and tree tips cover their whole area, a wall does not grow outward.
   */
  supportSpanMm?: number;
  /** Overhang specks smaller than this are ignored (mm²), default 1. */
  overhangMinAreaMm2?: number;
}

/** Support measures of one layer (areas in mm² on the support raster). */
export interface LayerSupport {
  /** The model's overhang on this layer, and the part of it with material under it. */
  overhangAreaMm2: number;
  overhangSupportedMm2: number;
  /** The layer's part extrusion, and the part of it over nothing. */
  partAreaMm2: number;
  overNothingMm2: number;
  /** Support and interface beads on this layer, and the part of them inside the model's section. */
  supportAreaMm2: number;
  insideMm2: number;
}

export interface GapStats {
  /** Area over which the gap was measured (mm²). */
  areaMm2: number;
  /** Area-weighted median and low end (2nd percentile) of the gap (mm), null when not measured. */
  medianMm: number | null;
  minMm: number | null;
  /** The same in whole layers (gap / layerHeight, rounded). */
  medianLayers: number | null;
  minLayers: number | null;
  /** Share of the measured area by gap in whole layers: index 0 = no gap, 1 = one layer, … */
  byLayers: number[];
}

export interface SupportSummary {
  overhangAngleDeg: number;
  /** The model's overhang area summed over analysed layers, the part with material under it, and the share. */
  overhangAreaMm2: number;
  overhangSupportedMm2: number;
  overhangSupported: number | null;
  /** Layers with the most unsupported overhang (up to 5). */
  overhangWorstLayers: { layer: number; z: number; areaMm2: number; unsupportedMm2: number }[];
  /** Part extrusion area summed over analysed layers, the part of it over nothing, and the share. */
  partAreaMm2: number;
  overNothingMm2: number;
  overNothing: number | null;
  /** Layers with the most part extrusion over nothing (up to 5). */
  overNothingWorstLayers: { layer: number; z: number; areaMm2: number; fraction: number }[];
  /** Support and interface bead area inside the model's section, summed over analysed layers (mm²). */
  insideAreaMm2: number;
  insideWorstLayer: number | null;
  insideWorstMm2: number;
  /** Support and interface bead area summed over analysed layers (mm²). */
  supportAreaMm2: number;
  /** Analysed layers with support or interface material. */
  supportLayers: number;
  /** From the top of support to the model above it, and from the model to support standing on it. */
  topGap: GapStats;
  /** The second model layer's top gap (over the first layer, where there is no room for one), not in topGap. */
  topGapOverFirstLayer: GapStats;
  bottomGap: GapStats;
  /** Extruded volumes from E (mm³), over every layer, and support (body + interface) and raft over the model's. */
  volume: {
    supportMm3: number;
    interfaceMm3: number;
    raftMm3: number;
    partMm3: number;
    /** The mesh's volume. */
    modelMm3: number;
    supportShare: number | null;
    raftShare: number | null;
  };
}

export interface ModelZSummary {
  /** Print Z minus model Z (mm), and whether it was given, detected (a raft) or is 0. */
  offsetMm: number;
  source: 'option' | 'detected' | 'none';
  firstModelLayer: number | null;
  raftLayerCount: number;
  /** Air gap from the raft's top to the bottom of the first model layer (mm). */
  raftGapMm: number | null;
}

export interface SkinMetrics {
  /** Exposed surface area of the model on the layer (mm²). */
  areaMm2: number;
  /** Fraction of that area covered by the layer's extruded part material, null without surface. */
  coverage: number | null;
}

export interface LayerReport {
  index: number;
  z: number;
  /** Top of the layer in the model's Z (print Z minus the model's Z offset). */
  modelZ: number;
  /** What the layer prints: part material (perhaps with support), support alone, or raft. */
  role: 'part' | 'support' | 'raft';
  thickness: number;
  /**
   * The nearest Z of the layer grid (firstLayerHeight, then every layerHeight) to modelZ, and whether modelZ is on
   * it (always true for layers not judged on the grid: raft, support alone, the first layer over a raft).
   */
  expectedZ: number;
  zOk: boolean;
  /** The `;LAYER:` marker merged into this layer, if any. */
  marker: number | null;
  /** Height of the model section compared with this layer (its mid-height). */
  sectionZ: number;
  sectionAreaMm2: number;
  /** True when the model has no section at this height (all material here is stray). */
  sectionEmpty: boolean;
  /** Area covered by the part's extruded material (raster of beads). */
  materialAreaMm2: number;
  /** Outline length that should carry a wall, and outline along features thinner than half a line width. */
  outlineLengthMm: number;
  thinOutlineMm: number;
  /** Fraction of the (wallable) outline with an extrusion within one line width; null without outline. */
  outlineCoverage: number | null;
  /** Fitted XY shift of the extrusions against the section outline, and the fitted wall inset (mm). */
  shift: { dx: number; dy: number; inset: number } | null;
  shiftMm: number | null;
  /** Distances of part extrusion centreline samples beyond the section grown by half a line width (mm). */
  outsideMaxMm: number;
  outsideP99Mm: number;
  /** Area of bead raster outside the section grown by half a line width. */
  outsideAreaMm2: number;
  topSkin: SkinMetrics;
  bottomSkin: SkinMetrics;
  /** The region that is neither walls nor skin (mm²), and the FILL density measured in it (null if too small). */
  infillRegionAreaMm2: number;
  infillDensity: number | null;
  /** Length-weighted median bead width of the part's extrusions (mm). */
  widthMedianMm: number | null;
  featureLengthMm: Partial<Record<FeatureName, number>>;
  travelLengthMm: number;
  retractions: number;
  /** Support measures, null for raft layers or without support checks. */
  support: LayerSupport | null;
}

export interface PrintSummary {
  layerCount: number;
  /** Layers a slicer needs for the model's height with the given first and other layer heights. */
  expectedLayerCount: number;
  firstLayerZ: number | null;
  /** Indices of printed layers whose Z is off the layer grid (first 50). */
  zMismatchLayers: number[];
  zMismatchCount: number;
  /** Grid Z values up to the model's top with no printed layer (first 50). */
  missingLayerZ: number[];
  missingLayerCount: number;
  analysedLayers: number;
  walls: {
    /** Outline-length-weighted coverage over analysed layers. */
    coverage: number | null;
    minCoverage: number | null;
    worstLayer: number | null;
    /** Layers below wallCoverageThreshold (first 50). */
    layersBelowThreshold: number[];
  };
  outside: {
    maxMm: number;
    p99Mm: number;
    areaMm2: number;
    worstLayer: number | null;
    /** Layers with part material where the model has no section, and the material length on them. */
    emptySectionLayers: number[];
    materialOnEmptySectionMm: number;
  };
  skin: {
    top: { areaMm2: number; coverage: number | null; minCoverage: number | null; worstLayer: number | null };
    bottom: { areaMm2: number; coverage: number | null; minCoverage: number | null; worstLayer: number | null };
  };
  infill: {
    /** Region-area-weighted density over layers where it was measured. */
    density: number | null;
    minDensity: number | null;
    maxDensity: number | null;
    layersMeasured: number;
    regionAreaMm2: number;
  };
  shift: { maxMm: number | null; worstLayer: number | null; shiftedLayers: number[] };
  e: ETotals & {
    balance: RetractionBalance;
    /** Length-weighted median bead width of part extrusions over all layers (mm). */
    widthMedianMm: number | null;
    /** Median bead width / nominal line width: far from 1 hints at a wrong E mode or filament diameter. */
    flowRatio: number | null;
  };
  featureLengthMm: Partial<Record<FeatureName, number>>;
  travelLengthMm: number;
  retractionCount: number;
  /** Extrusion before the first layer marker (purge lines), not judged against the model. */
  preambleExtrusionMm: number;
  extents: GcodeExtents | null;
  hasLayerMarkers: boolean;
  hasTypeMarkers: boolean;
  cellSizeMm: number;
  timingMs: { parse: number; analyse: number };
  /** Where the model sits in the print's Z (a raft raises it). */
  modelZ: ModelZSummary;
  /** Support checks, null when turned off. */
  support: SupportSummary | null;
}

export interface PrintReport {
  summary: PrintSummary;
  /** The analysed layers (every layer unless sampleEvery > 1). */
  layers: LayerReport[];
  /** Z of every printed layer. */
  layerZ: number[];
  warnings: string[];
}
