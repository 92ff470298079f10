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

export type Centering = 'object' | 'global';

/** Everything a pattern may know about the layer it fills. Lengths in µm, angles in degrees. */
export interface InfillLayerInput {
  layerIndex: number;
  /** Print height of the layer (mm). */
  z: number;
  /** Layer thickness (mm). */
  layerHeight: number;
  /** The area to fill, µm. Lines must stay inside it. */
  region: ExPolygon[];
}

/** Settings-derived parameters, the same for every layer of one object. */
export interface InfillParams {
  /** Infill density as a fraction, 0 < density ≤ 1. */
  density: number;
  /** Extrusion line width, µm. */
  lineWidth: number;
  /** Nozzle diameter, µm (the seed's spacing formulas are in terms of it). */
  nozzleDiameter: number;
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

export interface InfillPattern {
  readonly id: PatternId;
  readonly description: string;
  /**
   * Optional whole-object pass run once before the per-layer calls (lightning's trees).
   * Returns one plain-data value per layer, handed back to `generate` as `prepared`.
   */
  prepare?(model: InfillModelInput, params: InfillParams): unknown[];
  generate(layer: InfillLayerInput, params: InfillParams, prepared?: unknown): InfillResult;
}
