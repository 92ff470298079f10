/** Test helpers: the shared models and slicing one with the analyser's report. */
import { readFileSync } from 'node:fs';
import { gunzipSync } from 'node:zlib';
import { Slicer, prepareModel } from '#strata/api/slicer.js';
import { analyzePrint } from '../../tools/analysis/checks.js';
import type { AnalyzeOptions, PrintReport } from '../../tools/analysis/checks.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import type { Config } from '#strata/settings/resolve.js';

export { MODELS_DIR, modelsAvailable, skipWithoutModels } from './models-dir.js';
import { MODELS_DIR } from './models-dir.js';

export const MODEL_FILES = [
  'CalibrationCube.stl',
  'HollowCalibrationCube.stl',
  'HoleTest.stl',
  'Overhang.stl',
  'SupportTest.stl',
  'BridgeTest.stl',
  'spot.stl',
  'stanford-bunny.stl',
  '3DBenchy.stl.gz',
  '3DBenchy.3mf',
] as const;

export function readModel(name: string): Uint8Array {
  const bytes = readFileSync(MODELS_DIR + name);
  return name.endsWith('.gz') ? gunzipSync(bytes) : bytes;
}

export interface SlicedModel {
  gcode: string;
  report: PrintReport;
  layers: number;
  warnings: string[];
}

/**
 * Slice a model with options and analyse the G-code against the placed mesh; `analyze` adds or overrides analyser
 * options (for example the support checks' overhangAngleDeg or supportGapLayers, or a modelZOffset).
 */
export async function sliceAndAnalyze(
  name: string,
  options: SliceOptions = {},
  analyze: Partial<AnalyzeOptions> = {},
): Promise<SlicedModel> {
  return sliceAndAnalyzeInput(readModel(name), options, analyze);
}

/** `sliceAndAnalyze` of any input the library reads (file bytes, raw typed arrays). */
export async function sliceAndAnalyzeInput(
  input: unknown,
  options: SliceOptions = {},
  analyze: Partial<AnalyzeOptions> = {},
): Promise<SlicedModel> {
  const slicer = new Slicer({ threads: 1, ...options });
  const { gcode, stats, warnings } = await slicer.slice(input);
  const cfg = slicer.config;
  const placed = prepareModel(input, cfg).mesh;
  const report = analyzePrint(placed, gcode, { ...analysisProfile(cfg), ...analyze });
  return { gcode, report, layers: stats.layers, warnings };
}

/** What the analyser needs to know of the profile a print was sliced with. */
export function analysisProfile(cfg: Config) {
  return {
    layerHeight: cfg.layerHeight,
    firstLayerHeight: cfg.firstLayerHeight,
    lineWidth: cfg.lineWidthMm,
    filamentDiameter: cfg.filamentDiameter,
    wallThickness: cfg.wallCount * cfg.lineWidthMm,
    topThickness: cfg.topLayers * cfg.layerHeight,
    bottomThickness: cfg.bottomLayers * cfg.layerHeight,
  };
}
