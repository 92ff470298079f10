/**
 * The comment header at the top of the G-code: Cura's markers (which viewers, OctoPrint and Moonraker
 * read), then the same estimates in words.
 */
import type { PlanEstimate, PrintPlan } from '../plan/types.js';
import type { Settings } from '../settings/schema.js';
import { compact, humanDuration, mm } from './format.js';
import type { TemplateValues } from './template.js';
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

/** Placeholder values derived from the plan and estimate, for start/end templates. */
export function derivedTemplateValues(plan: PrintPlan, estimate: PlanEstimate): TemplateValues {
  const b = plan.bounds;
  return {
    layerCount: plan.layers.length,
    printTimeSeconds: Math.round(estimate.printTimeSeconds),
    filamentMm: Math.round(estimate.filamentMm * 100) / 100,
    filamentGrams: Math.round(estimate.filamentGrams * 100) / 100,
    minX: Math.round(b.minX * 1000) / 1000,
    minY: Math.round(b.minY * 1000) / 1000,
    minZ: Math.round(b.minZ * 1000) / 1000,
    maxX: Math.round(b.maxX * 1000) / 1000,
    maxY: Math.round(b.maxY * 1000) / 1000,
    maxZ: Math.round(b.maxZ * 1000) / 1000,
  };
}
