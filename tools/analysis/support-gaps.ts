/**
 * Z gaps of support: from the top of support to the overhang above it (per overhang cell, the highest support or
 * interface under it), and from the model to support standing on it (per cell where support starts, the part
 * under it when part, not support or raft, is the first material below).
 */
import type { GcodeLayer } from './gcode-types.js';
import type { LayerFrame } from './model-z.js';
import type { GapStats } from './report-types.js';
import { WeightedHistogram } from './stats.js';
import { LOW_BYTES, words } from './support-cells.js';
import type { LayerRasters } from './support-raster.js';
import { Cell } from './support-raster.js';

/** Z gaps are looked for this many layer heights below the layer (mm of gap beyond are not measured). */
export const GAP_SCAN_LAYERS = 6;
/** The low end of a gap distribution: the gap below which this share of the measured area lies. */
export const GAP_LOW_QUANTILE = 0.02;
/** Resolution of gap statistics (mm). */
const GAP_BIN_MM = 0.001;
/** Z comparisons between layers allow this much (mm). */
const Z_SLACK_MM = 1e-4;

/** Gaps weighted by area, in mm and in whole layers. */
export class GapMeter {
  private readonly mm: WeightedHistogram;
  private readonly byLayers = new Float64Array(GAP_SCAN_LAYERS + 2);

  constructor(
    private readonly layerHeight: number,
    private readonly cellArea: number,
  ) {
    this.mm = new WeightedHistogram((GAP_SCAN_LAYERS + 1) * layerHeight, GAP_BIN_MM);
  }

  add(gapMm: number, cells: number): void {
    const area = cells * this.cellArea;
    this.mm.add(gapMm, area);
    const n = Math.min(this.byLayers.length - 1, Math.max(0, Math.round(gapMm / this.layerHeight)));
    this.byLayers[n] = this.byLayers[n]! + area;
  }

  stats(): GapStats {
    let area = 0;
    for (const v of this.byLayers) area += v;
    const median = this.mm.quantile(0.5);
    const low = this.mm.quantile(GAP_LOW_QUANTILE);
    const layers = (mm: number) => (Number.isFinite(mm) ? Math.round(mm / this.layerHeight) : null);
    return {
      areaMm2: area,
      medianMm: Number.isFinite(median) ? median : null,
      minMm: Number.isFinite(low) ? low : null,
      medianLayers: layers(median),
      minLayers: layers(low),
      byLayers: Array.from(this.byLayers, (v) => (area > 0 ? v / area : 0)),
    };
  }
}

/** Print Z below which gap scans stop. */
function scanLimit(zBottom: number, layerHeight: number): number {
  return zBottom - GAP_SCAN_LAYERS * layerHeight - Z_SLACK_MM;
}

/**
 * Top gaps under the overhang cells `cells` (full-grid indices) of layer l, whose part material starts at print Z
 * `zBottom`.
 */
export function measureTopGap(
  meter: GapMeter,
  layers: readonly GcodeLayer[],
  rasters: LayerRasters,
  l: number,
  zBottom: number,
  cells: number[],
  layerHeight: number,
): void {
  const limit = scanLimit(zBottom, layerHeight);
  let left = cells;
  for (let k = l - 1; k >= 0 && left.length > 0 && layers[k]!.z >= limit; k--) {
    const r = rasters.get(k).bits;
    const next: number[] = [];
    let hit = 0;
    for (const q of left) {
      if ((r[q]! & (Cell.Support | Cell.Interface)) !== 0) hit++;
      else next.push(q);
    }
    if (hit > 0) meter.add(Math.max(0, zBottom - layers[k]!.z), hit);
    left = next;
  }
}

/**
 * Bottom gaps of layer l's support, whose material starts at print Z `zBottom`: measured down from the cells where
 * support starts, those with no support, interface or raft within `nearCells` (along the row or the column) on the
 * support layer whose top is at `zBottom`. The slack keeps the gaps between the dense lines of a floor from
 * counting as places where the layer above starts on the part.
 */
export function measureBottomGap(
  meter: GapMeter,
  layers: readonly GcodeLayer[],
  frames: readonly LayerFrame[],
  rasters: LayerRasters,
  l: number,
  zBottom: number,
  layerHeight: number,
  nearCells: number,
): void {
  const b = rasters.get(l).supportBounds;
  if (l === 0 || !b) return;
  const g = rasters.grid;
  // the support layer this one stands on: the one whose top is where this one's material starts (none when the
  // layer below that has no support, as when the support starts here on the part)
  let prev = -1;
  for (let k = l - 1; k >= 0 && layers[k]!.z >= zBottom - Z_SLACK_MM; k--) {
    if (Math.abs(layers[k]!.z - zBottom) <= Z_SLACK_MM && frames[k]!.hasSupport) prev = k;
  }
  const holds = Cell.Support | Cell.Interface | Cell.Raft;
  let open: number[] = [];
  const hw = words(rasters.get(l).bits);
  const below = prev >= 0 ? rasters.get(prev).bits : null;
  const perRow = g.cols >>> 2;
  for (let j = b[1]; j < b[3]; j++) {
    const row = (j - g.j0) * perRow;
    for (let w = row + ((b[0] - g.i0) >>> 2); w < row + ((b[2] - g.i0 + 3) >>> 2); w++) {
      // Support or interface here
      let start = ((hw[w]! >>> 2) | (hw[w]! >>> 3)) & LOW_BYTES;
      for (let k = 0; start !== 0; k++, start >>>= 8) {
        const q = 4 * w + k;
        if ((start & 1) !== 0 && !(below && heldNear(below, q, g.cols, g.rows, nearCells, holds))) open.push(q);
      }
    }
  }
  const limit = scanLimit(zBottom, layerHeight);
  for (let k = l - 1; k >= 0 && open.length > 0 && layers[k]!.z >= limit; k--) {
    const r = rasters.get(k).bits;
    const next: number[] = [];
    let onPart = 0;
    for (const q of open) {
      const v = r[q]!;
      if ((v & Cell.Any) === 0) next.push(q);
      else if ((v & holds) === 0) onPart++;
    }
    if (onPart > 0) meter.add(Math.max(0, zBottom - layers[k]!.z), onPart);
    open = next;
  }
}

/** Whether cell q, or one within `near` cells of it along its row or column, has any of `mask`. */
function heldNear(bits: Uint8Array, q: number, cols: number, rows: number, near: number, mask: number): boolean {
  if ((bits[q]! & mask) !== 0) return true;
  const i = q % cols,
    j = (q - i) / cols;
  for (let d = 1; d <= near; d++) {
    if ((i >= d && (bits[q - d]! & mask) !== 0) || (i + d < cols && (bits[q + d]! & mask) !== 0)) return true;
    if ((j >= d && (bits[q - d * cols]! & mask) !== 0) || (j + d < rows && (bits[q + d * cols]! & mask) !== 0))
      return true;
  }
  return false;
}
