/**
 * What the per-layer stages hand to the planner: each island's printable paths, unordered between
 * features but each feature's lines already clipped and linked. Coordinates in integer µm.
 */
import type { ExPolygon, Polygon, Polyline } from '../geometry/types.js';
import type { LayerZ } from '../slice/types.js';

export interface IslandPaths {
  /** The island's outline (its layer section): travel inside it needs no retraction. */
  outline: ExPolygon;
  /** walls[k] = closed centrelines of wall k (0 = outer wall). */
  walls: Polygon[][];
  /** Gap fill between walls: thin loops with their own bead width (mm). */
  gapFill: { loop: Polygon; width: number }[];
  /** Perimeters around skin regions. */
  skinWalls: Polygon[];
  /** Solid skin lines. */
  skinLines: Polyline[];
  /** Skin gap fill: thin loops with their own bead width (mm) where skin walls and lines leave the surface bare. */
  skinGaps: { loop: Polygon; width: number }[];
  /** Sparse infill lines and loops. */
  infillLines: Polyline[];
  infillLoops: Polygon[];
}

export interface LayerPaths extends LayerZ {
  /** Line width used on this layer, mm. */
  lineWidth: number;
  islands: IslandPaths[];
  /** Skirt or brim loops (first layer only), µm. */
  adhesion: Polygon[];
  adhesionFeature: 'SKIRT' | 'BRIM';
}
