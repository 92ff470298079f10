/**
 * Cross-sections of a triangle mesh by horizontal planes, and their rasterisation.
 *
 * Each triangle crossing the plane gives one segment, oriented so that the solid lies on its left (outer loops
 * counter-clockwise seen from +Z) when the mesh's triangles face outward. A vertex exactly on the plane counts as
 * above it, and every edge point is interpolated from the edge's lower to its upper vertex, so triangles sharing an
 * edge produce bit-identical points even in an unwelded mesh. Gaps of open meshes are closed (see section-gaps.ts)
 * and regions are filled with the nonzero winding rule, which also fills meshes whose triangles all face inward and
 * unions overlapping shells.
 */
import type { Mesh } from '#strata/mesh/types.js';
import { StrataError } from '#strata/errors.js';
import type { Grid } from './grid.js';
import { newBitmap } from './grid.js';
import type { SectionSegments } from './section-gaps.js';
import { closeGaps } from './section-gaps.js';
import type { Spans } from './spans.js';
import { SpansBuilder, emptySpans, sortByKey, spansToBitmap } from './spans.js';

export type { SectionSegments } from './section-gaps.js';

/** Segments shorter than this are dropped (mm); they come from triangles touching the plane at a vertex. */
const MIN_SEGMENT_MM = 1e-9;
/** Triangles per Z bucket of the sectioner's index, on average. */
const TRIANGLES_PER_BUCKET = 32;
const MAX_BUCKETS = 8192;
/** The index may list a triangle in several buckets; cap the total entries at this many per triangle. */
const MAX_ENTRIES_PER_TRIANGLE = 16;

export interface Sectioner {
  zMin: number;
  zMax: number;
  /** The section at height z (gaps closed). */
  section(z: number): SectionSegments;
  /** Whether a vertex of a triangle spanning z lies within `tolerance` of the plane. */
  touchesVertex(z: number, tolerance: number): boolean;
}

/** The section of `mesh` at height z: oriented segments, gaps of an open mesh closed. */
export function meshSection(mesh: Mesh, z: number): SectionSegments {
  checkMesh(mesh);
  const out = new SegmentCollector();
  const triangles = mesh.indices.length / 3;
  for (let t = 0; t < triangles; t++) cutTriangle(mesh, t, z, out);
  return closeGaps(out.finish());
}

/** A reusable sectioner that indexes the triangles by Z once, for many sections of one mesh. */
export function createSectioner(mesh: Mesh): Sectioner {
  checkMesh(mesh);
  const p = mesh.positions;
  const idx = mesh.indices;
  const triangles = idx.length / 3;
  let zMin = Infinity;
  let zMax = -Infinity;
  const tMin = new Float64Array(triangles);
  const tMax = new Float64Array(triangles);
  for (let t = 0; t < triangles; t++) {
    const za = p[3 * idx[3 * t]! + 2]!;
    const zb = p[3 * idx[3 * t + 1]! + 2]!;
    const zc = p[3 * idx[3 * t + 2]! + 2]!;
    tMin[t] = Math.min(za, zb, zc);
    tMax[t] = Math.max(za, zb, zc);
    if (tMin[t]! < zMin) zMin = tMin[t]!;
    if (tMax[t]! > zMax) zMax = tMax[t]!;
  }
  if (triangles === 0) {
    return { zMin: 0, zMax: 0, section: () => closeGaps(new SegmentCollector().finish()), touchesVertex: () => false };
  }
  let buckets = Math.min(MAX_BUCKETS, Math.max(1, Math.ceil(triangles / TRIANGLES_PER_BUCKET)));
  const height = () => Math.max((zMax - zMin) / buckets, 1e-9);
  const bucketOf = (z: number) => Math.min(buckets - 1, Math.max(0, Math.floor((z - zMin) / height())));
  for (;;) {
    let entries = 0;
    for (let t = 0; t < triangles; t++) entries += bucketOf(tMax[t]!) - bucketOf(tMin[t]!) + 1;
    if (entries <= MAX_ENTRIES_PER_TRIANGLE * triangles || buckets === 1) break;
    buckets = Math.max(1, Math.ceil(buckets / 4));
  }
  const start = new Uint32Array(buckets + 1);
  for (let t = 0; t < triangles; t++) {
    for (let b = bucketOf(tMin[t]!); b <= bucketOf(tMax[t]!); b++) start[b + 1]!++;
  }
  for (let b = 0; b < buckets; b++) start[b + 1] = start[b + 1]! + start[b]!;
  const list = new Uint32Array(start[buckets]!);
  const fill = start.slice(0, buckets);
  for (let t = 0; t < triangles; t++) {
    for (let b = bucketOf(tMin[t]!); b <= bucketOf(tMax[t]!); b++) list[fill[b]!++] = t;
  }
  return {
    zMin,
    zMax,
    section(z: number): SectionSegments {
      const out = new SegmentCollector();
      if (z >= zMin && z <= zMax) {
        const b = bucketOf(z);
        for (let k = start[b]!; k < start[b + 1]!; k++) {
          const t = list[k]!;
          if (tMin[t]! < z && tMax[t]! >= z) cutTriangle(mesh, t, z, out);
        }
      }
      return closeGaps(out.finish());
    },
    touchesVertex(z: number, tolerance: number): boolean {
      if (z < zMin - tolerance || z > zMax + tolerance) return false;
      const b = bucketOf(z);
      for (let k = start[b]!; k < start[b + 1]!; k++) {
        const t = list[k]!;
        for (let v = 0; v < 3; v++) if (Math.abs(p[3 * idx[3 * t + v]! + 2]! - z) <= tolerance) return true;
      }
      return false;
    },
  };
}

/**
 * Rasterises a section (as from meshSection: closed loops) onto a grid window: a cell is set when its centre is
 * inside by the nonzero winding rule.
 */
export function rasterizeSection(segments: SectionSegments, grid: Grid): Uint8Array {
  const bitmap = newBitmap(grid);
  spansToBitmap(sectionSpans(segments, grid.cell), grid, bitmap);
  return bitmap;
}

/** The section's region as spans on the lattice of cell size `cell` (nonzero winding at row centres). */
export function sectionSpans(seg: SectionSegments, cell: number): Spans {
  const n = seg.count;
  let ymin = Infinity;
  let ymax = -Infinity;
  for (let i = 0; i < n; i++) {
    ymin = Math.min(ymin, seg.y0[i]!, seg.y1[i]!);
    ymax = Math.max(ymax, seg.y0[i]!, seg.y1[i]!);
  }
  if (n === 0) return emptySpans(cell);
  // Row j (centre (j + 0.5)·cell) crosses segment [lo, hi) when lo <= centre < hi.
  const firstRow = (lo: number) => Math.ceil(lo / cell - 0.5);
  const j0 = firstRow(ymin);
  const rows = firstRow(ymax) - j0;
  if (rows <= 0) return emptySpans(cell);
  const counts = new Uint32Array(rows + 1);
  for (let i = 0; i < n; i++) {
    const ya = seg.y0[i]!;
    const yb = seg.y1[i]!;
    if (ya === yb) continue;
    const ja = firstRow(Math.min(ya, yb)) - j0;
    const jb = firstRow(Math.max(ya, yb)) - j0;
    for (let r = ja; r < jb; r++) counts[r + 1]!++;
  }
  for (let r = 0; r < rows; r++) counts[r + 1] = counts[r + 1]! + counts[r]!;
  const crossX = new Float64Array(counts[rows]!);
  const crossW = new Int8Array(counts[rows]!);
  const fill = counts.slice(0, rows);
  for (let i = 0; i < n; i++) {
    const xa = seg.x0[i]!;
    const ya = seg.y0[i]!;
    const xb = seg.x1[i]!;
    const yb = seg.y1[i]!;
    if (ya === yb) continue;
    const dir = yb > ya ? 1 : -1;
    const ja = firstRow(Math.min(ya, yb)) - j0;
    const jb = firstRow(Math.max(ya, yb)) - j0;
    const slope = (xb - xa) / (yb - ya);
    for (let r = ja; r < jb; r++) {
      const k = fill[r]!++;
      crossX[k] = xa + ((j0 + r + 0.5) * cell - ya) * slope;
      crossW[k] = dir;
    }
  }
  const out = new SpansBuilder(cell, j0, rows);
  for (let r = 0; r < rows; r++) {
    const a = counts[r]!;
    const b = counts[r + 1]!;
    sortByKey(crossX, crossW, a, b - 1);
    let w = 0;
    let from = 0;
    for (let k = a; k < b; k++) {
      const before = w;
      w += crossW[k]!;
      if (before === 0 && w !== 0) from = crossX[k]!;
      else if (before !== 0 && w === 0 && crossX[k]! > from) out.add(r, from, crossX[k]!);
    }
  }
  return out.finish();
}

function checkMesh(mesh: Mesh): void {
  if (mesh.positions.length % 3 !== 0 || mesh.indices.length % 3 !== 0) {
    throw new StrataError('BAD_MESH', 'mesh arrays must hold whole vertices and triangles');
  }
  const vertices = mesh.positions.length / 3;
  for (let k = 0; k < mesh.indices.length; k++) {
    if (mesh.indices[k]! >= vertices) {
      throw new StrataError('BAD_MESH', `triangle index ${mesh.indices[k]} is past the ${vertices} vertices`);
    }
  }
}

class SegmentCollector {
  private x0: Float64Array = new Float64Array(256);
  private y0: Float64Array = new Float64Array(256);
  private x1: Float64Array = new Float64Array(256);
  private y1: Float64Array = new Float64Array(256);
  private n = 0;
  push(ax: number, ay: number, bx: number, by: number): void {
    if (Math.abs(bx - ax) + Math.abs(by - ay) < MIN_SEGMENT_MM) return;
    if (this.n === this.x0.length) {
      this.x0 = grow(this.x0);
      this.y0 = grow(this.y0);
      this.x1 = grow(this.x1);
      this.y1 = grow(this.y1);
    }
    this.x0[this.n] = ax;
    this.y0[this.n] = ay;
    this.x1[this.n] = bx;
    this.y1[this.n] = by;
    this.n++;
  }
  finish(): SectionSegments {
    const n = this.n;
    return {
      count: n,
      x0: this.x0.slice(0, n),
      y0: this.y0.slice(0, n),
      x1: this.x1.slice(0, n),
      y1: this.y1.slice(0, n),
      synthetic: new Uint8Array(n),
      gapsClosed: 0,
      chainsDropped: 0,
    };
  }
}

function grow(a: Float64Array): Float64Array {
  const b = new Float64Array(a.length * 2);
  b.set(a);
  return b;
}

/**
 * Cuts triangle t at height z. With the triangle's vertices rotated so that the lone vertex (alone on its side of
 * the plane) comes first as (L, B, C): the segment runs from edge L-B to edge L-C when L is above the plane and
 * the other way when it is below, which puts the solid on the segment's left for outward-facing triangles.
 */
function cutTriangle(mesh: Mesh, t: number, z: number, out: SegmentCollector): void {
  const p = mesh.positions;
  const ia = mesh.indices[3 * t]!;
  const ib = mesh.indices[3 * t + 1]!;
  const ic = mesh.indices[3 * t + 2]!;
  const aUp = p[3 * ia + 2]! >= z;
  const bUp = p[3 * ib + 2]! >= z;
  const cUp = p[3 * ic + 2]! >= z;
  let l: number, b: number, c: number, loneUp: boolean;
  if (aUp === bUp) {
    if (aUp === cUp) return;
    l = ic;
    b = ia;
    c = ib;
    loneUp = cUp;
  } else if (aUp === cUp) {
    l = ib;
    b = ic;
    c = ia;
    loneUp = bUp;
  } else {
    l = ia;
    b = ib;
    c = ic;
    loneUp = aUp;
  }
  const pbx = edgeX(p, l, b, z, loneUp);
  const pby = edgeY(p, l, b, z, loneUp);
  const pcx = edgeX(p, l, c, z, loneUp);
  const pcy = edgeY(p, l, c, z, loneUp);
  if (loneUp) out.push(pbx, pby, pcx, pcy);
  else out.push(pcx, pcy, pbx, pby);
}

/** X where edge (lone, other) meets the plane, interpolated from its lower to its upper vertex. */
function edgeX(p: Float32Array, lone: number, other: number, z: number, loneUp: boolean): number {
  const lo = loneUp ? other : lone;
  const hi = loneUp ? lone : other;
  const t = (z - p[3 * lo + 2]!) / (p[3 * hi + 2]! - p[3 * lo + 2]!);
  return p[3 * lo]! + t * (p[3 * hi]! - p[3 * lo]!);
}

function edgeY(p: Float32Array, lone: number, other: number, z: number, loneUp: boolean): number {
  const lo = loneUp ? other : lone;
  const hi = loneUp ? lone : other;
  const t = (z - p[3 * lo + 2]!) / (p[3 * hi + 2]! - p[3 * lo + 2]!);
  return p[3 * lo + 1]! + t * (p[3 * hi + 1]! - p[3 * lo + 1]!);
}
