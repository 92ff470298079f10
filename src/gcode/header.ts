/**
 * The comment header at the top of the G-code: Cura's markers (which viewers, OctoPrint and Moonraker
 * read), then the same estimates in words.
 */
import type { PlanEstimate, PrintPlan } from '../plan/types.js';
import type { Settings } from '../settings/schema.js';
import { compact, humanDuration, mm } from './format.js';
import type { EncodedThumbnail } from '../thumbnail/types.js';

/** What the caller tells the writer about this file beyond plan and settings. */
export interface GcodeMeta {
  /** Program name and version for `;Generated with …`, e.g. `Strata 0.1.0`. */
  generator: string;
  /** A date/time text to record; the writer never reads the clock, so output stays deterministic. */
  date?: string;
  /** Further header comment lines (written after `;`, one per entry; newlines are flattened). */
  comments?: readonly string[];
  /** Encoded preview images to embed (see thumbnail/), in the order given. */
  thumbnails?: readonly EncodedThumbnail[];
}

const oneLine = (text: string): string => text.replace(/[\r\n]+/g, ' ');

export function headerLines(plan: PrintPlan, settings: Settings, estimate: PlanEstimate, meta: GcodeMeta, flavorName: string): string[] {
  const b = plan.bounds;
  const lines = [
    `;FLAVOR:${flavorName}`,
    `;TIME:${Math.round(estimate.printTimeSeconds)}`,
    `;Filament used: ${compact(estimate.filamentMm / 1000, 5)}m`,
    `;Layer height: ${mm(settings.layerHeight)}`,
    `;MINX:${mm(b.minX)}`,
    `;MINY:${mm(b.minY)}`,
    `;MINZ:${mm(b.minZ)}`,
    `;MAXX:${mm(b.maxX)}`,
    `;MAXY:${mm(b.maxY)}`,
    `;MAXZ:${mm(b.maxZ)}`,
    `;Generated with ${oneLine(meta.generator)}`,
  ];
  if (meta.date !== undefined) lines.push(`;Date: ${oneLine(meta.date)}`);
  lines.push(`;Estimated print time: ${humanDuration(estimate.printTimeSeconds)}`);
  lines.push(`;Estimated filament: ${compact(estimate.filamentMm / 1000, 2)} m, ${compact(estimate.filamentGrams, 2)} g`);
  for (const c of meta.comments ?? []) lines.push(`;${oneLine(c)}`);
  return lines;
}

/** Placeholder values derived from the plan and estimate, for every template (see template-vars.ts DERIVED_VALUES). */
export function derivedTemplateValues(plan: PrintPlan, estimate: PlanEstimate): Record<string, number> {
  const b = plan.bounds;
  const r3 = (v: number) => Math.round(v * 1000) / 1000;
  // the first layer's extent (skirt, brim or raft included), mm
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const step of plan.layers[0]?.steps ?? []) {
    if (step.kind !== 'extrude') continue;
    for (const p of step.points) {
      if (p.x < x0) x0 = p.x;
      if (p.y < y0) y0 = p.y;
      if (p.x > x1) x1 = p.x;
      if (p.y > y1) y1 = p.y;
    }
  }
  if (x0 > x1) x0 = y0 = x1 = y1 = 0;
  return {
    layerCount: plan.layers.length,
    printTimeSeconds: Math.round(estimate.printTimeSeconds),
    filamentMm: Math.round(estimate.filamentMm * 100) / 100,
    filamentGrams: Math.round(estimate.filamentGrams * 100) / 100,
    minX: r3(b.minX),
    minY: r3(b.minY),
    minZ: r3(b.minZ),
    maxX: r3(b.maxX),
    maxY: r3(b.maxY),
    maxZ: r3(b.maxZ),
    firstLayerMinX: r3(x0 / 1000),
    firstLayerMinY: r3(y0 / 1000),
    firstLayerMaxX: r3(x1 / 1000),
    firstLayerMaxY: r3(y1 / 1000),
  };
}
