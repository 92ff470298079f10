/**
 * Test-only helpers for the support tests: layer regions of small boxy models built by hand (sections from a
 * list of boxes, overhangs as the regions stage finds them), the support pass run to its end, and checks of
 * the result. Not exported from the package.
 */
import { rect } from '../geometry/test-shapes.js';
import { area, difference, intersection, offset, pointInArea, union } from '#strata/geometry/clip.js';
import { UM_PER_MM, type ExPolygon, type Pt } from '#strata/geometry/types.js';
import { resolveConfig, type Config } from '#strata/settings/resolve.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import type { LayerRegions } from '#strata/regions/types.js';
import { supportPass } from '#strata/support/index.js';
import { OVERHANG_XY_WIDTHS } from '#strata/support/model-layers.js';
import { drain, layersOf } from './test-layers.js';

/** An axis-aligned box, mm: x, y extents and the z range it fills. */
export interface Box {
  x: [number, number];
  y: [number, number];
  z: [number, number];
}

/** A box on a thin post: a 16 mm square plate 3 mm thick on a 4 mm square post 10 mm high. It overhangs all round. */
export const BOX_ON_POST: Box[] = [
  { x: [-2, 2], y: [-2, 2], z: [0, 10] },
  { x: [-8, 8], y: [-8, 8], z: [10, 13] },
];

/** A T: a bar 30 mm long on a 6 mm stem 10 mm high, both 20 mm deep. */
export const T_SHAPE: Box[] = [
  { x: [-3, 3], y: [-10, 10], z: [0, 10] },
  { x: [-15, 15], y: [-10, 10], z: [10, 13] },
];

/** A ledge over a lower step: a column with a ledge reaching out over a 4 mm step and beyond it. */
export const LEDGE_OVER_STEP: Box[] = [
  { x: [-15, -9], y: [-10, 10], z: [0, 12] },
  { x: [-15, 0], y: [-10, 10], z: [0, 4] },
  { x: [-15, 12], y: [-10, 10], z: [10, 12] },
];

/** A ledge 2 mm above a step that reaches 3 mm or more beyond it on every side: only the part can hold it. */
export const LEDGE_OVER_WIDE_STEP: Box[] = [
  { x: [-15, -9], y: [-10, 10], z: [0, 12] },
  { x: [-18, 15], y: [-13, 13], z: [0, 8] },
  { x: [-15, 12], y: [-10, 10], z: [10, 12] },
];

/** The model's section at height z (mm), µm. */
export function sectionAt(boxes: readonly Box[], z: number): ExPolygon[] {
  const pieces = boxes
    .filter((b) => z > b.z[0] && z < b.z[1])
    .map((b) => rect(b.x[0] * UM_PER_MM, b.y[0] * UM_PER_MM, b.x[1] * UM_PER_MM, b.y[1] * UM_PER_MM));
  return pieces.length ? union(pieces) : [];
}

/** The regions of every layer of a model made of boxes, as the regions stage leaves them for the support pass. */
export function boxLayers(boxes: readonly Box[], cfg: Config): LayerRegions[] {
  const height = Math.max(...boxes.map((b) => b.z[1]));
  const count = Math.round((height - cfg.firstLayerHeight) / cfg.layerHeight) + 1;
  return layersOf(
    count,
    (j) => sectionAt(boxes, j === 0 ? cfg.firstLayerHeight / 2 : cfg.firstLayerHeight + (j - 0.5) * cfg.layerHeight),
    cfg,
  );
}

export function supportConfig(options: SliceOptions = {}): Config {
  return resolveConfig({ supportEnabled: true, ...options });
}

/** Run the support pass to its end; returns the layers with their support filled in. */
export function supported(boxes: readonly Box[], options: SliceOptions = {}): { layers: LayerRegions[]; cfg: Config } {
  const cfg = supportConfig(options);
  const layers = boxLayers(boxes, cfg);
  drain(supportPass(layers, cfg));
  return { layers, cfg };
}

/** Every support area of a layer, merged. */
export function supportArea(layer: LayerRegions): ExPolygon[] {
  const s = layer.support;
  return s ? union([...s.body, ...s.roof, ...s.floor]) : [];
}

/** Points of `areas` on a square lattice `stepUm` apart. */
export function samplePoints(areas: readonly ExPolygon[], stepUm: number): Pt[] {
  const out: Pt[] = [];
  for (const a of areas) {
    let minX = Infinity,
      minY = Infinity,
      maxX = -Infinity,
      maxY = -Infinity;
    for (const p of a.outer) {
      minX = Math.min(minX, p.x);
      maxX = Math.max(maxX, p.x);
      minY = Math.min(minY, p.y);
      maxY = Math.max(maxY, p.y);
    }
    for (let y = Math.ceil(minY / stepUm) * stepUm; y <= maxY; y += stepUm) {
      for (let x = Math.ceil(minX / stepUm) * stepUm; x <= maxX; x += stepUm) {
        if (pointInArea({ x, y }, a)) out.push({ x, y });
      }
    }
  }
  return out;
}

/**
 * The share of the overhang points (lattice 0.5 mm) that have support right under the top Z gap (within
 * `tolUm`), counting only points support may reach: outside the part's collision on that layer.
 */
export function heldShare(
  layers: readonly LayerRegions[],
  cfg: Config,
  collision: (j: number) => ExPolygon[],
  tolUm: number,
): { held: number; total: number; missed: Pt[] } {
  let held = 0,
    total = 0;
  const missed: Pt[] = [];
  for (let m = 1; m < layers.length; m++) {
    if (layers[m].overhang.length === 0) continue;
    const j = m - 1 - cfg.supportTopGapLayers;
    if (j < 0) continue;
    const reachable = difference(layers[m].overhang, collision(j));
    const cover = offset(supportArea(layers[j]), tolUm);
    for (const p of samplePoints(reachable, 500)) {
      total++;
      if (cover.some((c) => pointInArea(p, c))) held++;
      else missed.push(p);
    }
  }
  return { held, total, missed };
}

/** Support area on each layer that lies in the part grown by the XY gap less `tolUm` (the overhang's own edge by less). */
export function intoPart(layers: readonly LayerRegions[], cfg: Config, tolUm: number): number {
  const w = cfg.supportLineWidthMm * UM_PER_MM;
  const xy = cfg.supportXYGap * UM_PER_MM;
  let total = 0;
  for (const l of layers) {
    const s = supportArea(l);
    if (s.length === 0) continue;
    const section = l.islands.map((i) => i.outline);
    const held = l.overhang.length ? difference(section, l.overhang) : section;
    const forbidden = union(offset(held, xy - tolUm), offset(section, Math.max(0, OVERHANG_XY_WIDTHS * w - tolUm)));
    total += area(intersection(s, forbidden));
  }
  return total;
}
