/**
 * What the regions stage computes for every layer, once: each island's outline, walls, skin, bridge and
 * sparse areas, and the layer's overhang, support and adhesion areas. Plain data (integer µm), so a layer's
 * regions cross a worker boundary as they are; every later pass (lightning, support, raft, the paths of the
 * layer) reads them instead of slicing again.
 */
import type { RegularPolygon } from '../geometry/regular-polygon.js';
import type { ExPolygon, Pt } from '../geometry/types.js';
import type { LayerZ } from '../slice/types.js';

/**
 * Wall paths of one index: closed loops or open lines (a thin feature's middle line), each with one width
 * per point where the widths vary.
 */
export interface WallSet {
  /** `wall`, or `wall-gap` for classic walls' thin gap loops. */
  role: 'wall' | 'wall-gap';
  /** 0 = outer wall, k = k-th inwards. */
  wall: number;
  closed: boolean;
  paths: Pt[][];
  /** Per path, the bead width at each point, mm (null: the layer's line width); null for none at all. */
  widths: (Float64Array | null)[] | null;
}

/** One ring of extra walls over an overhang: open lines, with their own widths where they vary (gap fill). */
export interface ExtraWallRing {
  paths: Pt[][];
  /** Per path, the bead width at each point, mm (null: the layer's line width); null for none at all. */
  widths: (Float64Array | null)[] | null;
}

/**
 * The skin and infill areas of one region of an island: inside the island's walls, where one config
 * applies (the object's, or a layer range's or modifier's).
 */
export interface RegionFill {
  /** Index of the config the region reads (PrintSetup.configs). */
  region: number;
  /** Top skin inside the walls: exposed within the top skin thickness above. */
  topSkin: ExPolygon[];
  /** Bottom skin inside the walls: exposed within the bottom skin thickness below. */
  bottomSkin: ExPolygon[];
  /** All skin inside the walls, top and bottom as one area (the one of them alone, when the other is empty). */
  skin: ExPolygon[];
  /** Every exposed area inside the walls, slivers included: what skin gap fill must still reach. */
  exposed: ExPolygon[];
  /** The part of the bottom skin over nothing on the layer below (before support is known). */
  bridge: ExPolygon[];
  /** Direction of lines over `bridge`, degrees (support to support), or null when there are no two anchors. */
  bridgeAngle: number | null;
  /** Centreline area of the sparse infill. */
  sparse: ExPolygon[];
  /**
   * The bridge as its lines print (bridge-angle.ts, anchoredBridge): `bridge` grown by bridgeAnchor into the
   * region's area held by the layer below, and the direction of its lines, support to support. Absent where the
   * bridge has no two anchors (a cantilever: its skin keeps the skin's lines, flagged over air).
   */
  bridgeFill?: { area: ExPolygon[]; angle: number };
  /**
   * The part of `bottomSkin` exposed above too: printed in the top skin's pattern (set only where the top
   * and bottom skin patterns differ).
   */
  topAndBottom?: ExPolygon[];
  /** Where the region irons after its skin (ironingEnabled; ironing-area.ts), µm. */
  ironing?: ExPolygon[];
}

/**
 * One island of one layer: its outline and walls (laid with the config `region`), and its skin and infill
 * (the region's, and with modifiers inside it, further `fills` with configs of their own).
 */
export interface IslandRegions extends RegionFill {
  /** The object the island belongs to (index into the pipeline's object list). */
  object: number;
  /** The island's section outline. */
  outline: ExPolygon;
  /** The walls, as sets of loops or lines of one wall index (classic walls' gap loops apart). */
  walls: WallSet[];
  /** Area of the island too thin to print (thinner than the smallest feature the walls lay), mm². */
  lostMm2: number;
  /** The part of the outline more than half a line width out from the layer below: walls there are overhangs. */
  unsupported: ExPolygon[];
  /**
   * With dynamic overhang speeds (overhang-levels.ts): where a wall's centreline has a quarter, half and three
   * quarters of the line width or more over nothing (levels 1 to 3; `unsupported` is level 4, all of it).
   */
  overhangLevels?: ExPolygon[][];
  /**
   * With extra perimeters on overhangs (overhang-walls.ts): lines over the overhangs inside the walls that
   * cannot bridge, ring by ring in print order (from the anchor outwards).
   */
  extraWalls?: ExtraWallRing[];
  /** The skin and infill of the parts of the island inside modifiers whose configs differ from `region`'s. */
  fills?: RegionFill[];
}

/** Support areas of one layer (filled by the support pass), µm. */
export interface SupportAreas {
  /** Support body (sparse columns or tree branches). */
  body: ExPolygon[];
  /** Dense interface under the part (roof). */
  roof: ExPolygon[];
  /** Dense interface where support stands on the part (floor). */
  floor: ExPolygon[];
  /**
   * The pieces of `body` (the same objects) that are straight columns in tree support (under its pockets),
   * printed as normal support's body is, with its walls (supportColumnWalls).
   */
  columnBody?: ExPolygon[];
  /** Body, roof and floor as the one area they were split from, when the pass has it (saves a union). */
  whole?: ExPolygon[];
  /**
   * Per island of `whole`, when that island is a lone regular polygon standing for a circle (a tree branch):
   * its centre and circumradius, µm, and its side count; then its walls and fill are made without an offset.
   */
  circles?: (RegularPolygon | null)[];
}

/** Raft layer areas (filled by the raft pass). */
export interface RaftArea {
  kind: 'base' | 'interface' | 'surface';
  area: ExPolygon[];
}

export interface LayerRegions extends LayerZ {
  islands: IslandRegions[];
  /**
   * The model's area on this layer that needs support: not within the overhang angle's reach of the layer
   * below (specks dropped). Computed only when support is on.
   */
  overhang: ExPolygon[];
  support: SupportAreas | null;
  /**
   * With several objects: per object, its overhang (`overhang` is all of them) and its own support
   * (`support` is all of them together), so that each object's support prints with the object.
   */
  overhangs?: ExPolygon[][];
  supports?: (SupportAreas | null)[];
  /** Set on raft layers (below the model's first layer), which have no islands. */
  raft?: RaftArea;
  /**
   * Set on the layers of a spiral vase above its bottom (spiralVase): each island has one outer wall and no
   * skin, infill, ironing or support; the planner spirals the layer's wall when it is one single loop.
   */
  vase?: true;
  /**
   * On the first layer, where an object's bottom was open or too thin to print and the first layer took the
   * section of the layer above as well: the area that added, mm².
   */
  firstLayerFilledMm2?: number;
  /** On a spiral vase layer: the area of the specks beside its main island dropped (vaseOutline), mm². */
  vaseDroppedMm2?: number;
}

/** What is kept of an island once its paths are made: whose it is and its outline. */
export type IslandOutline = Pick<IslandRegions, 'object' | 'region' | 'outline'>;

/**
 * A layer cut down to its islands' outlines, once its own paths are made: what the support and raft passes
 * and the skirt read (every LayerRegions is one). Keeping every layer's full regions alive until the end
 * cost ~9 % of the run in garbage collection.
 */
export interface LayerOutlines extends Omit<LayerRegions, 'islands'> {
  islands: IslandOutline[];
}

/** The layer's outlines (see LayerOutlines). */
export function outlinesOf(layer: LayerRegions): LayerOutlines {
  return { ...layer, islands: layer.islands.map((i) => ({ object: i.object, region: i.region, outline: i.outline })) };
}

/** The layer's whole section (every island's outline). */
export function sectionOf(layer: LayerOutlines): ExPolygon[] {
  return layer.islands.map((i) => i.outline);
}
