/**
 * Sampling a label field on a regular grid over a region, and locating every crossing between two
 * labels on the grid edges by bisection on the field itself (sub-pixel accurate).
 * Coordinates here are millimetres (doubles); the grid is aligned to a global lattice so adjacent
 * regions and layers sample the same points.
 */
import type { ExPolygon } from '../geometry/types.js';
import { StrataError } from '../errors.js';

/** Any function from a point (mm) to a label; equal numbers mean the same cell. */
export type LabelFn = (x: number, y: number) => number;

export interface LabelGrid {
  /** Grid spacing, mm. */
  h: number;
  /** World position of vertex (0, 0), mm. */
  x0: number;
  y0: number;
  nx: number;
  ny: number;
  /** Label per vertex (index j * nx + i); NaN where the vertex is outside the sampled area. */
  labels: Float64Array;
  /** Crossing x (mm) on horizontal edge (i,j)-(i+1,j), index j * (nx - 1) + i; NaN if none. */
  hx: Float32Array;
  /** Crossing y (mm) on vertical edge (i,j)-(i,j+1), index j * nx + i; NaN if none. */
  vy: Float32Array;
}

export interface GridOptions {
  /** Grid spacing, mm. */
  h: number;
  /** Bisection stops when the bracket is shorter than this, mm. */
  tolerance: number;
  /** Margin sampled around the region, mm (crossings just outside still link paths that enter it). */
  margin: number;
  /** Largest number of grid vertices (LIMIT_EXCEEDED beyond). */
  maxSamples: number;
  /** Fraction of h the lattice is shifted by, so boundaries at round coordinates miss the vertices. */
  phase: number;
}

/** Sorted inside-intervals [a0, b0, a1, b1, …] of the region (mm) along the horizontal line y. */
function rowIntervals(region: readonly ExPolygon[], y: number, margin: number): number[] {
  const xs: number[] = [];
  const yu = y * 1000;
  const addRing = (ring: readonly { x: number; y: number }[]) => {
    const n = ring.length;
    for (let i = 0, j = n - 1; i < n; j = i++) {
      const a = ring[i];
      const b = ring[j];
      if (a.y > yu !== b.y > yu) xs.push((a.x + ((yu - a.y) * (b.x - a.x)) / (b.y - a.y)) / 1000);
    }
  };
  for (const e of region) {
    addRing(e.outer);
    for (const hole of e.holes) addRing(hole);
  }
  xs.sort((p, q) => p - q);
  const out: number[] = [];
  for (let i = 0; i + 1 < xs.length; i += 2) {
    const a = xs[i] - margin;
    const b = xs[i + 1] + margin;
    if (out.length > 0 && a <= out[out.length - 1]) out[out.length - 1] = Math.max(out[out.length - 1], b);
    else out.push(a, b);
  }
  return out;
}

/**
 * Sample labels over the region (grown by the margin) and find every crossing.
 * `regionGrown` is the region already offset by the margin (µm), used for the row mask.
 */
export function sampleLabelGrid(
  label: LabelFn,
  regionGrown: readonly ExPolygon[],
  bounds: { minX: number; minY: number; maxX: number; maxY: number },
  opts: GridOptions,
): LabelGrid {
  const h = opts.h;
  const ph = opts.phase * h;
  const i0 = Math.floor((bounds.minX - ph) / h) - 1;
  const j0 = Math.floor((bounds.minY - ph) / h) - 1;
  const i1 = Math.ceil((bounds.maxX - ph) / h) + 1;
  const j1 = Math.ceil((bounds.maxY - ph) / h) + 1;
  const nx = i1 - i0 + 1;
  const ny = j1 - j0 + 1;
  if (!(nx > 1 && ny > 1) || nx * ny > opts.maxSamples) {
    throw new StrataError(
      'LIMIT_EXCEEDED',
      `custom infill: a ${(nx * h) | 0} × ${(ny * h) | 0} mm region at ${h} mm resolution needs ${nx * ny} samples (limit ${opts.maxSamples}); use a coarser resolution`,
    );
  }
  const x0 = i0 * h + ph;
  const y0 = j0 * h + ph;
  const labels = new Float64Array(nx * ny).fill(NaN);
  for (let j = 0; j < ny; j++) {
    const y = y0 + j * h;
    // Rows near the region: sample the intervals of this row and its neighbours (vertical margin).
    const iv = rowIntervals(regionGrown, y, h);
    for (let k = 0; k < iv.length; k += 2) {
      const ia = Math.max(0, Math.floor((iv[k] - x0) / h));
      const ib = Math.min(nx - 1, Math.ceil((iv[k + 1] - x0) / h));
      for (let i = ia; i <= ib; i++) {
        const idx = j * nx + i;
        if (labels[idx] !== labels[idx]) labels[idx] = label(x0 + i * h, y);
      }
    }
  }
  // Float32 is ample for crossings (0.03 µm at 300 mm) and halves the memory of big grids.
  const hx = new Float32Array((nx - 1) * ny).fill(NaN);
  const vy = new Float32Array(nx * (ny - 1)).fill(NaN);
  const tol = opts.tolerance;
  for (let j = 0; j < ny; j++) {
    const y = y0 + j * h;
    for (let i = 0; i + 1 < nx; i++) {
      const a = labels[j * nx + i];
      const b = labels[j * nx + i + 1];
      if (a !== a || b !== b || a === b) continue;
      let lo = x0 + i * h;
      let hi = lo + h;
      while (hi - lo > tol) {
        const mid = 0.5 * (lo + hi);
        if (label(mid, y) === a) lo = mid;
        else hi = mid;
      }
      hx[j * (nx - 1) + i] = 0.5 * (lo + hi);
    }
  }
  for (let j = 0; j + 1 < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const a = labels[j * nx + i];
      const b = labels[(j + 1) * nx + i];
      if (a !== a || b !== b || a === b) continue;
      const x = x0 + i * h;
      let lo = y0 + j * h;
      let hi = lo + h;
      while (hi - lo > tol) {
        const mid = 0.5 * (lo + hi);
        if (label(x, mid) === a) lo = mid;
        else hi = mid;
      }
      vy[j * nx + i] = 0.5 * (lo + hi);
    }
  }
  return { h, x0, y0, nx, ny, labels, hx, vy };
}
