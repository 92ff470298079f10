/**
 * What the paths stage hands to the planner: per layer, groups of path entries. A group is printed as a
 * whole (an island, one support area, the adhesion around the print); an entry is one kind of path within
 * it (the outer wall, the infill, the bridge lines…), already clipped and linked. Which entry prints when is
 * data (`print-order.ts`), so support, raft or ironing are new entries, not new code in the planner.
 * Coordinates are integer µm.
 */
import type { ExPolygon, Polygon, Pt } from '../geometry/types.js';
import type { LayerZ } from '../slice/types.js';

/** What a path is for. The G-code feature, speed and print order follow from it (print-order.ts). */
export const PATH_ROLES = [
  'raft-base',
  'raft-interface',
  'raft-surface',
  'skirt',
  'brim',
  'support-floor',
  'support',
  'support-roof',
  'wall',
  'wall-gap',
  'infill',
  'skin-wall',
  'skin',
  'skin-gap',
] as const;
export type PathRole = (typeof PATH_ROLES)[number];

export interface PathEntry {
  role: PathRole;
  /** For walls: 0 = outer wall, k = k-th wall inwards (the wall order setting sorts them). */
  wall?: number;
  /** Closed loops (true) or open polylines (false). */
  closed: boolean;
  paths: Pt[][];
  /** Bead width, mm: one for every path, or one per path. */
  width: number | number[];
  /**
   * Per path (when present), one flag per edge (edge k runs from point k to k+1, for loops the last back to
   * the first): 1 where the edge lies over nothing on the layer below. Such runs print as the role's over-air
   * variant (bridge skin, slowed overhang walls).
   */
  overAir?: (Uint8Array | null)[];
  /** Speed (mm/s) and flow multiplier when the role's own (from the settings) do not apply (raft layers). */
  speed?: number;
  flow?: number;
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
  /** The area is convex (a lone tree branch): a straight travel between two points in it stays in it. */
  convex?: boolean;
  entries: PathEntry[];
}

export interface LayerPaths extends LayerZ {
  /** Nominal line width of the layer, mm. */
  lineWidth: number;
  groups: PathGroup[];
}
