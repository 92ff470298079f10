/**
 * Stray material: distances of the part's extrusion centrelines beyond the model section grown by half a line
 * width, and the area of bead raster there.
 */
import type { ExtrusionTable } from './gcode-types.js';
import type { Grid } from './grid.js';
import { bitmapAt, newBitmap } from './grid.js';
import type { CachedSection } from './section-cache.js';
import { SegmentIndex, WindingIndex } from './segment-index.js';
import { countInSpans, dilateSpans, erodeSpans, spansBoolean, spansToBitmap } from './spans.js';
import { quantileWithZeros } from './stats.js';

/** Outside-distance searches look this far before falling back to a search of the whole section, mm. */
const OUTSIDE_SEARCH_MM = 5;

export interface OutsideMetrics {
  /** Nonzero excess distances of centreline samples (mm), and the number of samples. */
  positives: Float64Array;
  samples: number;
  maxMm: number;
  p99Mm: number;
  areaMm2: number;
}

/**
 * Samples every part segment at `step` mm. Where the section is ambiguous (the plane runs through mesh vertices),
 * material inside either reading is inside. `inside` indexes section.segments.
 */
export function measureOutside(
  t: ExtrusionTable,
  partIds: Uint32Array,
  section: CachedSection,
  inside: WindingIndex,
  grid: Grid,
  material: Uint8Array,
  materialCells: number,
  tolerance: number,
  step: number,
): OutsideMetrics {
  const cell = grid.cell;
  const main = section.segments;
  const up = section.above?.segments ?? null;
  const windUp = up ? new WindingIndex(up.x0, up.y0, up.x1, up.y1, up.count, 1) : null;
  const nearMain = new SegmentIndex(main.x0, main.y0, main.x1, main.y1, null, main.count, 1);
  const nearUp = up ? new SegmentIndex(up.x0, up.y0, up.x1, up.y1, null, up.count, 1) : null;
  const region = section.above ? spansBoolean(section.spans, section.above.spans, 'union') : section.spans;
  // Samples in cells whose centre lies within (tolerance - 3/4 cell) of the section are within the tolerance
  // wherever they sit in the cell: no exact test needed. (Spans sample the section, so they never overstate it.)
  const safe = newBitmap(grid);
  const safeRadius = tolerance - 0.75 * cell;
  spansToBitmap(safeRadius > 0 ? dilateSpans(region, safeRadius) : erodeSpans(region, 2 * cell), grid, safe);
  const positives: number[] = [];
  let samples = 0;
  for (const i of partIds) {
    const ax = t.x0[i]!,
      ay = t.y0[i]!;
    const dx = t.x1[i]! - ax,
      dy = t.y1[i]! - ay;
    const n = Math.max(1, Math.ceil(Math.hypot(dx, dy) / step));
    samples += n + 1;
    for (let k = 0; k <= n; k++) {
      const px = ax + (dx * k) / n;
      const py = ay + (dy * k) / n;
      if (bitmapAt(safe, grid, px, py)) continue;
      if (inside.winding(px, py) !== 0 || (windUp !== null && windUp.winding(px, py) !== 0)) continue;
      let d = distance(nearMain, px, py, tolerance);
      if (nearUp) d = Math.min(d, distance(nearUp, px, py, tolerance));
      if (d > tolerance) positives.push(d - tolerance);
    }
  }
  const arr = Float64Array.from(positives);
  const [, kept] = countInSpans(dilateSpans(region, tolerance), grid, material);
  return {
    positives: arr,
    samples,
    maxMm: arr.reduce((m, v) => Math.max(m, v), 0),
    p99Mm: quantileWithZeros(arr.slice(), samples, 0.99),
    areaMm2: (materialCells - kept) * cell * cell,
  };
}

/** Distance to the nearest outline segment, searched first within the tolerance, then farther, then everywhere. */
function distance(index: SegmentIndex, px: number, py: number, tolerance: number): number {
  let d = index.nearest(px, py, tolerance);
  if (d === Infinity) d = index.nearest(px, py, OUTSIDE_SEARCH_MM);
  if (d === Infinity) d = index.nearest(px, py, Number.MAX_SAFE_INTEGER);
  return d;
}
