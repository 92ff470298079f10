/**
 * Adaptive layer height: how thick a layer may be at each Z, from the slope of the model's facets.
 *
 * A layer h thick on a surface whose normal makes angle a with the vertical leaves a stair step (a cusp)
 * h·cos(a) deep across the surface (Wasserfall et al., "Adaptive Slicing for the FDM Process Revisited",
 * as PrusaSlicer's SlicingAdaptive and CuraEngine's adaptive layers use it). So a facet allows layers up to
 * cusp / |n_z| thick: vertical walls any height, near-horizontal slopes the thinnest. Facets that are flat
 * (horizontal) allow any height, and instead a layer is ended on their Z where that can be done.
 *
 * The limit is sampled on a grid of GRID_UM over the model's height (the least any facet crossing a cell
 * allows), then made to change by no more than `slope` per µm, going up and down, so that greedy layers,
 * each as thick as the limit allows over its whole span, differ by at most the step between neighbours.
 * Everything is in whole µm, so the plan is deterministic and exact.
 */
import type { Mesh } from '../mesh/types.js';

/** Cell of the sampled height limit, µm. */
export const GRID_UM = 10;
/** A facet whose Z span is at most this (µm) is flat: it bounds no height, a layer ends on it instead. */
const FLAT_UM = 1;

export interface AdaptiveSpec {
  /** Thinnest and thickest layer, µm. */
  minUm: number;
  maxUm: number;
  /** The deepest cusp allowed, µm. */
  cuspUm: number;
  /** Largest change of height between neighbouring layers, µm. */
  stepUm: number;
}

/** The cusp depth allowed by a quality 0..1: maxLayerHeight's at 0, half of minLayerHeight's at 1, geometrically. */
export function cuspFor(minMm: number, maxMm: number, quality: number): number {
  const fine = minMm / 2,
    coarse = maxMm;
  return fine ** quality * coarse ** (1 - quality);
}

/**
 * The next-layer height of an adaptive plan over these meshes (bed coordinates, mm, bottom at z = 0): a
 * function of the layer's bottom Z and the height of the layer below (µm), for `planVaryingLayers`.
 */
export function adaptiveHeights(
  meshes: readonly Mesh[],
  spec: AdaptiveSpec,
): (bottomUm: number, prevUm: number) => number {
  const { minUm, maxUm, stepUm } = spec;
  let topUm = 0;
  for (const m of meshes)
    for (let i = 2; i < m.positions.length; i += 3) topUm = Math.max(topUm, m.positions[i] * 1000);
  const cells = Math.max(1, Math.ceil(topUm / GRID_UM) + 1);
  const limit = new Float64Array(cells).fill(maxUm);
  const flats: number[] = [];
  for (const m of meshes) {
    const p = m.positions,
      idx = m.indices;
    for (let t = 0; t + 2 < idx.length; t += 3) {
      const a = 3 * idx[t],
        b = 3 * idx[t + 1],
        c = 3 * idx[t + 2];
      const az = p[a + 2] * 1000,
        bz = p[b + 2] * 1000,
        cz = p[c + 2] * 1000;
      const lo = Math.min(az, bz, cz),
        hi = Math.max(az, bz, cz);
      if (hi - lo <= FLAT_UM) {
        flats.push(Math.round((lo + hi) / 2));
        continue;
      }
      // |n_z| of the facet: the cross product's z over its length (in mm, as the positions are)
      const ux = p[b] - p[a],
        uy = p[b + 1] - p[a + 1],
        uz = p[b + 2] - p[a + 2];
      const vx = p[c] - p[a],
        vy = p[c + 1] - p[a + 1],
        vz = p[c + 2] - p[a + 2];
      const nx = uy * vz - uz * vy,
        ny = uz * vx - ux * vz,
        nz = ux * vy - uy * vx;
      const len = Math.hypot(nx, ny, nz);
      if (!(len > 0)) continue;
      const cos = Math.abs(nz) / len;
      const allowed = Math.max(minUm, spec.cuspUm / cos);
      if (allowed >= maxUm) continue;
      const k1 = Math.min(cells - 1, Math.floor(hi / GRID_UM));
      for (let k = Math.max(0, Math.floor(lo / GRID_UM)); k <= k1; k++) if (allowed < limit[k]) limit[k] = allowed;
    }
  }
  // at most `slope` µm of height per µm of Z: neighbours (together at most 2·max thick) differ by the step
  const perCell = (stepUm / (2 * maxUm)) * GRID_UM;
  for (let k = 1; k < cells; k++) limit[k] = Math.min(limit[k], limit[k - 1] + perCell);
  for (let k = cells - 2; k >= 0; k--) limit[k] = Math.min(limit[k], limit[k + 1] + perCell);
  const flatZ = [...new Set(flats)].sort((x, y) => x - y);
  return (bottomUm, prevUm) => {
    let h = Math.min(maxUm, prevUm + stepUm);
    for (let k = Math.floor(bottomUm / GRID_UM); k < cells && k * GRID_UM < bottomUm + h; k++)
      h = Math.min(h, limit[k]);
    h = Math.max(minUm, Math.floor(h));
    // end the layer on a flat face inside it, if that keeps it within the limits
    const next = firstAbove(flatZ, bottomUm);
    if (next < flatZ.length) {
      const toFlat = flatZ[next] - bottomUm;
      if (toFlat < h && toFlat >= Math.max(minUm, prevUm - stepUm)) h = toFlat;
    }
    return h;
  };
}

/** The index of the first value above z in an ascending list (its length if none). */
function firstAbove(sorted: readonly number[], z: number): number {
  let lo = 0,
    hi = sorted.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (sorted[mid] <= z) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}
