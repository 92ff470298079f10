/**
 * Exposure detection for top and bottom skin, done exactly with polygon booleans.
 * A part of a layer's inner area is top skin when any of the `topLayers` layers above lacks material
 * there, and bottom skin when any of the `bottomLayers` layers below does. Areas with material on
 * every layer within the skin thickness above and below (covered areas, cavity interiors) get none.
 */
import { difference, intersection, opening, union } from '../geometry/clip.js';
import type { ExPolygon } from '../geometry/types.js';
import { LAYER_SHARE_EPS } from '../geometry/tolerances.js';

export interface SkinAreas {
  top: ExPolygon[];
  bottom: ExPolygon[];
  /** All exposed area (top or bottom) before slivers were dropped: what skin gap fill must still reach. */
  exposed: ExPolygon[];
  /** The part of `bottom` exposed above too (within the top skin thickness), when asked for and not empty. */
  both?: ExPolygon[];
}

/**
 * Skin areas of one island.
 * @param inner the island's area inside its walls, µm
 * @param coveredAbove area with material on each of the `topLayers` layers above (CoverWindows.window), µm
 * @param coveredBelow the same for the `bottomLayers` layers below
 * @param minWidthUm features of skin narrower than this are dropped (they are slivers along the walls)
 * @param wantBoth also give the part of the bottom skin that is exposed above (`both`)
 */
export function skinAreas(
  inner: readonly ExPolygon[],
  coveredAbove: readonly ExPolygon[],
  coveredBelow: readonly ExPolygon[],
  topLayers: number,
  bottomLayers: number,
  minWidthUm: number,
  wantBoth = false,
): SkinAreas {
  if (inner.length === 0) return { top: [], bottom: [], exposed: [] };
  const topRaw = topLayers > 0 ? difference(inner, coveredAbove) : [];
  const bottomRaw = bottomLayers > 0 ? difference(inner, coveredBelow) : [];
  if (topRaw.length === 0 && bottomRaw.length === 0) return { top: [], bottom: [], exposed: [] };
  // Drop slivers from the skin as a whole (cleaning top and bottom apart would also drop the seam
  // between them), then split it: a region that is both is printed once, as bottom (it rests on nothing).
  const raw = topRaw.length === 0 ? bottomRaw : bottomRaw.length === 0 ? topRaw : union(topRaw, bottomRaw);
  const all = minWidthUm > 0 ? opening(raw, minWidthUm / 2) : raw;
  if (bottomRaw.length === 0) return { top: all, bottom: [], exposed: raw };
  if (topRaw.length === 0) return { top: [], bottom: all, exposed: raw };
  const bottom = intersection(all, bottomRaw);
  const out: SkinAreas = { top: difference(all, bottom), bottom, exposed: raw };
  if (wantBoth) {
    const both = intersection(bottom, topRaw);
    if (both.length) out.both = both;
  }
  return out;
}

/**
 * Intersections of `count` consecutive layer sections, computed once per window start and shared:
 * the area covered above layer i (window i+1) is the area covered below layer i+count+1. Windows of
 * any count are built from pairwise intersections, so each costs about two booleans.
 */
export class CoverWindows {
  readonly #sectionAt: (i: number) => readonly ExPolygon[];
  readonly #count: number;
  readonly #layers: number;
  readonly #pairs = new Map<number, ExPolygon[]>();
  /** By window start and count (start · MAX_WINDOW + count). */
  readonly #windows = new Map<number, ExPolygon[]>();

  /**
   * @param sectionAt the section of layer i ([] outside the model)
   * @param count layers per window, unless a window is asked for with its own
   * @param layers number of layers of the model (a window reaching past them covers nothing)
   */
  constructor(sectionAt: (i: number) => readonly ExPolygon[], count: number, layers: number) {
    this.#sectionAt = sectionAt;
    this.#count = count;
    this.#layers = layers;
  }

  /** ∩ sections[a .. a+1] */
  #pair(a: number): ExPolygon[] {
    let p = this.#pairs.get(a);
    if (!p) {
      const s0 = this.#sectionAt(a),
        s1 = this.#sectionAt(a + 1);
      p = s0.length && s1.length ? intersection(s0, s1) : [];
      this.#pairs.set(a, p);
    }
    return p;
  }

  /** The area covered by material on every layer a .. a+count-1 (count: the constructor's, or a layer's own with uneven layers). */
  window(a: number, count = this.#count): ExPolygon[] {
    const n = count;
    if (n <= 0 || a < 0 || a + n > this.#layers) return [];
    const key = a * MAX_WINDOW + Math.min(n, MAX_WINDOW - 1);
    let w = this.#windows.get(key);
    if (w) return w;
    if (n === 1) w = this.#sectionAt(a).slice();
    else {
      // cover [a, a+n) with pairs starting at a, a+2, …, and a final pair ending at a+n-1
      w = this.#pair(a);
      for (let k = a + 2; k + 1 < a + n && w.length; k += 2) w = intersection(w, this.#pair(k));
      if (n % 2 === 1 && w.length) w = intersection(w, this.#pair(a + n - 2));
    }
    this.#windows.set(key, w);
    return w;
  }
}

/** Windows longer than this many layers share a cache key (no skin is that many layers). */
const MAX_WINDOW = 1 << 16;

/**
 * How many layers above (`dir` 1) or below (-1) each layer make a skin thickness, with uneven layers: the
 * fewest neighbours whose heights together reach it (each layer's top skin is then the least stack of
 * layers from the top that is that thick, however thick each layer is). Where the layers run out, a count
 * reaching past them (its window covers nothing). With even layers this is ceil(thickness / layerHeight),
 * as the config's topLayers and bottomLayers.
 */
export function skinLayerCounts(heightsUm: ArrayLike<number>, thicknessMm: number, dir: 1 | -1): Int32Array {
  const n = heightsUm.length;
  const out = new Int32Array(n);
  if (thicknessMm <= 0) return out;
  // as ceil(t / h − LAYER_SHARE_EPS): a stack within that share of a layer of the thickness reaches it
  const need = thicknessMm * 1000;
  for (let i = 0; i < n; i++) {
    let k = 0,
      sum = 0,
      reached = false;
    for (let j = i + dir; j >= 0 && j < n && !reached; j += dir) {
      k++;
      sum += heightsUm[j];
      reached = sum >= need - LAYER_SHARE_EPS * heightsUm[j];
    }
    out[i] = reached ? k : k + 1;
  }
  return out;
}

/** All skin of a layer as one area. */
export function allSkin(s: SkinAreas): ExPolygon[] {
  if (s.top.length === 0) return s.bottom;
  if (s.bottom.length === 0) return s.top;
  return union(s.top, s.bottom);
}
