/**
 * Developer command: judge any slicer's G-code against the model it was sliced from and print the report.
 *
 *   node dist-dev/tools/analysis/analyze-cli.js MODEL.stl[.gz] PRINT.gcode [options]
 *
 * The mesh is placed as slicers place it: by default its bounding box is centred on the centre of the G-code's
 * part extrusions (`--center auto`), or on a given point (`--center X,Y`), or left where it is (`--center none`);
 * it always rests on z = 0 unless left where it is. Not part of the library.
 */
import { readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { gunzipSync } from 'node:zlib';
import type { Mesh } from '#strata/mesh/types.js';
import { StrataError } from '#strata/errors.js';
import { analyzeParsed } from './checks.js';
import { isPartFeature } from './feature-names.js';
import { formatLayerSupport, formatReport } from './format-report.js';
import { parseGcode } from './gcode-parse.js';
import type { ParsedGcode } from './gcode-types.js';
import type { AnalyzeOptions } from './report-types.js';
import { placeOnBed, readStl } from './toy-slicer.js';

const USAGE = `usage: analyze-cli MODEL.stl[.gz] PRINT.gcode [--layer-height 0.2] [--first-layer-height 0.2]
  [--line-width 0.4] [--filament-diameter 1.75] [--wall-thickness MM] [--top-thickness MM] [--bottom-thickness MM]
  [--center auto|none|X,Y] [--model-z-offset MM] [--sample-every N] [--overhang-angle DEG]
  [--support-gap-layers N] [--support-span MM] [--no-support-checks] [--layer-height-range MIN,MAX] [--layers] [--json]`;

/** Numeric options: flag → AnalyzeOptions key. */
const NUMERIC: Record<string, keyof AnalyzeOptions> = {
  '--layer-height': 'layerHeight',
  '--first-layer-height': 'firstLayerHeight',
  '--line-width': 'lineWidth',
  '--filament-diameter': 'filamentDiameter',
  '--wall-thickness': 'wallThickness',
  '--top-thickness': 'topThickness',
  '--bottom-thickness': 'bottomThickness',
  '--model-z-offset': 'modelZOffset',
  '--sample-every': 'sampleEvery',
  '--overhang-angle': 'overhangAngleDeg',
  '--support-gap-layers': 'supportGapLayers',
  '--support-span': 'supportSpanMm',
  '--cell': 'cellSize',
};

interface CliArgs {
  model: string;
  gcode: string;
  options: AnalyzeOptions;
  center: 'auto' | 'none' | [number, number];
  layers: boolean;
  json: boolean;
}

export function parseArgs(argv: string[]): CliArgs {
  const files: string[] = [];
  const options: Record<string, unknown> = { layerHeight: 0.2, lineWidth: 0.4, filamentDiameter: 1.75 };
  let center: CliArgs['center'] = 'auto';
  let layers = false;
  let json = false;
  for (let k = 0; k < argv.length; k++) {
    const a = argv[k]!;
    const value = () => {
      const v = argv[++k];
      if (v === undefined) throw new StrataError('BAD_SETTING', `${a} needs a value\n${USAGE}`);
      return v;
    };
    if (a in NUMERIC) {
      const v = Number(value());
      if (!Number.isFinite(v)) throw new StrataError('BAD_SETTING', `${a} must be a number`);
      options[NUMERIC[a]!] = v;
    } else if (a === '--center') {
      const v = value();
      if (v === 'auto' || v === 'none') center = v;
      else {
        const m = /^(-?[\d.]+),(-?[\d.]+)$/.exec(v);
        if (!m) throw new StrataError('BAD_SETTING', `--center must be auto, none or X,Y (got ${v})`);
        center = [Number(m[1]), Number(m[2])];
      }
    } else if (a === '--layer-height-range') {
      // variable layer height: each layer MIN to MAX mm thick
      const v = value();
      const m = /^([\d.]+),([\d.]+)$/.exec(v);
      if (!m) throw new StrataError('BAD_SETTING', `--layer-height-range must be MIN,MAX in mm (got ${v})`);
      options['layerHeightRange'] = [Number(m[1]), Number(m[2])];
    } else if (a === '--no-support-checks') options['supportChecks'] = false;
    else if (a === '--layers') layers = true;
    else if (a === '--json') json = true;
    else if (a.startsWith('--')) throw new StrataError('BAD_SETTING', `unknown option ${a}\n${USAGE}`);
    else files.push(a);
  }
  if (files.length !== 2) throw new StrataError('BAD_SETTING', USAGE);
  options['firstLayerHeight'] ??= options['layerHeight'];
  return { model: files[0]!, gcode: files[1]!, options: options as unknown as AnalyzeOptions, center, layers, json };
}

/** Centre of the XY extents of the part's extrusions, null without any. */
export function partCentre(parsed: ParsedGcode): [number, number] | null {
  let xmin = Infinity,
    xmax = -Infinity,
    ymin = Infinity,
    ymax = -Infinity;
  for (const layer of parsed.layers) {
    const t = layer.extrusions;
    for (let i = 0; i < t.count; i++) {
      if (!isPartFeature(t.feature[i]!)) continue;
      xmin = Math.min(xmin, t.x0[i]!, t.x1[i]!);
      xmax = Math.max(xmax, t.x0[i]!, t.x1[i]!);
      ymin = Math.min(ymin, t.y0[i]!, t.y1[i]!);
      ymax = Math.max(ymax, t.y0[i]!, t.y1[i]!);
    }
  }
  return xmax >= xmin ? [(xmin + xmax) / 2, (ymin + ymax) / 2] : null;
}

function readMesh(path: string): Mesh {
  let bytes: Uint8Array = readFileSync(path);
  if (path.endsWith('.gz')) bytes = gunzipSync(bytes);
  return readStl(bytes);
}

function main(): void {
  const args = parseArgs(process.argv.slice(2));
  const parsed = parseGcode(readFileSync(args.gcode, 'utf8'));
  let mesh = readMesh(args.model);
  if (args.center !== 'none') {
    const c = args.center === 'auto' ? partCentre(parsed) : args.center;
    if (!c) throw new StrataError('BAD_SETTING', 'the G-code prints no part features to centre the model on');
    mesh = placeOnBed(mesh, c[0], c[1]);
  }
  const report = analyzeParsed(mesh, parsed, args.options);
  if (args.json) {
    console.log(JSON.stringify(args.layers ? report : { summary: report.summary, warnings: report.warnings }, null, 1));
    return;
  }
  console.log(formatReport(report));
  if (args.layers) console.log(formatLayerSupport(report));
}

if (process.argv[1] && import.meta.url === pathToFileURL(process.argv[1]).href) {
  try {
    main();
  } catch (e) {
    console.error(e instanceof StrataError ? `error: ${e.message}` : e);
    process.exitCode = 1;
  }
}
