/**
 * Extrusion segments rasterised as capsules (a bead of width w is every point within w/2 of its centreline) onto a
 * grid window, with widths from the extruded volume or a nominal width, and coverage of one bitmap by another.
 */
import type { ExtrusionTable } from './gcode-types.js';
import type { Grid } from './grid.js';
import { columnsOf, newBitmap } from './grid.js';

/** Cross-section area of filament of diameter d (mm²). */
export function filamentArea(diameter: number): number {
  return (Math.PI * diameter * diameter) / 4;
}

/**
 * Width of the bead that segment i deposits on a layer of height h, from its extruded volume, with the bead's
 * cross-section taken as a rectangle with semicircular ends (width w, height h): area = (w - h)·h + π·h²/4, so
 * w = area/h + h·(1 - π/4). This is the physical width both PrusaSlicer (which uses this model) and Cura (which
 * extrudes w·h per mm, so its beads squish a little wider than their spacing) lay down.
 */
export function beadWidth(e: number, length: number, h: number, filamentAreaMm2: number): number {
  if (length <= 0 || h <= 0) return 0;
  return (e * filamentAreaMm2) / (length * h) + h * (1 - Math.PI / 4);
}

/**
 * Width-equivalent of the extruded volume per mm of path per layer height: area/h. Multiplied by the path length
 * it is the area the material covers at full density, used for infill density (it equals the line spacing that
 * Cura and PrusaSlicer both use to turn a density setting into line distances).
 */
export function volumeWidth(e: number, length: number, h: number, filamentAreaMm2: number): number {
  if (length <= 0 || h <= 0) return 0;
  return (e * filamentAreaMm2) / (length * h);
}

export function segmentLength(t: ExtrusionTable, i: number): number {
  return Math.hypot(t.x1[i]! - t.x0[i]!, t.y1[i]! - t.y0[i]!);
}

/**
 * Sets (to `value`) every cell whose centre lies within r of segment (ax, ay)-(bx, by); with `or`, ORs `value`
 * into those cells instead (bitmaps of flag bits).
 */
export function stampCapsule(
  bitmap: Uint8Array,
  grid: Grid,
  ax: number,
  ay: number,
  bx: number,
  by: number,
  r: number,
  value = 1,
  or = false,
): void {
  const c = grid.cell;
  const dx = bx - ax;
  const dy = by - ay;
  const len = Math.hypot(dx, dy);
  const ux = len > 0 ? dx / len : 1;
  const uy = len > 0 ? dy / len : 0;
  const nx = -uy;
  const ny = ux;
  const jFirst = Math.max(grid.j0, Math.ceil((Math.min(ay, by) - r) / c - 0.5));
  const jLast = Math.min(grid.j0 + grid.rows - 1, Math.floor((Math.max(ay, by) + r) / c - 0.5));
  for (let j = jFirst; j <= jLast; j++) {
    const yc = (j + 0.5) * c;
    let lo = Infinity;
    let hi = -Infinity;
    const da = yc - ay;
    if (Math.abs(da) <= r) {
      const s = Math.sqrt(r * r - da * da);
      lo = ax - s;
      hi = ax + s;
    }
    const db = yc - by;
    if (Math.abs(db) <= r) {
      const s = Math.sqrt(r * r - db * db);
      lo = Math.min(lo, bx - s);
      hi = Math.max(hi, bx + s);
    }
    if (len > 0) {
      // The band: |signed distance to the line| <= r and 0 <= projection <= len, both linear in x.
      let bandLo = -Infinity;
      let bandHi = Infinity;
      const sOff = da * ny;
      if (Math.abs(nx) > 1e-12) {
        const p = (-r - sOff) / nx;
        const q = (r - sOff) / nx;
        bandLo = ax + Math.min(p, q);
        bandHi = ax + Math.max(p, q);
      } else if (Math.abs(sOff) > r) {
        bandLo = Infinity;
      }
      const tOff = da * uy;
      if (Math.abs(ux) > 1e-12) {
        const p = -tOff / ux;
        const q = (len - tOff) / ux;
        bandLo = Math.max(bandLo, ax + Math.min(p, q));
        bandHi = Math.min(bandHi, ax + Math.max(p, q));
      } else if (tOff < 0 || tOff > len) {
        bandLo = Infinity;
      }
      if (bandHi >= bandLo) {
        lo = Math.min(lo, bandLo);
        hi = Math.max(hi, bandHi);
      }
    }
    if (hi < lo) continue;
    const [first, last] = columnsOf(grid, lo, hi);
    if (last >= first) {
      const base = (j - grid.j0) * grid.cols;
      if (!or) bitmap.fill(value, base + first, base + last + 1);
      else for (let k = base + first; k <= base + last; k++) bitmap[k] = bitmap[k]! | value;
    }
  }
}

/**
 * The bitmap grown by about r (mm): a superset of every cell whose centre is within r of a set cell's centre,
 * larger by at most r·√2/4. Discs are stamped only at boundary cells, and at most one per square of side r/4
 * (with the radius grown by that square's diagonal), so the cost follows the outline length, not the area.
 */
export function dilateBitmap(bitmap: Uint8Array, grid: Grid, r: number): Uint8Array {
  const out = bitmap.slice();
  const { cols, rows, cell } = grid;
  const block = Math.max(1, Math.floor(r / 4 / cell));
  const radius = r + block * cell * Math.SQRT2;
  const bCols = Math.ceil(cols / block);
  const stamped = new Uint8Array(bCols * Math.ceil(rows / block));
  for (let j = 0; j < rows; j++) {
    const base = j * cols;
    const bRow = Math.floor(j / block) * bCols;
    for (let i = 0; i < cols; i++) {
      const k = base + i;
      if (bitmap[k] === 0) continue;
      const boundary =
        i === 0 ||
        bitmap[k - 1] === 0 ||
        i === cols - 1 ||
        bitmap[k + 1] === 0 ||
        j === 0 ||
        bitmap[k - cols] === 0 ||
        j === rows - 1 ||
        bitmap[k + cols] === 0;
      if (!boundary) continue;
      const b = bRow + Math.floor(i / block);
      if (stamped[b] !== 0) continue;
      stamped[b] = 1;
      const x = (grid.i0 + i + 0.5) * cell;
      const y = (grid.j0 + j + 0.5) * cell;
      stampCapsule(out, grid, x, y, x, y, radius);
    }
  }
  return out;
}

/**
 * Rasterises the selected segments of a table as capsules of their widths (`widths[i]`, or one width for all).
 * `select` picks segment ids; all segments when omitted.
 */
export function rasterizeExtrusions(
  table: ExtrusionTable,
  grid: Grid,
  widths: Float32Array | number,
  select?: (i: number) => boolean,
): Uint8Array {
  const bitmap = newBitmap(grid);
  for (let i = 0; i < table.count; i++) {
    if (select && !select(i)) continue;
    const w = typeof widths === 'number' ? widths : widths[i]!;
    stampCapsule(bitmap, grid, table.x0[i]!, table.y0[i]!, table.x1[i]!, table.y1[i]!, w / 2);
  }
  return bitmap;
}

/** Fraction of the cells set in `region` that are also set in `covered` (NaN for an empty region). */
export function coverage(covered: Uint8Array, region: Uint8Array): number {
  let total = 0;
  let hit = 0;
  for (let k = 0; k < region.length; k++) {
    if (region[k] === 0) continue;
    total++;
    if (covered[k] !== 0) hit++;
  }
  return total === 0 ? NaN : hit / total;
}
