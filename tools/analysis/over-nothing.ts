/**
 * Candidates for part extrusion over nothing: part cells of a layer with no material of the layers below within
 * the threshold's allowance, outside the interior of the model layer below (whose sparse infill is the part's
 * own design). The footprint test in support.ts then decides which of them the closed material below holds.
 */
import { squaredDistance } from './morphology.js';
import type { Spans } from './spans.js';
import { erodeSpans, isEmptySpans } from './spans.js';
import { LOW_BYTES, cellBounds, inWindow, outsideSpans, windowIn, windowOf, words } from './support-cells.js';
import type { LayerRaster, LayerRasters } from './support-raster.js';
import { Cell } from './support-raster.js';

/** Candidates search discs around each cell while that reads fewer cells than this many windows. */
const DISC_SEARCH_LIMIT = 4;

/**
 * Full-grid indices of part cells of `here` with no material of the layers `below` within `reachMm`, outside
 * the interior (`previous` shrunk by `wallThickness`). Cells right above material are skipped four at a time; the
 * rest look for material in the disc of the reach around them, or read one distance transform when that is
 * cheaper.
 */
export function overNothingCandidates(
  rasters: LayerRasters,
  here: LayerRaster,
  below: number[],
  previous: Spans,
  reachMm: number,
  wallThickness: number,
): number[] {
  const out: number[] = [];
  const b = here.partBounds;
  if (!b) return out;
  const g = rasters.grid;
  const under = below.map((k) => rasters.get(k).bits);
  const under4 = under.map(words);
  const bits = words(here.bits);
  const perRow = g.cols >>> 2;
  const open: number[] = [];
  for (let j = b[1]; j < b[3]; j++) {
    const row = (j - g.j0) * perRow;
    for (let w = row + ((b[0] - g.i0) >>> 2); w < row + ((b[2] - g.i0 + 3) >>> 2); w++) {
      let part = (bits[w]! >>> 1) & LOW_BYTES;
      if (part === 0) continue;
      for (const r of under4) part &= ~r[w]!;
      part &= LOW_BYTES;
      for (let k = 0; part !== 0; k++, part >>>= 8) if ((part & 1) !== 0) open.push(4 * w + k);
    }
  }
  if (open.length === 0) return out;
  const interior = erodeSpans(previous, wallThickness);
  const outside = isEmptySpans(interior) ? open : outsideSpans(open, g, interior);
  if (outside.length === 0) return out;
  const rc = reachMm / g.cell;
  const win = windowIn(g, cellBounds(g, null, outside), reachMm + 2 * g.cell);
  if (outside.length * Math.PI * rc * rc > DISC_SEARCH_LIMIT * win.cols * win.rows) {
    const d = squaredDistance(windowOf(rasters, win, below, Cell.Any), win.cols, win.rows, 1);
    const r2 = rc * rc + 1e-9;
    for (const q of outside) if (d[inWindow(g, win, q)]! > r2) out.push(q);
    return out;
  }
  const reach = Math.floor(rc);
  const r2 = rc * rc;
  for (const q of outside) {
    const ci = q % g.cols;
    const cj = (q - ci) / g.cols;
    let held = false;
    for (let dj = -reach; dj <= reach && !held; dj++) {
      const jj = cj + dj;
      if (jj < 0 || jj >= g.rows) continue;
      const span = Math.floor(Math.sqrt(Math.max(0, r2 - dj * dj)));
      const from = jj * g.cols + Math.max(0, ci - span);
      const to = jj * g.cols + Math.min(g.cols - 1, ci + span);
      for (const r of under) {
        for (let k = from; k <= to && !held; k++) if (r[k] !== 0) held = true;
        if (held) break;
      }
    }
    if (!held) out.push(q);
  }
  return out;
}
