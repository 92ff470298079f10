/**
 * The interface every infill pattern implements. A pattern draws raw lines (or closed loops) for one
 * layer's infill region; the shared code in this folder clips, links and orders them.
 */
import type { ExPolygon, Polygon, Polyline, Pt } from '../geometry/types.js';

/** Pattern ids. Adding one here makes the registry's `satisfies` check demand a module for it. */
export const PATTERN_IDS = [
  'grid',
  'lines',
  'triangles',
  'hexagons',
  'cubic',
  'concentric',
  'gyroid',
  'spiral',
  'lightning',
] as const;
export type PatternId = (typeof PATTERN_IDS)[number];

/** Skin (top and bottom solid) pattern ids; skin-patterns.ts maps each to its fill. */
export const SKIN_PATTERN_IDS = ['lines', 'monotonic', 'concentric'] as const;
export type SkinPatternId = (typeof SKIN_PATTERN_IDS)[number];

export type Centering = 'object' | 'global';

/** Everything a pattern may know about the layer it fills: its heights in mm, its region in µm. */
export interface InfillLayerInput {
  layerIndex: number;
  /** Print height of the layer, mm. */
  zMm: number;
  /** Layer thickness, mm. */
  layerHeightMm: number;
  /** The area to fill, µm. Lines must stay inside it. */
  region: ExPolygon[];
}

/** Settings-derived parameters, the same for every layer of one object. Lengths in µm, angles in degrees. */
export interface InfillParams {
  /** Infill density as a fraction, 0 < density ≤ 1. */
  density: number;
  /** Extrusion line width, µm. */
  lineWidthUm: number;
  /** Nozzle diameter, µm (the seed's spacing formulas are in terms of it). */
  nozzleDiameterUm: number;
  /** Base angle of the pattern, degrees (setting infillAngle, default 45); patterns add their own sweeps to it. */
  angle: number;
  centering: Centering;
  /** Pattern origin, µm: the object's centre (object centering) or the bed centre (global). */
  origin: Pt;
  /** Whether consecutive lines may be connected along the region boundary. */
  connect: boolean;
}

/** One layer's infill: open polylines and closed loops, both inside the region. */
export interface InfillResult {
  lines: Polyline[];
  loops: Polygon[];
}

/** Whole-object inputs for patterns that look across layers (lightning). */
export interface InfillModelInput {
  layers: InfillLayerInput[];
  /** Per layer: the area of top skin printed directly above this layer's infill (what must be supported), µm. */
  supportNeeded: ExPolygon[][];
}

/**
 * One family of parallel lines for the shared scanline clipper: lines in direction `angle` (degrees
 * counter-clockwise from +X), `spacingUm` µm apart, one of them passing through origin + offsetUm·n, where n
 * is the unit normal (−sin angle, cos angle).
 */
export interface Sweep {
  angle: number;
  spacingUm: number;
  offsetUm: number;
}

/**
 * What a pattern's `generate` returns: raw lines (drawn over the region's bounds, clipped by the shared
 * code), closed loops (already inside the region), optional line families for the scanline clipper, and
 * hints for linking. A plain InfillResult is a valid PatternOutput.
 */
export interface PatternOutput extends InfillResult {
  /** Families of straight parallel lines, clipped exactly by the scanline engine (faster than `lines`). */
  sweeps?: Sweep[];
  /** Typical distance between neighbouring lines, µm; line ends closer than a small multiple of it along the boundary are joined. */
  linkSpacingUm?: number;
  /** false: never join these lines along the boundary (trees, loops the pattern linked itself). */
  link?: boolean;
  /** true: the pattern already fitted its spacing to this region's density; the engine runs it only once. */
  fitted?: boolean;
}

/**
 * How the density setting maps to material. 'layer' (default): every layer's extruded lines (length × width)
 * over the region's area is the setting. 'volume': the mean over one Z period (`zPeriodMm`) is the setting, single layers vary (gyroid).
 * 'support': the pattern prints only what top skins need and reports its own, lower, figure (lightning).
 */
export type DensityModel = 'layer' | 'volume' | 'support';

export interface InfillPattern {
  /** A built-in pattern's id, or 'custom': the slice's custom infill (patterns/custom.ts). */
  readonly id: PatternId | 'custom';
  readonly description: string;
  /**
   * true: `generate` draws finished paths, clipped to the region, ordered, at the density it reads itself
   * (custom infill); the shared code takes them as they are, even where the density setting is 0.
   */
  readonly finished?: boolean;
  /** Defaults to 'layer'. */
  readonly densityModel?: DensityModel;
  /** true: the pattern follows the region (or the skins), so `params.origin` / centering has no effect. */
  readonly followsRegion?: boolean;
  /** Z period of a 'volume' pattern, mm. */
  zPeriodMm?(params: InfillParams): number;
  /**
   * Optional whole-model pass run once before the per-layer calls (lightning's trees): the lines it draws
   * on each layer, handed back to `generate` as that layer's `prepared`.
   */
  prepare?(model: InfillModelInput, params: InfillParams): Polyline[][];
  generate(layer: InfillLayerInput, params: InfillParams, prepared?: Polyline[]): PatternOutput;
}
