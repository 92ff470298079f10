/**
 * The G-code writer: prints a plan as text to a sink, in chunks of about CHUNK_BYTES.
 *
 * File layout: header comments (header.ts); thumbnails (thumbnail-blocks.ts); object definitions
 * (Klipper EXCLUDE_OBJECT_DEFINE, M486 T); heat-up, only when the start template neither uses a
 * temperature placeholder nor sets that temperature itself (M104/M109, M140/M190); the start template;
 * the extrusion mode (M82/M83, forced whatever the template did) and `G92 E0`; the machine limits when
 * `machineLimits` is `write`, else M204 when `acceleration` is not the schema default (firmware keeps
 * its own unless a preset or the user chose one); pressure advance when set; `;LAYER_COUNT:`; the layers
 * (move-writer.ts, walking the plan through moves.ts exactly as the estimate does, with the per-layer
 * templates of custom-gcode.ts); `M73 P100 R0`; the end template.
 */
import { StrataError } from '../errors.js';
import type { PlanEstimate, PrintPlan } from '../plan/types.js';
import { SCHEMA, type Settings } from '../settings/schema.js';
import { ChunkedText } from './chunked-text.js';
import { FLAVORS } from './flavor.js';
import { templateHeatsNozzle } from './flavor-templates.js';
import { printCustomGcode } from './custom-gcode.js';
import { headerLines, type GcodeMeta } from './header.js';
import { hostTrailerLines } from './host-metadata.js';
import { MoveWriter } from './move-writer.js';
import { walkPlanSteps } from '../plan/moves.js';
import { placeholders, settingValue } from './template.js';
import { labelMode, objectLabels } from './object-labels.js';
import { thumbnailBlockLines } from './thumbnail-blocks.js';

export type { GcodeMeta } from './header.js';
export { TYPE_MARKERS } from './move-writer.js';

/** Target size of the chunks given to the sink: UTF-8 bytes (= characters for ASCII G-code). */
export const CHUNK_BYTES = 65536;

const NOZZLE_KEYS = ['firstLayerNozzleTemperature', 'nozzleTemperature'];
const BED_KEYS = ['firstLayerBedTemperature', 'bedTemperature'];
const SETS_BED = /^\s*M1[49]0\b/im;

function temperature(settings: Settings, key: string): number {
  const value = settingValue(settings, key);
  return typeof value === 'number' ? value : NaN;
}

/**
 * Write `plan` as G-code to `sink`. Templates are checked before anything is written, so a bad
 * placeholder throws StrataError BAD_SETTING without partial output, and a plan with nothing to
 * extrude throws EMPTY_MODEL (G-code that heats, homes and prints nothing would mislead).
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
  const { start, end, layers: layerGcode } = printCustomGcode(plan, settings, estimate);

  const labels = objectLabels(plan.objects, labelMode(settings), settings.gcodeFlavor);

  const out = new ChunkedText(sink, CHUNK_BYTES);
  if (!plan.layers.some((l) => l.steps.some((s) => s.kind === 'extrude'))) {
    throw new StrataError(
      'EMPTY_MODEL',
      'nothing to print: no layer of the model is wide enough for a line (it is thinner than the line width everywhere)',
    );
  }
  for (const l of headerLines(plan, settings, estimate, meta, flavor.name)) out.line(l);
  for (const image of meta.thumbnails ?? []) for (const l of thumbnailBlockLines(image)) out.line(l);
  for (const l of labels?.preamble ?? []) out.line(l);

  // Heat-up, unless the start template takes care of it.
  const used = placeholders(settings.startGcode);
  const firstNozzle = temperature(settings, 'firstLayerNozzleTemperature');
  const firstBed = temperature(settings, 'firstLayerBedTemperature');
  const heatNozzle =
    !NOZZLE_KEYS.some((k) => used.includes(k)) && !templateHeatsNozzle(settings.startGcode, settings.gcodeFlavor);
  const heatBed = settings.heatedBed && !BED_KEYS.some((k) => used.includes(k)) && !SETS_BED.test(settings.startGcode);
  if (heatBed) out.line(flavor.setBed(firstBed));
  if (heatNozzle) for (const l of flavor.setNozzle(firstNozzle)) out.line(l);
  if (heatBed) out.line(flavor.waitBed(firstBed));
  if (heatNozzle) for (const l of flavor.waitNozzle(firstNozzle)) out.line(l);

  for (const l of start) out.line(l);
  out.line(relative ? 'M83 ; relative extrusion' : 'M82 ; absolute extrusion');
  out.line('G92 E0');
  if (settings.machineLimits === 'write') for (const l of flavor.machineLimits(settings)) out.line(l);
  else if (settings.acceleration !== SCHEMA.acceleration.default) out.line(flavor.acceleration(settings.acceleration));
  if (settings.pressureAdvance !== null) out.line(flavor.pressureAdvance(settings.pressureAdvance));
  out.line(`;LAYER_COUNT:${plan.layers.length}`);

  const moves = new MoveWriter(out, {
    flavor,
    relativeE: relative,
    heatedBed: settings.heatedBed,
    layerSeconds: estimate.layerSeconds,
    nozzleTemperature: firstNozzle,
    bedTemperature: firstBed,
    progress: settings.progressM73,
    firmwareRetraction: settings.firmwareRetraction && settings.retractionEnabled,
    labels,
    layerGcode,
  });
  yield* walkPlanSteps(plan, settings, moves);
  moves.finish();

  for (const l of end) out.line(l);
  // what print hosts read (Moonraker, for Mainsail and Fluidd), after the G-code as PrusaSlicer writes it
  for (const l of hostTrailerLines(plan, settings, estimate, meta)) out.line(l);
  out.flush();
}

/** Write `plan` as G-code and return the whole text. */
export function gcodeToString(plan: PrintPlan, settings: Settings, estimate: PlanEstimate, meta: GcodeMeta): string {
  const chunks: string[] = [];
  writeGcode(plan, settings, estimate, (chunk) => chunks.push(chunk), meta);
  return chunks.join('');
}
