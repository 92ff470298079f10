/**
 * The G-code writer: prints a plan as text to a sink, in chunks of about CHUNK_BYTES.
 *
 * File layout: header comments (header.ts); heat-up, only when the start template neither uses a
 * temperature placeholder nor sets that temperature itself (M104/M109, M140/M190); the start template;
 * the extrusion mode (M82/M83, forced whatever the template did) and `G92 E0`; M204 when `acceleration`
 * is not the schema default (firmware keeps its own unless a preset or the user chose one);
 * `;LAYER_COUNT:`; the layers (move-writer.ts, walking the plan through moves.ts exactly as the estimate
 * does); the end template.
 */
import type { PlanEstimate, PrintPlan } from '../plan/types.js';
import { SCHEMA, type Settings } from '../settings/schema.js';
import { ChunkedText } from './chunked-text.js';
import { FLAVORS } from './flavor.js';
import { derivedTemplateValues, headerLines, type GcodeMeta } from './header.js';
import { MoveWriter } from './move-writer.js';
import { walkPlanSteps } from '../plan/moves.js';
import { expandTemplate, placeholders, settingValue } from './template.js';

export type { GcodeMeta } from './header.js';
export { TYPE_MARKERS } from './move-writer.js';

/** Target size of the chunks given to the sink: UTF-8 bytes (= characters for ASCII G-code). */
export const CHUNK_BYTES = 65536;

const NOZZLE_KEYS = ['firstLayerNozzleTemperature', 'nozzleTemperature'];
const BED_KEYS = ['firstLayerBedTemperature', 'bedTemperature'];
const SETS_NOZZLE = /^\s*M10[49]\b/im;
const SETS_BED = /^\s*M1[49]0\b/im;

function templateLines(text: string): string[] {
  const lines = text.split(/\r?\n/).map((l) => l.trimEnd());
  while (lines.length > 0 && lines[lines.length - 1] === '') lines.pop();
  return lines;
}

function temperature(settings: Settings, key: string): number {
  const value = settingValue(settings, key);
  return typeof value === 'number' ? value : NaN;
}

/**
 * Write `plan` as G-code to `sink`. Templates are checked before anything is written, so a bad
 * placeholder throws StrataError BAD_SETTING without partial output.
 */
export function writeGcode(
  plan: PrintPlan,
  settings: Settings,
  estimate: PlanEstimate,
  sink: (chunk: string) => void,
  meta: GcodeMeta,
): void {
  const steps = writeGcodeSteps(plan, settings, estimate, sink, meta);
  while (!steps.next().done);
}

/** `writeGcode` as steps: yields after each layer, so a caller can pause (and stop) between layers. */
export function* writeGcodeSteps(
  plan: PrintPlan,
  settings: Settings,
  estimate: PlanEstimate,
  sink: (chunk: string) => void,
  meta: GcodeMeta,
): Generator<void, void> {
  const flavor = FLAVORS[settings.gcodeFlavor];
  const relative = settings.extruderMode === 'relative';
  const derived = derivedTemplateValues(plan, estimate);
  const start = templateLines(expandTemplate('startGcode', settings.startGcode, settings, derived));
  const end = templateLines(expandTemplate('endGcode', settings.endGcode, settings, derived));

  const out = new ChunkedText(sink, CHUNK_BYTES);
  for (const l of headerLines(plan, settings, estimate, meta, flavor.name)) out.line(l);

  // Heat-up, unless the start template takes care of it.
  const used = placeholders(settings.startGcode);
  const firstNozzle = temperature(settings, 'firstLayerNozzleTemperature');
  const firstBed = temperature(settings, 'firstLayerBedTemperature');
  const heatNozzle = !NOZZLE_KEYS.some((k) => used.includes(k)) && !SETS_NOZZLE.test(settings.startGcode);
  const heatBed = settings.heatedBed && !BED_KEYS.some((k) => used.includes(k)) && !SETS_BED.test(settings.startGcode);
  if (heatBed) out.line(flavor.setBed(firstBed));
  if (heatNozzle) for (const l of flavor.setNozzle(firstNozzle)) out.line(l);
  if (heatBed) out.line(flavor.waitBed(firstBed));
  if (heatNozzle) for (const l of flavor.waitNozzle(firstNozzle)) out.line(l);

  for (const l of start) out.line(l);
  out.line(relative ? 'M83 ; relative extrusion' : 'M82 ; absolute extrusion');
  out.line('G92 E0');
  if (settings.acceleration !== SCHEMA.acceleration.default) out.line(flavor.acceleration(settings.acceleration));
  out.line(`;LAYER_COUNT:${plan.layers.length}`);

  const moves = new MoveWriter(out, {
    flavor,
    relativeE: relative,
    heatedBed: settings.heatedBed,
    layerSeconds: estimate.layerSeconds,
    nozzleTemperature: firstNozzle,
    bedTemperature: firstBed,
  });
  yield* walkPlanSteps(plan, settings, moves);

  for (const l of end) out.line(l);
  out.flush();
}

/** Write `plan` as G-code and return the whole text. */
export function gcodeToString(plan: PrintPlan, settings: Settings, estimate: PlanEstimate, meta: GcodeMeta): string {
  const chunks: string[] = [];
  writeGcode(plan, settings, estimate, (chunk) => chunks.push(chunk), meta);
  return chunks.join('');
}
