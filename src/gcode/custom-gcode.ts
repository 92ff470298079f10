/**
 * The print's custom G-code, from its templates (template.ts), each in the flavour's words
 * (flavor-templates.ts): the start and end G-code, run once, and per layer, run at that layer with
 * `{layer_num}` (from 0), `{layer_z}` (the layer's top, mm), `{max_layer_z}` and the filament extruded
 * so far (`{extruded_volume_total}` mm³, `{extruded_weight_total}` g):
 *
 *   ;LAYER:n ;Z: ;HEIGHT: (M73)
 *   beforeLayerChangeGcode
 *   ;COLOR_CHANGE,T0 and colorChangeGcode   the first layer at or above a colorChangeAt height
 *   ;PAUSE_PRINT and pauseGcode             the first layer at or above a pauseAt height
 *   (the layer's temperatures and fan)
 *   (its first Z move)
 *   layerChangeGcode
 *   (the layer's moves)
 *
 * move-writer.ts writes them there. The colour change comes before the layer's first move, outside any
 * object's label block, so cancelling an object never skips it. In sequential printing the layers are
 * numbered on through the whole print (`{layer_num}` keeps rising while `{layer_z}` goes down at each new
 * object), and each object changes colour or pauses at the given heights. The markers are PrusaSlicer's (its
 * G-code viewer reads them). Every layer gets the layer templates, the first too (as OrcaSlicer; PrusaSlicer
 * skips the first). A pause adds no time to the estimate: the printer waits for the user.
 */
import type { LayerPlan, PlanEstimate, PrintPlan } from '../plan/types.js';
import { filamentAreaMm2 } from '../plan/moves.js';
import type { Settings } from '../settings/schema.js';
import { FLAVORS } from './flavor.js';
import { templateForFlavor } from './flavor-templates.js';
import { derivedTemplateValues } from './header.js';
import { compileTemplate, runCompiledTemplate } from './template.js';
import type { ParsedTemplate } from './template-parse.js';
import { DERIVED_VALUES } from './template-vars.js';

/** A layer is at or above a height when its top is within this of it or higher (PrusaSlicer's EPSILON), mm. */
export const HEIGHT_TOLERANCE_MM = 1e-4;

/** The per-layer G-code move-writer.ts writes; lines are final (in the flavour's words). */
export interface LayerGcode {
  /** Before the layer's moves: beforeLayerChangeGcode, a colour change, a pause. */
  before(layer: LayerPlan, index: number, extrudedMm: number): readonly string[];
  /** After the layer's first Z move: layerChangeGcode. */
  after(layer: LayerPlan, index: number, extrudedMm: number): readonly string[];
}

export interface PrintCustomGcode {
  start: string[];
  end: string[];
  /** Null when no layer has any (the writer then writes exactly what it wrote before there was any). */
  layers: LayerGcode | null;
}

type TemplateSettings = Pick<Settings, 'gcodeFlavor' | 'startGcode' | 'endGcode'> & Partial<Settings>;

/** The heights of a colorChangeAt / pauseAt list, sorted, each once. */
export function parseHeights(text: string | undefined): number[] {
  const heights = (text ?? '')
    .split(/[\s,;]+/)
    .filter((t) => t !== '')
    .map(Number)
    .filter((h) => Number.isFinite(h) && h >= 0)
    .sort((a, b) => a - b);
  return heights.filter((h, i) => i === 0 || h !== heights[i - 1]);
}

/** The templates a print runs, by setting name (colour change and pause only with heights to run at). */
export function templatesInUse(s: TemplateSettings): Array<[name: string, text: string]> {
  const flavor = FLAVORS[s.gcodeFlavor];
  const out: Array<[string, string]> = [
    ['startGcode', s.startGcode],
    ['endGcode', s.endGcode],
  ];
  if (s.beforeLayerChangeGcode) out.push(['beforeLayerChangeGcode', s.beforeLayerChangeGcode]);
  if (s.layerChangeGcode) out.push(['layerChangeGcode', s.layerChangeGcode]);
  if (parseHeights(s.colorChangeAt).length) out.push(['colorChangeGcode', s.colorChangeGcode || flavor.colorChange]);
  if (parseHeights(s.pauseAt).length) out.push(['pauseGcode', s.pauseGcode || flavor.pause]);
  return out;
}

/**
 * Check every template the print runs before slicing: its syntax and placeholders, and that its
 * commands suit the flavour (a Klipper macro under Marlin is an error naming the line). Lines that
 * start with a placeholder or condition are checked once they are filled in, when the G-code is written.
 */
export function checkTemplatesForFlavor(s: TemplateSettings): void {
  for (const [name, text] of templatesInUse(s)) {
    compileTemplate(name, text, DERIVED_VALUES);
    const lines = text.split(/\r?\n/).map((l) => (/^\s*[{[]/.test(l) ? '' : l));
    templateForFlavor(lines, s.gcodeFlavor, name);
  }
  // a template that is set but not run (a colour change with no heights) must still read
  if (s.colorChangeGcode) compileTemplate('colorChangeGcode', s.colorChangeGcode, DERIVED_VALUES);
  if (s.pauseGcode) compileTemplate('pauseGcode', s.pauseGcode, DERIVED_VALUES);
}

/** Template lines as written to the file: trailing blanks and trailing empty lines dropped. */
function finalLines(lines: string[]): string[] {
  const out = lines.map((l) => l.trimEnd());
  while (out.length > 0 && out[out.length - 1] === '') out.pop();
  return out;
}

const r3 = (v: number) => Math.round(v * 1000) / 1000;

/** Compile and run every template of the print (the per-layer ones as the layers are written). */
export function printCustomGcode(plan: PrintPlan, settings: Settings, estimate: PlanEstimate): PrintCustomGcode {
  const derived = derivedTemplateValues(plan, estimate);
  const area = filamentAreaMm2(settings.filamentDiameter);
  const volume = (filamentMm: number) => r3(filamentMm * area);
  const weight = (filamentMm: number) => r3((filamentMm * area * settings.filamentDensity) / 1000);
  const run = (name: string, t: ParsedTemplate, values: Record<string, number>): string[] =>
    templateForFlavor(
      finalLines(runCompiledTemplate(t, settings, values)),
      settings.gcodeFlavor,
      name,
      settings.heatedBed,
    );
  const compiled = new Map(
    templatesInUse(settings).map(([name, text]) => [name, compileTemplate(name, text, DERIVED_VALUES)]),
  );

  const layers = plan.layers;
  let top = 0;
  for (const l of layers) if (l.z > top) top = l.z;
  const first = layers[0];
  const last = layers[layers.length - 1];
  const start = run('startGcode', compiled.get('startGcode')!, {
    ...derived,
    layerIndex: 0,
    layerZ: r3(first?.z ?? 0),
    maxLayerZ: r3(first?.z ?? 0),
    extrudedVolume: 0,
    extrudedWeight: 0,
  });
  const end = run('endGcode', compiled.get('endGcode')!, {
    ...derived,
    layerIndex: Math.max(0, layers.length - 1),
    layerZ: r3(last?.z ?? 0),
    maxLayerZ: r3(top),
    extrudedVolume: volume(estimate.filamentMm),
    extrudedWeight: weight(estimate.filamentMm),
  });

  const before = compiled.get('beforeLayerChangeGcode');
  const after = compiled.get('layerChangeGcode');
  const colorChange = compiled.get('colorChangeGcode');
  const pause = compiled.get('pauseGcode');
  if (!before && !after && !colorChange && !pause) return { start, end, layers: null };

  /**
   * The layers that are the first at or above one of the heights, in each run of rising layers: the whole
   * print, or in sequential printing (where Z goes down at each new object) each object, so every object
   * changes colour or pauses at that height (as PrusaSlicer does).
   */
  const firstAtOrAbove = (heights: readonly number[]): Set<number> => {
    const found = new Set<number>();
    for (let start = 0, end = 1; start < layers.length; start = end, end = start + 1) {
      while (end < layers.length && layers[end].z >= layers[end - 1].z) end++;
      for (const h of heights) {
        for (let i = start; i < end; i++) {
          if (layers[i].z < h - HEIGHT_TOLERANCE_MM) continue;
          found.add(i);
          break;
        }
      }
    }
    return found;
  };
  const colorLayers = colorChange ? firstAtOrAbove(parseHeights(settings.colorChangeAt)) : new Set<number>();
  const pauseLayers = pause ? firstAtOrAbove(parseHeights(settings.pauseAt)) : new Set<number>();
  let maxSoFar = 0;
  const values = (layer: LayerPlan, index: number, extrudedMm: number) => ({
    ...derived,
    layerIndex: index,
    layerZ: r3(layer.z),
    maxLayerZ: r3(Math.max(maxSoFar, layer.z)),
    extrudedVolume: volume(extrudedMm),
    extrudedWeight: weight(extrudedMm),
  });
  const none: readonly string[] = [];
  return {
    start,
    end,
    layers: {
      before(layer, index, extrudedMm) {
        const v = values(layer, index, extrudedMm);
        maxSoFar = v.maxLayerZ;
        const lines: string[] = [];
        if (before) lines.push(...run('beforeLayerChangeGcode', before, v));
        if (colorChange && colorLayers.has(index))
          lines.push(';COLOR_CHANGE,T0', ...run('colorChangeGcode', colorChange, v));
        if (pause && pauseLayers.has(index)) lines.push(';PAUSE_PRINT', ...run('pauseGcode', pause, v));
        return lines;
      },
      after(layer, index, extrudedMm) {
        return after ? run('layerChangeGcode', after, values(layer, index, extrudedMm)) : none;
      },
    },
  };
}
