/**
 * Sparse infill density. The region is the section shrunk by the wall thickness and one line width more (where
 * infill overlaps or runs along the innermost wall), minus the model's skin within the skin thickness plus
 * skinMargin above and below grown sideways by skinMargin, minus (with feature types) the solid infill the G-code
 * prints grown by a line width. The density is the FILL lines' extruded volume per layer height — the area they
 * would cover at full density — over the region's area, which is the quantity Cura and PrusaSlicer both turn a
 * density setting into line distances with.
 */
import { Feature, isPartFeature } from './feature-names.js';
import type { ExtrusionTable } from './gcode-types.js';
import type { Grid } from './grid.js';
import { newBitmap } from './grid.js';
import { dilateBitmap, stampCapsule, volumeWidth } from './raster.js';
import type { Spans } from './spans.js';
import {
  bitmapToSpans,
  erodeSpans,
  isEmptySpans,
  spansArea,
  spansBoolean,
  spansContain,
  spansToBitmap,
} from './spans.js';

/** Infill regions smaller than this (mm²) give no density. */
const MIN_INFILL_REGION_MM2 = 1;

export interface InfillOptions {
  wallThickness: number;
  lineWidth: number;
  skinMargin: number;
  /** Use FILL-typed lines only (else every part line). */
  typed: boolean;
  /** Width per mm of path from E ('flow') or the nominal line width. */
  widthSource: 'flow' | 'nominal';
  layerHeight: number;
  filamentArea: number;
}

export interface InfillMetrics {
  regionAreaMm2: number;
  /** NaN when the region is smaller than MIN_INFILL_REGION_MM2. */
  density: number;
}

/** `skin`: the model's skin near this layer; `beadWidths`: bead widths of the table's segments. */
export function measureInfill(
  t: ExtrusionTable,
  grid: Grid,
  beadWidths: Float32Array,
  section: Spans,
  skin: Spans,
  o: InfillOptions,
): InfillMetrics {
  let region = erodeSpans(section, o.wallThickness + o.lineWidth);
  if (!isEmptySpans(skin)) region = spansBoolean(region, skin, 'subtract');
  if (!isEmptySpans(region)) {
    let excluded = newBitmap(grid);
    if (!isEmptySpans(skin)) {
      spansToBitmap(skin, grid, excluded);
      excluded = dilateBitmap(excluded, grid, o.skinMargin);
    }
    if (o.typed) {
      for (let i = 0; i < t.count; i++) {
        if (t.feature[i] !== Feature.Skin) continue;
        stampCapsule(excluded, grid, t.x0[i]!, t.y0[i]!, t.x1[i]!, t.y1[i]!, beadWidths[i]! / 2 + o.lineWidth);
      }
    }
    region = spansBoolean(region, bitmapToSpans(excluded, grid), 'subtract');
  }
  const area = spansArea(region);
  if (area < MIN_INFILL_REGION_MM2) return { regionAreaMm2: area, density: NaN };
  const step = grid.cell / 2;
  let covered = 0;
  for (let i = 0; i < t.count; i++) {
    const f = t.feature[i]!;
    if (o.typed ? f !== Feature.Fill : !isPartFeature(f)) continue;
    const ax = t.x0[i]!,
      ay = t.y0[i]!;
    const dx = t.x1[i]! - ax,
      dy = t.y1[i]! - ay;
    const len = Math.hypot(dx, dy);
    const n = Math.max(1, Math.ceil(len / step));
    let inside = 0;
    for (let k = 0; k < n; k++) {
      if (spansContain(region, ax + (dx * (k + 0.5)) / n, ay + (dy * (k + 0.5)) / n)) inside++;
    }
    if (inside === 0) continue;
    const w = o.widthSource === 'nominal' ? o.lineWidth : volumeWidth(t.e[i]!, len, o.layerHeight, o.filamentArea);
    covered += (len * inside * w) / n;
  }
  return { regionAreaMm2: area, density: covered / area };
}
