/**
 * What the paths stage hands to the planner: per layer, groups of path entries. A group is printed as a
 * whole (an island, one support area, the adhesion around the print); an entry is one kind of path within
 * it (the outer wall, the infill, the bridge lines…), already clipped and linked. Which entry prints when, and
 * how, is data (`roles.ts`), so support, raft or ironing are new entries, not new code in the planner.
 * Coordinates are integer µm.
 */
import type { ExPolygon, Polygon, Pt } from '../geometry/types.js';
import type { LayerZ } from '../slice/types.js';
import type { EntryStyle, PathRole } from './roles.js';

export { PATH_ROLES, type PathRole } from './roles.js';

/**
 * A self-describing group of extrusions of one role: its paths (closed loops or open lines), each point
 * with its own bead width when the widths vary (variable-width walls), room for a per-point Z and per-edge
 * over-air flags, and the style (feature, speed, flow, seam policy) resolved where it was made.
 */
export interface PathEntry {
  role: PathRole;
  /** For walls: 0 = outer wall, k = k-th wall inwards (the wall order setting sorts them). */
  wall?: number;
  /** Closed loops (true) or open polylines (false). */
  closed: boolean;
  paths: Pt[][];
  /** Bead width, mm, of every path without widths of its own. */
  width: number;
  /** Per path (when present): the bead width at each point, mm (null: `width` all along). */
  widths?: (Float64Array | null)[];
  /** Per path (when present): the nozzle's Z at each point above the layer's, mm (null: flat). */
  z?: (Float64Array | null)[];
  /**
   * Per path (when present), one flag per edge (edge k runs from point k to k+1, for loops the last back to
   * the first): 1 where the edge lies over nothing on the layer below. Such runs print in the style's
   * over-air variant (bridge skin, slowed overhang walls). Walls with graded styles (EntryStyle.levels) carry
   * the level instead: 1 to 4 for a quarter, half, three quarters or all of the line width over nothing
   * (roles.ts `flagStyle` gives a flag's style).
   */
  overAir?: (Uint8Array | null)[];
  /** How the entry prints, resolved from the role table where it was made (roles.ts `entryStyle`). */
  style: EntryStyle;
  /**
   * The paths print in the order given, open ones from their first point (monotonic skin, concentric skin
   * loops from the outside in, ironing); absent: the planner orders them nearest-first.
   */
  ordered?: true;
}

export type GroupKind = 'adhesion' | 'support' | 'island';

export interface PathGroup {
  kind: GroupKind;
  /** The object the group belongs to (islands), for object labels. */
  object?: number;
  /**
   * Where travel stays inside the group (combing, no retraction needed): the island's outline, or the support
   * area. Absent: travels in the group are straight and retract by the usual rule.
   */
  area?: ExPolygon;
  /** The rings travel follows round the area (the outer wall for islands); default: the area's rings. */
  boundary?: Polygon[];
  /**
   * The innermost wall's loops (islands): a travel that stays inside them crosses no wall and passes over
   * nothing but the island's own skin and infill, so it needs no retraction, however long.
   */
  inner?: Polygon[];
  /** The area is convex (a lone tree branch): a straight travel between two points in it stays in it. */
  convex?: boolean;
  entries: PathEntry[];
}

export interface LayerPaths extends LayerZ {
  /** Nominal line width of the layer, mm. */
  lineWidthMm: number;
  /** Area of the layer's islands too thin for any wall line (left out), mm²; absent when none. */
  lostMm2?: number;
  /** A spiral vase layer (LayerRegions.vase): the planner spirals it when it is one wall loop. */
  vase?: true;
  /** The first layer's area added under an open or pointed bottom (LayerRegions.firstLayerFilledMm2), mm². */
  firstLayerFilledMm2?: number;
  /** LayerRegions.vaseDroppedMm2: specks beside a spiral vase layer's main island left out, mm². */
  vaseDroppedMm2?: number;
  groups: PathGroup[];
}
