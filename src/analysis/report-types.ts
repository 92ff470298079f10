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
  thickness: number;
  /** The nearest Z of the layer grid (firstLayerHeight, then every layerHeight), and whether Z is on it. */
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
}

export interface PrintReport {
  summary: PrintSummary;
  /** The analysed layers (every layer unless sampleEvery > 1). */
  layers: LayerReport[];
  /** Z of every printed layer. */
  layerZ: number[];
  warnings: string[];
}
