/**
 * The regions stage for a run of layers: each object's sections (cut on demand, with a window of neighbours
 * for exposure detection) become the layer's `LayerRegions`: walls, gap fill, top/bottom skin, bridges, sparse
 * area, the outline over nothing (overhanging walls) and, with support on, the overhang that needs support.
 * Pure over plain data: the same result inline or in a worker, however the layers are split into runs.
 */
import { area, difference, intersection, offset, union, unionRings } from '../geometry/clip.js';
import { StrataError } from '../errors.js';
import { UM_PER_MM, type ExPolygon } from '../geometry/types.js';
import type { Config } from '../settings/resolve.js';
import { evenLayers, SectionStream, toHalfUm, type PreparedMesh } from '../slice/index.js';
import type { LayerZ } from '../slice/types.js';
import { anchoredBridge, bridgeOf } from './bridge-angle.js';
import { ironingArea, type IroningIsland } from './ironing-area.js';
import { overhangOf } from './overhang.js';
import { BelowLevels, overhangLevels } from './overhang-levels.js';
import { overhangWalls } from './overhang-walls.js';
import { allSkin, CoverWindows, skinAreas, skinLayerCounts } from './skin-areas.js';
import { rangeAt, type ObjectSetup, type PrintSetup } from './objects.js';
import type { IslandRegions, LayerRegions, RegionFill } from './types.js';
import { computeWalls } from './wall-generator.js';
import { medialScratch } from '../geometry/medial-axis.js';

export function lineWidthUm(cfg: Config, layerIndex: number): number {
  return Math.round((layerIndex === 0 ? cfg.firstLayerLineWidthMm : cfg.lineWidthMm) * UM_PER_MM);
}

interface ObjectSections {
  setup: ObjectSetup;
  /** The object's config (its skin thickness, its support). */
  cfg: Config;
  parts: SectionStream;
  negatives: SectionStream[];
  modifiers: SectionStream[];
  blockers: SectionStream[];
  enforcers: SectionStream[];
  /** Sections with the negative volumes cut out, by layer (only with negative volumes). */
  cut: Map<number, ExPolygon[]>;
  /** The highest vertex of the parts (half-µm), found when first asked for (topmost ironing). */
  topPlane?: number;
  top: CoverWindows;
  bottom: CoverWindows;
  /** With uneven layers, each layer's count of layers above and below that make the skin thickness. */
  topCounts: Int32Array | null;
  bottomCounts: Int32Array | null;
  /** The first layer's section, once asked for (#firstSection). */
  first?: { section: ExPolygon[]; addedMm2: number };
}

/**
 * A first layer with less section than this share of the layer above's is taken to be an open or pointed bottom
 * and takes the layer above's section as well (RegionsRun#firstSection). The bunny's is 0.1 %; Spot's rounded
 * hooves (8 %: 1.1 of 13.4 mm²) and a sphere's (a third) are bottoms that meet the bed, and stay as they are.
 */
const FIRST_LAYER_SHARE = 0.05;

/** Below this, mm², two objects' sections are taken not to overlap (touching faces, rounding). */
const OVERLAP_MIN_MM2 = 0.05;

/** Parts of one island's inside with one config: the whole of it (area null) or a modifier's piece. */
interface Piece {
  region: number;
  area: ExPolygon[] | null;
}

/**
 * Below this, mm², an island of a spiral vase layer other than its largest is a speck (a sliver where faces
 * nearly touch, the tip of a spike, a stray shell) and is dropped, with a warning, rather than making the
 * layer print flat: a 1.1 mm round rod. A larger second island (two objects, a vase that splits) is kept,
 * and the layer prints flat as before.
 */
export const VASE_SPECK_MM2 = 1;

/**
 * What a spiral vase layer prints of a section: the outer boundary of each island, holes dropped (as
 * Cura's spiralize: a cup modelled hollow spirals on its outside like a solid one; an island inside a hole
 * is inside the boundary, so it goes too), and, beside the largest island, those smaller than VASE_SPECK_MM2,
 * whose area (mm²) is `droppedMm2`.
 */
export function vaseOutline(section: readonly ExPolygon[]): { kept: ExPolygon[]; droppedMm2: number } {
  if (section.length === 0) return { kept: [], droppedMm2: 0 };
  const solid = section.every((e) => e.holes.length === 0) ? section.slice() : unionRings(section.map((e) => e.outer));
  if (solid.length === 1) return { kept: solid, droppedMm2: 0 };
  const areas = solid.map((e) => area([e]) / 1e6);
  let largest = 0;
  for (let k = 1; k < areas.length; k++) if (areas[k] > areas[largest]) largest = k;
  const kept: ExPolygon[] = [];
  let droppedMm2 = 0;
  for (let k = 0; k < solid.length; k++) {
    if (k === largest || areas[k] >= VASE_SPECK_MM2) kept.push(solid[k]);
    else droppedMm2 += areas[k];
  }
  return { kept, droppedMm2 };
}

/** The walls' settings: regions that agree on these share their walls. */
function wallsKey(cfg: Config): string {
  return [
    cfg.wallCount,
    cfg.wallGenerator,
    cfg.minFeatureSize,
    cfg.minBeadWidth,
    cfg.maxBeadWidth,
    cfg.wallTransitionLength,
    cfg.wallTransitionAngle,
    cfg.wallDistributionCount,
    cfg.extraPerimetersOnOverhangs,
  ].join('/');
}

/**
 * Computes the regions of layers [from, to) of the layer plan, in ascending order. Each object is sliced
 * from `from - bottomLayers` (and one more below, for overhangs) to `to + topLayers`, as far as the layers
 * asked for need.
 */
export class RegionsRun {
  readonly #setup: PrintSetup;
  readonly #cfg: Config;
  readonly #layers: readonly LayerZ[];
  readonly #lo: number;
  readonly #hi: number;
  readonly #objects: ObjectSections[];
  readonly #keepBelow: number;
  readonly #meshes: readonly PreparedMesh[];
  /** How many layers above a layer topmost ironing looks for more of the object (see #isTopmost). */
  readonly #reach: number;
  /** The medial axis's working memory for this run's layers (variable walls), this run's own. */
  readonly #axis = medialScratch();

  /** @param meshes the meshes the setup's objects point into, prepared for slicing */
  constructor(meshes: readonly PreparedMesh[], setup: PrintSetup, layers: readonly LayerZ[], from: number, to: number) {
    this.#setup = setup;
    this.#meshes = meshes;
    const cfg = (this.#cfg = setup.configs[0]);
    this.#layers = layers;
    const n = layers.length;
    const objectCfgs = setup.objects.map((o) => setup.configs[o.config]);
    // skin counts its layers by their heights when they are uneven (adaptive, a layer range's own height)
    const heights = evenLayers(layers, cfg.layerHeight)
      ? null
      : Int32Array.from(layers, (l) => Math.round(l.height * 1000));
    const counts = objectCfgs.map((c) => {
      if (!heights) return { top: null, bottom: null, maxTop: c.topLayers, maxBottom: c.bottomLayers };
      const top = skinLayerCounts(heights, c.topSkinThicknessMm, 1);
      const bottom = skinLayerCounts(heights, c.bottomSkinThicknessMm, -1);
      return {
        top,
        bottom,
        maxTop: top.reduce((a, b) => Math.max(a, b), 0),
        maxBottom: bottom.reduce((a, b) => Math.max(a, b), 0),
      };
    });
    const maxBottom = Math.max(1, ...counts.map((c) => c.maxBottom));
    const maxTop = Math.max(0, ...counts.map((c) => c.maxTop));
    this.#keepBelow = maxBottom;
    // ironing finds the top surface from the layer above, and topmost ironing looks up to #reach layers up
    this.#reach = Math.max(1, maxTop);
    const ironing = setup.configs.some((c) => c.ironingEnabled);
    this.#lo = Math.max(0, from - maxBottom);
    // the first layer reads the second's section (#firstSection)
    this.#hi = Math.min(n, Math.max(to + (ironing ? this.#reach : maxTop), this.#lo === 0 ? 2 : 0));
    const run = layers.slice(this.#lo, this.#hi);
    const tolerance = Math.round(cfg.meshTolerance * UM_PER_MM);
    const stream = (m: number) => new SectionStream(meshes[m], run, tolerance);
    this.#objects = setup.objects.map((o, k) => {
      const ocfg = objectCfgs[k];
      const sectionAt = (i: number): ExPolygon[] => this.#section(k, i);
      const top = new CoverWindows(sectionAt, ocfg.topLayers, n);
      const bottom = ocfg.bottomLayers === ocfg.topLayers ? top : new CoverWindows(sectionAt, ocfg.bottomLayers, n);
      return {
        setup: o,
        cfg: ocfg,
        parts: stream(o.parts),
        negatives: o.negatives.map(stream),
        modifiers: o.modifiers.map(stream),
        blockers: o.blockers.map(stream),
        enforcers: o.enforcers.map(stream),
        cut: new Map(),
        top,
        bottom,
        topCounts: counts[k].top,
        bottomCounts: counts[k].bottom,
      };
    });
  }

  #inRun(i: number): boolean {
    return i >= this.#lo && i < this.#hi;
  }

  /** The sections of volumes of one kind on layer i, together. */
  #volumes(streams: readonly SectionStream[], i: number): ExPolygon[] {
    if (!this.#inRun(i) || streams.length === 0) return [];
    const all: ExPolygon[] = [];
    for (const s of streams) for (const a of s.at(i - this.#lo).islands) all.push(a);
    return streams.length > 1 ? union(all) : all;
  }

  /** Object k's section of layer i: its parts less its negative volumes (the first layer repaired: #firstSection). */
  #section(k: number, i: number): ExPolygon[] {
    if (!this.#inRun(i)) return [];
    const o = this.#objects[k];
    if (i === 0) return (o.first ??= this.#firstSection(k)).section;
    return this.#cutSection(o, i);
  }

  /**
   * Object k's section of the first layer. Where the model's bottom is open (holes in the mesh there) or comes to
   * the bed in a point or a thin rim, its section halfway up the first layer has little or nothing of what the
   * model has just above: the first printed layer would be the second one, 0.2 mm over the bed. There (less
   * than FIRST_LAYER_SHARE of the section of the layer above) the first layer takes the union of both sections,
   * as Cura unites the sections through its first layer's thickness, and the area added is reported. Sinking the
   * model into the bed (as PrusaSlicer may) would cut away a layer of the model everywhere; this adds under it
   * only what the open bottom lacks, and leaves a model with a proper bottom exactly as it was.
   */
  #firstSection(k: number): { section: ExPolygon[]; addedMm2: number } {
    const o = this.#objects[k];
    const own = this.#cutSection(o, 0);
    if (!this.#inRun(1)) return { section: own, addedMm2: 0 };
    const above = this.#cutSection(o, 1);
    const aboveArea = above.length ? area(above) : 0;
    if (aboveArea === 0 || area(own) >= FIRST_LAYER_SHARE * aboveArea) return { section: own, addedMm2: 0 };
    const section = own.length ? union(own, above) : above;
    return { section, addedMm2: (area(section) - area(own)) / (UM_PER_MM * UM_PER_MM) };
  }

  #cutSection(o: ObjectSections, i: number): ExPolygon[] {
    const parts = o.parts.at(i - this.#lo).islands;
    if (o.negatives.length === 0 || parts.length === 0) return parts;
    let s = o.cut.get(i);
    if (!s) {
      const neg = this.#volumes(o.negatives, i);
      o.cut.set(i, (s = neg.length ? difference(parts, neg) : parts));
    }
    return s;
  }

  /** Every object's section of layer i, as one list of islands. */
  #layerSection(i: number): ExPolygon[] {
    if (this.#objects.length === 1) return this.#section(0, i);
    const all: ExPolygon[] = [];
    for (let o = 0; o < this.#objects.length; o++) for (const a of this.#section(o, i)) all.push(a);
    return all;
  }

  /** Object k's pieces of layer i with a config each: the modifiers' (a later one wins), and the rest. */
  #pieces(k: number, i: number, section: readonly ExPolygon[]): Piece[] {
    const o = this.#objects[k];
    const row = o.setup.regions[rangeAt(o.setup, this.#layers[i].sliceZ)];
    if (o.modifiers.length === 0 || section.length === 0) return [{ region: row[0], area: null }];
    const pieces: Piece[] = [];
    let claimed: ExPolygon[] = [];
    for (let m = o.modifiers.length - 1; m >= 0; m--) {
      const mod = this.#volumes([o.modifiers[m]], i);
      if (mod.length === 0) continue;
      const inside = intersection(section, mod);
      const own = claimed.length && inside.length ? difference(inside, claimed) : inside;
      if (own.length) pieces.push({ region: row[m + 1], area: own });
      claimed = claimed.length ? union(claimed, mod) : mod;
    }
    if (pieces.length === 0) return [{ region: row[0], area: null }];
    const rest = difference(section, claimed);
    if (rest.length) pieces.push({ region: row[0], area: rest });
    // pieces of one config are one piece
    const byRegion = new Map<number, ExPolygon[]>();
    for (const p of pieces) byRegion.set(p.region, [...(byRegion.get(p.region) ?? []), ...p.area!]);
    if (byRegion.size === 1) return [{ region: pieces[0].region, area: null }];
    return [...byRegion].sort((a, b) => a[0] - b[0]).map(([region, area]) => ({ region, area }));
  }

  /**
   * The skin and infill of one region of an island, and where it irons when it does (`iron`: the island's
   * outline and top surface, `piece`: the region's part of it, null for all of it).
   */
  #fill(
    k: number,
    i: number,
    region: number,
    inner: readonly ExPolygon[],
    below: readonly ExPolygon[],
    w: number,
    iron: IroningIsland | null = null,
    piece: readonly ExPolygon[] | null = null,
  ): RegionFill {
    const o = this.#objects[k];
    const cfg = this.#setup.configs[region];
    const topLayers = o.topCounts ? o.topCounts[i] : o.cfg.topLayers;
    const bottomLayers = o.bottomCounts ? o.bottomCounts[i] : o.cfg.bottomLayers;
    const coveredAbove = inner.length ? o.top.window(i + 1, topLayers) : [];
    const coveredBelow = inner.length ? o.bottom.window(i - bottomLayers, bottomLayers) : [];
    const skin = skinAreas(
      inner,
      coveredAbove,
      coveredBelow,
      topLayers,
      bottomLayers,
      w,
      cfg.topSkinPattern !== cfg.bottomSkinPattern,
    );
    const bridge = i > 0 ? bridgeOf(skin.bottom, below, w) : null;
    // a bridge with two anchors is grown onto them (bridgeAnchor): that area is bottom skin, printed as bridge
    let bridgeFill: RegionFill['bridgeFill'];
    if (bridge && bridge.area.length && bridge.lines != null) {
      const anchored = anchoredBridge(bridge.area, inner, Math.round(cfg.bridgeAnchor * UM_PER_MM));
      if (anchored.length) {
        bridgeFill = { area: anchored, angle: bridge.lines };
        skin.bottom = union(skin.bottom, anchored);
        if (skin.top.length) skin.top = difference(skin.top, anchored);
      }
    }
    const skinAll = allSkin(skin);
    const overlapInfill = (cfg.infillOverlap / 100) * w;
    const ironsAll = iron !== null && this.#irons(k, i, cfg) && cfg.ironingType === 'all';
    const rest = cfg.infillDensity > 0 || ironsAll ? (skinAll.length ? difference(inner, skinAll) : inner) : [];
    const sparse = cfg.infillDensity > 0 ? offset(rest, -(w / 2 - overlapInfill)) : [];
    const fill: RegionFill = {
      region,
      topSkin: skin.top,
      bottomSkin: skin.bottom,
      skin: skinAll,
      exposed: skin.exposed,
      bridge: bridge?.area ?? [],
      bridgeAngle: bridge && bridge.mostly ? bridge.angle : null,
      sparse,
    };
    if (bridgeFill) fill.bridgeFill = bridgeFill;
    if (skin.both) fill.topAndBottom = skin.both;
    if (iron && this.#irons(k, i, cfg)) {
      // solid throughout: no sparse area left, or sparse infill as good as solid (OrcaSlicer: over 95 %)
      const area = ironingArea(cfg.ironingType, iron, piece, fill, rest.length === 0 || cfg.infillDensity > 95, w / 2);
      if (area.length) fill.ironing = area;
    }
    return fill;
  }

  /** Whether a region of object k with config `cfg` irons on layer i. */
  #irons(k: number, i: number, cfg: Config): boolean {
    return cfg.ironingEnabled && (cfg.ironingType !== 'topmost' || this.#isTopmost(k, i));
  }

  /**
   * Whether layer i is object k's last layer with material: no layer above it that still cuts the parts'
   * mesh has any of the object (a tip too small to slice, a negative volume over the top). Only #reach
   * layers up are looked at, the same for every layer, so the answer does not depend on how the layers are
   * split into runs; an object that goes on further up is taken to have material there.
   */
  #isTopmost(k: number, i: number): boolean {
    const o = this.#objects[k];
    if (o.topPlane === undefined) {
      const zq = this.#meshes[o.setup.parts].zq;
      let top = -Infinity;
      for (let v = 0; v < zq.length; v++) if (zq[v] > top) top = zq[v];
      o.topPlane = top;
    }
    for (let j = i + 1; j < this.#layers.length && toHalfUm(this.#layers[j].sliceZ) <= o.topPlane; j++) {
      if (j > i + this.#reach || this.#section(k, j).length) return false;
    }
    return true;
  }

  /**
   * Object k's islands of layer i.
   * @param levelsBelow the layer below as measured for the overhang levels of walls
   */
  #islands(
    k: number,
    i: number,
    w: number,
    below: readonly ExPolygon[],
    belowGrown: readonly ExPolygon[],
    levelsBelow: BelowLevels,
  ): IslandRegions[] {
    const section = this.#section(k, i);
    const pieces = this.#pieces(k, i, section);
    const configs = this.#setup.configs;
    // regions that lay the same walls share them: one wall set round all of them
    const groups = new Map<string, Piece[]>();
    for (const p of pieces) {
      const key = pieces.length === 1 ? '' : wallsKey(configs[p.region]);
      groups.set(key, [...(groups.get(key) ?? []), p]);
    }
    const out: IslandRegions[] = [];
    for (const group of groups.values()) {
      const area =
        groups.size === 1 ? section : group.length === 1 ? group[0].area! : union(group.flatMap((p) => p.area!));
      const first = group[0].region;
      const irons = group.some((p) => this.#irons(k, i, configs[p.region]));
      const wallCfg = configs[first];
      for (const iw of computeWalls(area, wallCfg, w, this.#axis)) {
        // extra walls over the overhangs inside the walls that cannot bridge take their area from skin and infill
        const extra =
          i > 0 && wallCfg.extraPerimetersOnOverhangs ? overhangWalls(iw.inner, below, w, wallCfg.wallCount) : null;
        const inside = extra ? difference(iw.inner, extra.covered) : iw.inner;
        const fills: RegionFill[] = [];
        // the island's top surface, where a region of it irons
        let iron: IroningIsland | null = null;
        if (irons) {
          const above = this.#section(k, i + 1);
          iron = { outline: iw.outline, topSurface: above.length ? difference([iw.outline], above) : [iw.outline] };
        }
        for (const p of group) {
          const inner = group.length === 1 ? inside : intersection(inside, p.area!);
          if (inner.length || group.length === 1)
            fills.push(this.#fill(k, i, p.region, inner, below, w, iron, group.length === 1 ? null : p.area));
        }
        const main = fills.shift() ?? this.#fill(k, i, first, [], below, w);
        const island: IslandRegions = {
          object: k,
          ...main,
          outline: iw.outline,
          walls: iw.walls,
          lostMm2: iw.lostMm2,
          unsupported: i > 0 ? difference([iw.outline], belowGrown) : [],
        };
        if (fills.length) island.fills = fills;
        if (extra) island.extraWalls = extra.rings;
        if (i > 0 && wallCfg.dynamicOverhangSpeeds) {
          const levels = overhangLevels(iw.outline, levelsBelow, w);
          if (levels) island.overhangLevels = levels;
        }
        out.push(island);
      }
    }
    return out;
  }

  /**
   * Whether layer i is a spiral vase layer: spiralVase on and the layer above the bottom skin's layers
   * (the print's bottomSkinThickness: the vase's floor).
   */
  #vase(i: number): boolean {
    return this.#cfg.spiralVase && i >= this.#cfg.bottomLayers;
  }

  /**
   * Object k's islands of a spiral vase layer: the outer boundary of its section (vaseOutline: holes dropped,
   * specks beside the main island dropped), one outer wall round each island left (laid with the object's own
   * wall settings, modifiers aside: a vase has no inside for them to change), and nothing inside it.
   */
  #vaseIslands(
    k: number,
    i: number,
    w: number,
    belowGrown: readonly ExPolygon[],
    levelsBelow: BelowLevels,
  ): { islands: IslandRegions[]; droppedMm2: number } {
    const o = this.#objects[k];
    const region = o.setup.regions[rangeAt(o.setup, this.#layers[i].sliceZ)][0];
    const cfg = this.#setup.configs[region];
    const oneWall: Config = { ...cfg, wallCount: 1, extraPerimetersOnOverhangs: false };
    const { kept, droppedMm2 } = vaseOutline(this.#section(k, i));
    const islands = computeWalls(kept, oneWall, w, this.#axis).map((iw): IslandRegions => {
      const island: IslandRegions = {
        object: k,
        region,
        topSkin: [],
        bottomSkin: [],
        skin: [],
        exposed: [],
        bridge: [],
        bridgeAngle: null,
        sparse: [],
        outline: iw.outline,
        walls: iw.walls,
        lostMm2: iw.lostMm2,
        unsupported: i > 0 ? difference([iw.outline], belowGrown) : [],
      };
      if (i > 0 && cfg.dynamicOverhangSpeeds) {
        const levels = overhangLevels(iw.outline, levelsBelow, w);
        if (levels) island.overhangLevels = levels;
      }
      return island;
    });
    return { islands, droppedMm2 };
  }

  /** Object k's overhang on layer i, with its support blockers and enforcers. */
  #overhang(k: number, i: number, islands: readonly IslandRegions[], grownUm: number): ExPolygon[] {
    const o = this.#objects[k];
    const z = this.#layers[i];
    if (i === 0 || !(o.cfg.supportEnabled || o.enforcers.length) || this.#vase(i)) return [];
    const section = this.#section(k, i);
    const below = this.#section(k, i - 1);
    let over = o.cfg.supportEnabled
      ? overhangOf(section, below, z.height, o.cfg, false, {
          any: islands.some((r) => r.unsupported.length > 0),
          grownUm,
        })
      : [];
    const enforced = this.#volumes(o.enforcers, i);
    if (enforced.length) {
      // inside an enforcer every overhang is held, however steep
      const more = overhangOf(intersection(section, enforced), below, z.height, { ...o.cfg, supportThreshold: 0 });
      if (more.length) over = over.length ? union(over, more) : more;
    }
    const blocked = this.#volumes(o.blockers, i);
    if (blocked.length && over.length) over = difference(over, blocked);
    return over;
  }

  /** The regions of layer i (call in ascending order). */
  layer(i: number): LayerRegions {
    const cfg = this.#cfg;
    const z = this.#layers[i];
    const w = lineWidthUm(cfg, i);
    const below = i > 0 ? this.#layerSection(i - 1) : [];
    // a wall is over air where its centreline is more than half a line width out from the layer below
    // (as PrusaSlicer marks overhang perimeters): the parts of the outline beyond that grown section
    const belowGrown = below.length ? offset(below, w / 2) : below;
    const levelsBelow = new BelowLevels(below, w);
    const islands: IslandRegions[] = [];
    const overhangs: ExPolygon[][] = [];
    let droppedMm2 = 0;
    for (let k = 0; k < this.#objects.length; k++) {
      let own: IslandRegions[];
      if (this.#vase(i)) {
        const v = this.#vaseIslands(k, i, w, belowGrown, levelsBelow);
        own = v.islands;
        droppedMm2 += v.droppedMm2;
      } else own = this.#islands(k, i, w, below, belowGrown, levelsBelow);
      for (const r of own) islands.push(r);
      overhangs.push(this.#overhang(k, i, own, w / 2));
    }
    this.#checkOverlaps(i);
    const vase = this.#vase(i)
      ? droppedMm2 > 0
        ? { vase: true as const, vaseDroppedMm2: droppedMm2 }
        : { vase: true as const }
      : {};
    let filled = 0;
    if (i === 0) for (const o of this.#objects) filled += o.first?.addedMm2 ?? 0;
    const repaired = filled > 0 ? { firstLayerFilledMm2: filled } : {};
    if (overhangs.length === 1) return { ...z, islands, overhang: overhangs[0], support: null, ...vase, ...repaired };
    return { ...z, islands, overhang: overhangs.flat(), overhangs, support: null, ...vase, ...repaired };
  }

  /** Refuse objects with different settings that share volume on layer i. */
  #checkOverlaps(i: number): void {
    for (const [a, b] of this.#setup.overlapPairs) {
      const sa = this.#section(a, i),
        sb = this.#section(b, i);
      if (!sa.length || !sb.length) continue;
      const shared = area(intersection(sa, sb)) / 1e6;
      if (shared > OVERLAP_MIN_MM2) {
        const na = this.#setup.objects[a].name,
          nb = this.#setup.objects[b].name;
        throw new StrataError(
          'OVERLAPPING_OBJECTS',
          `objects "${na}" and "${nb}" overlap (${shared.toFixed(1)} mm² at Z ${this.#layers[i].z.toFixed(2)} mm) and have different settings or volumes of their own: move them apart, give them the same settings, or make one a modifier of the other`,
        );
      }
    }
  }

  /** Forget sections no later layer (from i on) needs. */
  release(i: number): void {
    const keepFrom = i - this.#keepBelow - 1 - this.#lo;
    for (const o of this.#objects) {
      for (const s of [o.parts, ...o.negatives, ...o.modifiers, ...o.blockers, ...o.enforcers]) s.release(keepFrom);
      for (const key of o.cut.keys()) if (key - this.#lo < keepFrom) o.cut.delete(key);
    }
  }
}

/** The whole layer's sparse area (every island's, merged), for whole-model infill passes. */
export function layerSparse(layer: LayerRegions, regions?: (region: number) => boolean): ExPolygon[] {
  const all: ExPolygon[] = [];
  for (const island of layer.islands) {
    for (const f of island.fills ? [island, ...island.fills] : [island])
      if (!regions || regions(f.region)) all.push(...f.sparse);
  }
  return all.length > 1 ? union(all) : all;
}

/** The whole layer's top skin. */
export function layerTopSkin(layer: LayerRegions): ExPolygon[] {
  return layer.islands.flatMap((i) => (i.fills ? [i, ...i.fills].flatMap((f) => f.topSkin) : i.topSkin));
}
