/**
 * The regions stage for a run of layers: each object's sections (cut on demand, with a window of neighbours
 * for exposure detection) become the layer's `LayerRegions`: walls, gap fill, top/bottom skin, bridges, sparse
 * area, the outline over nothing (overhanging walls) and, with support on, the overhang that needs support.
 * Pure over plain data: the same result inline or in a worker, however the layers are split into runs.
 */
import { difference, offset, union } from '../geometry/clip.js';
import { UM_PER_MM, type ExPolygon } from '../geometry/types.js';
import type { Config } from '../settings/resolve.js';
import { SectionStream, type PreparedMesh } from '../slice/index.js';
import type { LayerZ } from '../slice/types.js';
import { bridgeOf } from './bridge-angle.js';
import { overhangOf } from './overhang.js';
import { allSkin, CoverWindows, skinAreas } from './skin-areas.js';
import type { IslandRegions, LayerRegions } from './types.js';
import { computeWalls } from './wall-generator.js';

export function lineWidthUm(cfg: Config, layerIndex: number): number {
  return Math.round((layerIndex === 0 ? cfg.firstLayerLineWidthMm : cfg.lineWidthMm) * UM_PER_MM);
}

interface ObjectSections {
  stream: SectionStream;
  top: CoverWindows;
  bottom: CoverWindows;
}

/**
 * Computes the regions of layers [from, to) of the layer plan, in ascending order. Each object is sliced
 * from `from - bottomLayers` (and one more below, for overhangs) to `to + topLayers`, as far as the layers
 * asked for need.
 */
export class RegionsRun {
  readonly #cfg: Config;
  readonly #layers: readonly LayerZ[];
  readonly #lo: number;
  readonly #hi: number;
  readonly #objects: ObjectSections[];

  constructor(meshes: readonly PreparedMesh[], cfg: Config, layers: readonly LayerZ[], from: number, to: number) {
    this.#cfg = cfg;
    this.#layers = layers;
    const n = layers.length;
    this.#lo = Math.max(0, from - Math.max(cfg.bottomLayers, 1));
    this.#hi = Math.min(n, to + cfg.topLayers);
    const run = layers.slice(this.#lo, this.#hi);
    const tolerance = Math.round(cfg.meshTolerance * UM_PER_MM);
    this.#objects = meshes.map((mesh) => {
      const stream = new SectionStream(mesh, run, tolerance);
      const sectionAt = (i: number): ExPolygon[] => (i >= this.#lo && i < this.#hi ? stream.at(i - this.#lo).islands : []);
      const top = new CoverWindows(sectionAt, cfg.topLayers, n);
      const bottom = cfg.bottomLayers === cfg.topLayers ? top : new CoverWindows(sectionAt, cfg.bottomLayers, n);
      return { stream, top, bottom };
    });
  }

  #section(object: number, i: number): ExPolygon[] {
    return i >= this.#lo && i < this.#hi ? this.#objects[object].stream.at(i - this.#lo).islands : [];
  }

  /** Every object's section of layer i, as one list of islands. */
  #layerSection(i: number): ExPolygon[] {
    if (this.#objects.length === 1) return this.#section(0, i);
    const all: ExPolygon[] = [];
    for (let o = 0; o < this.#objects.length; o++) for (const a of this.#section(o, i)) all.push(a);
    return all;
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
    const islands: IslandRegions[] = [];
    const infillOn = cfg.infillDensity > 0;
    const overlapInfill = (cfg.infillOverlap / 100) * w;
    for (let o = 0; o < this.#objects.length; o++) {
      const walls = computeWalls(this.#section(o, i), cfg, w);
      const anyInner = walls.some((iw) => iw.inner.length > 0);
      const coveredAbove = anyInner ? this.#objects[o].top.window(i + 1) : [];
      const coveredBelow = anyInner ? this.#objects[o].bottom.window(i - cfg.bottomLayers) : [];
      for (const iw of walls) {
        const skin = skinAreas(iw.inner, coveredAbove, coveredBelow, cfg.topLayers, cfg.bottomLayers, w);
        const skinAll = allSkin(skin);
        const sparse = infillOn ? offset(skinAll.length ? difference(iw.inner, skinAll) : iw.inner, -(w / 2 - overlapInfill)) : [];
        const bridge = i > 0 ? bridgeOf(skin.bottom, below, w) : null;
        islands.push({
          object: o,
          outline: iw.outline,
          walls: iw.walls,
          lostMm2: iw.lostMm2,
          topSkin: skin.top,
          bottomSkin: skin.bottom,
          exposed: skin.exposed,
          bridge: bridge?.area ?? [],
          bridgeAngle: bridge && bridge.mostly ? bridge.angle : null,
          sparse,
          unsupported: i > 0 ? difference([iw.outline], belowGrown) : [],
        });
      }
    }
    const overhang = cfg.supportEnabled
      ? overhangOf(this.#layerSection(i), below, z.height, cfg, i === 0, { any: islands.some((r) => r.unsupported.length > 0), grownUm: w / 2 })
      : [];
    return { ...z, islands, overhang, support: null };
  }

  /** Forget sections no later layer (from i on) needs. */
  release(i: number): void {
    const keepFrom = i - Math.max(this.#cfg.bottomLayers, 1) - 1 - this.#lo;
    for (const o of this.#objects) o.stream.release(keepFrom);
  }
}

/** The whole layer's sparse area (every island's, merged), for whole-model infill passes. */
export function layerSparse(layer: LayerRegions): ExPolygon[] {
  const all = layer.islands.flatMap((i) => i.sparse);
  return all.length > 1 ? union(all) : all;
}

/** The whole layer's top skin. */
export function layerTopSkin(layer: LayerRegions): ExPolygon[] {
  return layer.islands.flatMap((i) => i.topSkin);
}
