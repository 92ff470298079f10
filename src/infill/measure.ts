/**
 * Density measurement by rasterising. Every segment is drawn as a capsule of the line width (round ends,
 * as the nozzle leaves them) into a bitmap, so crossings and overlaps count once; with a region, only the
 * footprint inside the region counts (connectors running along the boundary are half inside, line ends
 * poke out by half a width). Pixel size defaults to a tenth of the line width: error well under 1 %.
 * The density setting is not the footprint but the extruded lines (see density.ts): `lineDensity`.
 */
import { hypot, type ExPolygon, type Pt } from '../geometry/types.js';
import type { InfillResult } from './types.js';
import { area as regionArea, clipLines, offset } from '../geometry/clip.js';
import { ringsOf, rowCrossings } from './geom-util.js';

interface Raster {
  minX: number;
  minY: number;
  p: number;
  W: number;
  H: number;
  bits: Uint8Array;
}

function makeRaster(minX: number, minY: number, maxX: number, maxY: number, p: number): Raster {
  const W = Math.max(1, Math.ceil((maxX - minX) / p)),
    H = Math.max(1, Math.ceil((maxY - minY) / p));
  return { minX, minY, p, W, H, bits: new Uint8Array(W * H) };
}

function fillRow(R: Raster, j: number, xlo: number, xhi: number, value: number): void {
  const i0 = Math.max(0, Math.ceil((xlo - R.minX) / R.p - 0.5));
  const i1 = Math.min(R.W - 1, Math.floor((xhi - R.minX) / R.p - 0.5));
  for (let i = i0, o = j * R.W + i0; i <= i1; i++, o++) R.bits[o] |= value;
}

/** Interval of x where a·x + b ∈ [lo, hi]; null if empty. */
function linearRange(a: number, b: number, lo: number, hi: number): [number, number] | null {
  if (a === 0) return b >= lo && b <= hi ? [-Infinity, Infinity] : null;
  const x0 = (lo - b) / a,
    x1 = (hi - b) / a;
  return a > 0 ? [x0, x1] : [x1, x0];
}

function drawCapsule(R: Raster, A: Pt, B: Pt, r: number): void {
  const dx = B.x - A.x,
    dy = B.y - A.y;
  const len = hypot(dx, dy);
  const j0 = Math.max(0, Math.ceil((Math.min(A.y, B.y) - r - R.minY) / R.p - 0.5));
  const j1 = Math.min(R.H - 1, Math.floor((Math.max(A.y, B.y) + r - R.minY) / R.p - 0.5));
  for (let j = j0; j <= j1; j++) {
    const y = R.minY + (j + 0.5) * R.p;
    let lo = Infinity,
      hi = -Infinity;
    for (const C of [A, B]) {
      const h = r * r - (y - C.y) * (y - C.y);
      if (h >= 0) {
        const s = Math.sqrt(h);
        lo = Math.min(lo, C.x - s);
        hi = Math.max(hi, C.x + s);
      }
    }
    if (len > 0) {
      // t = ((x−Ax)dx + (y−Ay)dy)/len² ∈ [0,1];  perpendicular ((x−Ax)(−dy) + (y−Ay)dx)/len ∈ [−r, r]
      const t = linearRange(dx / (len * len), (-A.x * dx + (y - A.y) * dy) / (len * len), 0, 1);
      const n = linearRange(-dy / len, (A.x * dy + (y - A.y) * dx) / len, -r, r);
      if (t && n) {
        const a = Math.max(t[0], n[0]),
          b = Math.min(t[1], n[1]);
        if (a <= b) {
          lo = Math.min(lo, a);
          hi = Math.max(hi, b);
        }
      }
    }
    if (lo <= hi) fillRow(R, j, lo, hi, 1);
  }
}

function drawRegion(R: Raster, region: readonly ExPolygon[]): void {
  const rings = ringsOf(region);
  const xs: number[] = [];
  for (let j = 0; j < R.H; j++) {
    rowCrossings(rings, R.minY + (j + 0.5) * R.p, xs);
    for (let i = 0; i + 1 < xs.length; i += 2) fillRow(R, j, xs[i], xs[i + 1], 2);
  }
}

/**
 * Extruded footprint of an infill result, µm²: the union of all lines and loops drawn `lineWidthUm` wide
 * (crossings counted once), measured by rasterising. With `region`, only the part inside the region counts.
 */
export function extrudedAreaUm2(
  result: InfillResult,
  lineWidthUm: number,
  region?: readonly ExPolygon[],
  pixelUm?: number,
): number {
  const r = lineWidthUm / 2;
  let minX = Infinity,
    minY = Infinity,
    maxX = -Infinity,
    maxY = -Infinity;
  const paths: Array<{ pts: Pt[]; closed: boolean }> = [
    ...result.lines.map((pts) => ({ pts, closed: false })),
    ...result.loops.map((pts) => ({ pts, closed: true })),
  ];
  for (const { pts } of paths)
    for (const p of pts) {
      if (p.x < minX) minX = p.x;
      if (p.y < minY) minY = p.y;
      if (p.x > maxX) maxX = p.x;
      if (p.y > maxY) maxY = p.y;
    }
  if (minX > maxX) return 0;
  minX -= r;
  minY -= r;
  maxX += r;
  maxY += r;
  const p = pixelUm ?? Math.max(lineWidthUm / 10, Math.max(maxX - minX, maxY - minY) / 6000);
  const R = makeRaster(minX, minY, maxX, maxY, p);
  for (const { pts, closed } of paths) {
    if (pts.length === 1) drawCapsule(R, pts[0], pts[0], r);
    for (let i = 0; i + 1 < pts.length; i++) drawCapsule(R, pts[i], pts[i + 1], r);
    if (closed && pts.length > 2) drawCapsule(R, pts[pts.length - 1], pts[0], r);
  }
  let count = 0;
  if (region) {
    drawRegion(R, region);
    for (let i = 0; i < R.bits.length; i++) if (R.bits[i] === 3) count++;
  } else {
    for (let i = 0; i < R.bits.length; i++) if (R.bits[i] & 1) count++;
  }
  return count * p * p;
}

/** Measured density: extruded footprint inside the region over the region's area. */
export function measuredDensity(
  result: InfillResult,
  region: readonly ExPolygon[],
  lineWidthUm: number,
  pixelUm?: number,
): number {
  const a = regionArea(region);
  return a > 0 ? extrudedAreaUm2(result, lineWidthUm, region, pixelUm) / a : 0;
}

/** Total length of all lines and loops, µm. */
export function pathLengthUm(result: InfillResult): number {
  let l = 0;
  for (const pts of result.lines)
    for (let i = 1; i < pts.length; i++) l += hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
  for (const pts of result.loops)
    for (let i = 0; i < pts.length; i++) {
      const a = pts[i],
        b = pts[(i + 1) % pts.length];
      l += hypot(b.x - a.x, b.y - a.y);
    }
  return l;
}

/**
 * Density as the setting means it (density.ts): the length × width of the lines and loops inside the region,
 * over its area; lines that cross count twice. Connectors run on the region's edge, in the innermost wall's
 * overlap, and are left out, as the G-code analyser leaves them out (tools/analysis/infill-density.ts): only
 * what lies deeper than `insetUm` (default a tenth of the line width) counts, over the area that deep.
 */
export function lineDensity(
  result: InfillResult,
  region: readonly ExPolygon[],
  lineWidthUm: number,
  insetUm = lineWidthUm / 10,
): number {
  const inner = offset(region, -insetUm);
  const a = regionArea(inner);
  if (!(a > 0)) return 0;
  const paths = [...result.lines, ...result.loops.map((l) => [...l, l[0]])];
  return (pathLengthUm({ lines: clipLines(paths, inner), loops: [] }) * lineWidthUm) / a;
}
