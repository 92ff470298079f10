/**
 * The section outline against the extrusions: how much of the outline has an extrusion centreline within a line
 * width (walls present), and by how much the extrusions are shifted in XY relative to the outline. Outline along
 * features thinner than half a line width (no slicer can wall them) is counted apart.
 *
 * Shift: at outline samples p with outward normal n, the nearest extrusion point q gives the offset
 * s = (q − p)·n. A wall inset by c and shifted by d gives s ≈ −c + d·n, so (c, d) follow from a least-squares
 * fit over the samples; because ∮ n ds = 0 around a closed outline, a uniform inset does not leak into d.
 * Samples whose residual exceeds half a line width after a first fit (corners, nearby features) are dropped and
 * the fit redone.
 */
import type { SectionSegments } from './section-gaps.js';
import type { SegmentIndex, WindingIndex } from './segment-index.js';

export interface OutlineOptions {
  /** Outline samples with an extrusion centreline within this distance count as walled (mm). */
  coverRadius: number;
  /** Nearest extrusions farther than this are ignored by the shift fit (mm). */
  searchRadius: number;
  /** Distance between outline samples (mm). */
  step: number;
  /** Residual (mm) beyond which a sample is dropped from the second fit. */
  outlier: number;
  /**
   * Outline samples where the section is thinner than this (the point this far inside is not inside) belong to
   * features too thin to print a wall along (mm).
   */
  minThickness: number;
}

export interface OutlineMetrics {
  /** Outline length (synthetic gap-closing segments and thin features excluded), mm. */
  lengthMm: number;
  /** Outline length along features thinner than minThickness, mm. */
  thinLengthMm: number;
  /** Fraction of the outline length with an extrusion within coverRadius (NaN without outline). */
  coverage: number;
  /** Fitted XY shift of the extrusions relative to the outline (mm), null when too few samples. */
  shift: { dx: number; dy: number; inset: number } | null;
}

/** Fewer fitted samples than this give no shift estimate. */
const MIN_FIT_SAMPLES = 8;

export function outlineMetrics(
  section: SectionSegments,
  inside: WindingIndex,
  extrusions: SegmentIndex,
  o: OutlineOptions,
): OutlineMetrics {
  let length = 0;
  let thin = 0;
  let covered = 0;
  const nx: number[] = [];
  const ny: number[] = [];
  const off: number[] = [];
  const wt: number[] = [];
  for (let i = 0; i < section.count; i++) {
    if (section.synthetic[i] !== 0) continue;
    const ax = section.x0[i]!,
      ay = section.y0[i]!;
    const dx = section.x1[i]! - ax,
      dy = section.y1[i]! - ay;
    const len = Math.hypot(dx, dy);
    if (len <= 0) continue;
    const n = Math.max(1, Math.ceil(len / o.step));
    const w = len / n;
    // Solid on the left, so the outward normal is the right-hand normal.
    const ox = dy / len;
    const oy = -dx / len;
    for (let k = 0; k < n; k++) {
      const t = (k + 0.5) / n;
      const px = ax + t * dx;
      const py = ay + t * dy;
      if (inside.winding(px - ox * o.minThickness, py - oy * o.minThickness) === 0) {
        thin += w;
        continue;
      }
      length += w;
      const d = extrusions.nearest(px, py, o.searchRadius);
      if (d <= o.coverRadius) covered += w;
      if (d !== Infinity) {
        nx.push(ox);
        ny.push(oy);
        off.push((extrusions.qx - px) * ox + (extrusions.qy - py) * oy);
        wt.push(w);
      }
    }
  }
  let fit = fitShift(nx, ny, off, wt, null, 0);
  if (fit) fit = fitShift(nx, ny, off, wt, fit, o.outlier) ?? fit;
  return {
    lengthMm: length,
    thinLengthMm: thin,
    coverage: length > 0 ? covered / length : NaN,
    shift: fit ? { dx: fit[1], dy: fit[2], inset: -fit[0] } : null,
  };
}

/** Weighted least squares for s ≈ b0 + b1·nx + b2·ny; with `prev`, samples off it by more than `outlier` drop. */
function fitShift(
  nx: number[],
  ny: number[],
  s: number[],
  w: number[],
  prev: [number, number, number] | null,
  outlier: number,
): [number, number, number] | null {
  const m = new Float64Array(9);
  const v = new Float64Array(3);
  let used = 0;
  for (let k = 0; k < s.length; k++) {
    const a0 = 1,
      a1 = nx[k]!,
      a2 = ny[k]!;
    if (prev && Math.abs(s[k]! - (prev[0] + prev[1] * a1 + prev[2] * a2)) > outlier) continue;
    const wk = w[k]!;
    const row = [a0, a1, a2];
    for (let r = 0; r < 3; r++) {
      v[r] = v[r]! + wk * row[r]! * s[k]!;
      for (let c = 0; c < 3; c++) m[3 * r + c] = m[3 * r + c]! + wk * row[r]! * row[c]!;
    }
    used++;
  }
  if (used < MIN_FIT_SAMPLES) return null;
  // A small ridge keeps directions the outline cannot observe (all normals parallel) at zero shift.
  const ridge = 1e-6 * (m[0]! + m[4]! + m[8]!);
  m[4] = m[4]! + ridge;
  m[8] = m[8]! + ridge;
  return solve3(m, v);
}

function solve3(m: Float64Array, v: Float64Array): [number, number, number] | null {
  const a = m[0]!,
    b = m[1]!,
    c = m[2]!,
    d = m[3]!,
    e = m[4]!,
    f = m[5]!,
    g = m[6]!,
    h = m[7]!,
    i = m[8]!;
  const det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  if (Math.abs(det) < 1e-18) return null;
  const x = (v[0]! * (e * i - f * h) - b * (v[1]! * i - f * v[2]!) + c * (v[1]! * h - e * v[2]!)) / det;
  const y = (a * (v[1]! * i - f * v[2]!) - v[0]! * (d * i - f * g) + c * (d * v[2]! - v[1]! * g)) / det;
  const z = (a * (e * v[2]! - v[1]! * h) - b * (d * v[2]! - v[1]! * g) + v[0]! * (d * h - e * g)) / det;
  return [x, y, z];
}
