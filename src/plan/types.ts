/**
 * The structured toolpath plan between planning and G-code text. Layers hold ordered steps: extrusions
 * with a feature type, width (or one per point), height and speed, and travels (with retraction and combing waypoints).
 * Cooling, time and filament estimates are passes over this plan; the G-code writer prints it last.
 * Coordinates are integer µm in bed space; widths, heights and Z are mm; speeds mm/s.
 */
import type { Pt } from '../geometry/types.js';
import type { FeatureType } from '../paths/roles.js';

export { FEATURE_TYPES, type FeatureType } from '../paths/roles.js';

/** An extrusion along `points` (a closed loop returns to its first point when `closed`). */
export interface ExtrudeStep {
  kind: 'extrude';
  feature: FeatureType;
  points: Pt[];
  closed: boolean;
  /** Line width, mm, where `widths` is absent. */
  width: number;
  /**
   * The bead width at each point, mm, when it varies along the path (variable-width walls): a segment's
   * filament is its length times the mean of its two end widths.
   */
  widths?: Float64Array;
  /** The nozzle's Z at each point above the layer's Z, mm, when it varies along the path. */
  z?: Float64Array;
  /** Layer height the line is laid at, mm (first layer may differ). */
  height: number;
  /** Feed rate, mm/s (after cooling slow-down). */
  speed: number;
  /** Flow multiplier (1 = nominal). */
  flow: number;
  /** Index into `PrintPlan.objects` of the object this extrusion belongs to (absent: none, e.g. skirt, raft). */
  object?: number;
  /** Part-cooling fan for this step, 0..1, when it differs from the layer's (bridges); the layer's fan comes back after. */
  fan?: number;
  /**
   * Segment kinds (arc fitting): `arcs[i]` set means the segment that ends at `points[i]` is a circular
   * arc rather than a straight line; for a closed step `arcs[points.length]` is the closing segment back
   * to `points[0]`. Absent or unset entries are lines.
   */
  arcs?: Array<PlanArc | undefined>;
}

/** A circular arc segment: its centre (µm, bed space, not rounded) and its direction of turn. */
export interface PlanArc {
  cx: number;
  cy: number;
  /** True for clockwise (G2), false for counter-clockwise (G3), seen from above. */
  clockwise: boolean;
}

/** A travel to `points[points.length-1]` through the given waypoints (combing). */
export interface TravelStep {
  kind: 'travel';
  points: Pt[];
  /** Retract before and prime after this travel. */
  retract: boolean;
  /** Lift Z by this much during the travel, mm (0 = no hop). Only with retract. */
  zHop: number;
  /**
   * Travel at this Z instead (mm, absolute), coming down to the layer's Z only at the travel's end: the
   * move from one object to the next in sequential printing, over the objects printed before. Absent on
   * every other travel.
   */
  liftTo?: number;
  /** Travel speed, mm/s. */
  speed: number;
}

export type PlanStep = ExtrudeStep | TravelStep;

export interface LayerPlan {
  index: number;
  /** Nozzle Z for this layer, mm. */
  z: number;
  /** Layer thickness, mm. */
  height: number;
  /** Part-cooling fan, 0..1, set at the start of the layer. */
  fan: number;
  /** Nozzle temperature to set at the start of the layer (°C), when it changes. */
  nozzleTemperature?: number;
  /** Bed temperature to set at the start of the layer (°C), when it changes. */
  bedTemperature?: number;
  /**
   * The layer is one turn of a spiral vase (spiral-vase.ts): its extrusions carry a Z per point rising from
   * the previous layer's Z to this one's, and the first starts where the nozzle is (in XY, and in Z when
   * the previous layer was a turn too), so no Z move comes before it.
   */
  spiral?: true;
  steps: PlanStep[];
}

/** One printed object, for object labels (cancel one object mid-print). Coordinates mm, bed space. */
export interface PlanObject {
  /** Unique within the plan, from the file / 3MF object name. */
  name: string;
  /** Centre of its footprint. */
  center: [number, number];
  /** Its footprint on the bed (convex hull of every layer's outline), counter-clockwise. */
  polygon: [number, number][];
}

export interface PrintPlan {
  layers: LayerPlan[];
  /** The objects the extrusions' `object` indices refer to (may be empty). */
  objects: PlanObject[];
  /** Bounds of all extrusions, mm. */
  bounds: { minX: number; minY: number; minZ: number; maxX: number; maxY: number; maxZ: number };
}

/** Results of the estimate passes over a plan. */
export interface PlanEstimate {
  printTimeSeconds: number;
  /** Filament length, mm. */
  filamentMm: number;
  /** Filament weight, g. */
  filamentGrams: number;
  /** Per layer: estimated seconds. */
  layerSeconds: number[];
}
