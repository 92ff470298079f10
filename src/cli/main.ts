#!/usr/bin/env node
/**
 * The `strata` command: slice, info, presets, settings. Bad input gives a one-line error and a
 * non-zero exit, never a stack trace (set STRATA_DEBUG=1 to see one).
 */
import { closeSync, openSync, readFileSync, writeSync } from 'node:fs';
import { basename, extname } from 'node:path';
import { Slicer } from '../index.js';
import { StrataError } from '../errors.js';
import { loadModelBytes, prepareMesh, mergeObjects } from '../mesh/index.js';
import { VERSION } from '../pipeline/run.js';
import { listPresets } from '../settings/presets/index.js';
import { SCHEMA, SETTING_KEYS, type SliceOptions } from '../settings/schema.js';
import { parseArgs, kebab, type ParsedArgs } from './args.js';
import { progressBar } from './progress.js';
import { cmdServe } from './serve.js';
import { layerToSvg } from '../preview/svg.js';
import { PATTERN_IDS } from '../infill/types.js';
import { loadInfiller, parseInfillParams } from '../shader/index.js';
import { iceslInfillersDirs, listInfillers, readInfillersFolder, shippedInfillersDir } from '../shader/node-folder.js';
import type { CustomInfillSpec } from '../pipeline/custom-infill.js';

const HELP = `strata ${VERSION}: a fast FFF slicer

Usage:
  strata slice MODEL... [-o OUT.gcode] [options]   slice STL/OBJ/3MF models (- reads stdin) to G-code
  strata info MODEL...                             triangles, size, volume, open and non-manifold edges
  strata preview MODEL [--layer N] [-o layer.svg]   slice and draw one layer as SVG (paths by feature,
                                                   --travel adds travels, --width PX sets the size)
  strata infillers [DIR...]                         list custom infillers (IceSL layout) and their parameters
  strata presets                                   list printer and filament presets
  strata settings                                  list every setting with its flag, unit, default and range
  strata serve [--port N]                          the web page on http://127.0.0.1:N/ (default 8080)

Slice options:
  -o, --output FILE      where to write G-code (- for stdout; default: MODEL.gcode)
  --printer NAME         printer preset (default creality-ender-3)
  --filament NAME        filament preset (default pla)
  --config FILE.json     settings from a JSON object (may name printer and filament); repeatable
  --set key=value        any setting by its key; repeatable
  --no-center            keep the models' own XY coordinates instead of centring them on the bed
  --threads N            worker threads (default: one per core); output is identical for any N
  -q, --quiet            no progress bar or summary
  --infill-shader FILE   custom infill from a GLSL cellular() shader (IceSL infiller format)
  --infill-image FILE    custom infill from a cells.png image (with --infill-image-pixel-size MM)
  --infill-pattern NAME  a built-in pattern, or an infiller folder NAME/shader.glsl|cells.png
                         (shipped infillers/, ~/.icesl/icesl-infillers, or --infillers DIR)
  --infill-param N=V     set a shader's ui_ parameter; repeatable
  --infill-density-shader FILE   density() from a shader defining float density(vec3 world), 0-100
  --infill-density-layers A,B,…  density() per layer (the last value holds for the layers above)
  --<setting> VALUE      every setting has a flag, e.g. --layer-height 0.2 --infill-density 20
                         --infill-pattern gyroid --wall-count 3 (see: strata settings)
`;

function readInput(path: string): Uint8Array {
  try {
    return path === '-' ? readFileSync(0) : readFileSync(path);
  } catch (e) {
    const code = (e as NodeJS.ErrnoException).code;
    throw new StrataError('BAD_FILE', `cannot read ${path}: ${code === 'ENOENT' ? 'no such file' : code === 'EISDIR' ? 'it is a folder' : (e as Error).message}`);
  }
}

function readConfigFile(path: string): Record<string, unknown> {
  const text = new TextDecoder().decode(readInput(path));
  let obj: unknown;
  try {
    obj = JSON.parse(text);
  } catch (e) {
    throw new StrataError('BAD_FILE', `${path} is not valid JSON: ${(e as Error).message}`);
  }
  if (!obj || typeof obj !== 'object' || Array.isArray(obj)) throw new StrataError('BAD_FILE', `${path} must hold a JSON object of settings`);
  return obj as Record<string, unknown>;
}

function infillerDirs(args: ParsedArgs): string[] {
  const extra = typeof args.flags.infillers === 'string' ? args.flags.infillers.split('\n') : [];
  return [...extra, shippedInfillersDir(), ...iceslInfillersDirs()];
}

/** A custom infiller named by --infill-shader, --infill-image, or an --infill-pattern that is not built in. */
async function customInfillFrom(args: ParsedArgs, opts: Record<string, unknown>): Promise<CustomInfillSpec | undefined> {
  let spec: CustomInfillSpec | undefined;
  const shader = args.flags['infill-shader'];
  const image = args.flags['infill-image'];
  if (typeof shader === 'string' && typeof image === 'string') throw new StrataError('BAD_SETTING', '--infill-shader and --infill-image exclude each other');
  if (typeof shader === 'string') spec = { name: basename(shader), shader: new TextDecoder().decode(readInput(shader)) };
  else if (typeof image === 'string') spec = { name: basename(image), image: readInput(image) };
  else if (typeof opts.infillPattern === 'string' && !(PATTERN_IDS as readonly string[]).includes(opts.infillPattern)) {
    const name = opts.infillPattern;
    for (const dir of infillerDirs(args)) {
      const found = (await readInfillersFolder(dir)).find((f) => f.name === name);
      if (found) {
        spec = found;
        break;
      }
    }
    if (!spec) {
      throw new StrataError('BAD_SETTING', `infillPattern "${name}" is neither a built-in pattern (${PATTERN_IDS.join(', ')}) nor an infiller folder (see strata infillers)`);
    }
    delete opts.infillPattern;
  }
  const assignments = typeof args.flags['infill-param'] === 'string' ? args.flags['infill-param'].split('\n') : [];
  const densityShader = args.flags['infill-density-shader'];
  const densityLayers = args.flags['infill-density-layers'];
  if (!spec) {
    if (assignments.length || densityShader || densityLayers) {
      throw new StrataError('BAD_SETTING', '--infill-param and --infill-density-shader/-layers need a custom infiller (--infill-shader, --infill-image or an infiller --infill-pattern)');
    }
    return undefined;
  }
  if (assignments.length) spec.params = parseInfillParams(loadInfiller(spec).params, assignments);
  if (typeof densityShader === 'string') spec.density = { shader: new TextDecoder().decode(readInput(densityShader)), fileName: basename(densityShader) };
  else if (typeof densityLayers === 'string') {
    const list = densityLayers.split(',').map((v) => Number(v.trim()));
    if (!list.length || list.some((v) => !Number.isFinite(v) || v < 0 || v > 100)) throw new StrataError('BAD_SETTING', '--infill-density-layers expects comma-separated percentages 0-100, one per layer');
    spec.density = list;
  }
  return spec;
}

async function optionsFrom(args: ParsedArgs): Promise<SliceOptions & { customInfill?: CustomInfillSpec }> {
  const opts: Record<string, unknown> = {};
  for (const f of args.configFiles) Object.assign(opts, readConfigFile(f));
  if (args.printer) opts.printer = args.printer;
  if (args.filament) opts.filament = args.filament;
  Object.assign(opts, args.settings);
  const customInfill = await customInfillFrom(args, opts);
  return { ...(opts as SliceOptions), ...(customInfill ? { customInfill } : {}) };
}

async function cmdInfillers(args: ParsedArgs): Promise<void> {
  const dirs = args.positional.length ? args.positional : infillerDirs(args);
  for (const dir of dirs) {
    const list = await listInfillers(dir);
    if (!list.length) continue;
    process.stdout.write(`${dir}:\n`);
    for (const inf of list) {
      if (inf.error) {
        process.stdout.write(`  ${inf.name}  (cannot load: ${inf.error})\n`);
        continue;
      }
      process.stdout.write(`  ${inf.name}  ${inf.kind}${inf.numPasses && inf.numPasses > 1 ? `, ${inf.numPasses} passes` : ''}\n`);
      for (const p of inf.params ?? []) process.stdout.write(`      --infill-param ${p.name}=${p.default}  (${p.type})${p.tooltip ? '  ' + p.tooltip : ''}\n`);
    }
  }
}

function formatDuration(s: number): string {
  const h = Math.floor(s / 3600), m = Math.floor((s % 3600) / 60), sec = Math.round(s % 60);
  return h ? `${h}h ${m}m` : m ? `${m}m ${sec}s` : `${sec}s`;
}

async function cmdSlice(args: ParsedArgs): Promise<void> {
  if (args.positional.length === 0) throw new StrataError('BAD_FILE', 'slice needs at least one model file (see strata --help)');
  const slicer = new Slicer(await optionsFrom(args));
  const inputs = args.positional.map((p) => loadModelBytes(readInput(p), p === '-' ? undefined : basename(p)));
  const first = args.positional[0];
  const out = args.output ?? (first === '-' ? '-' : first.slice(0, first.length - extname(first).length) + '.gcode');
  const fd = out === '-' ? 1 : openFileForWrite(out);
  const showProgress = !args.quiet && process.stderr.isTTY && out !== '-';
  const bar = showProgress ? progressBar(process.stderr) : null;
  try {
    const { stats, warnings } = await slicer.sliceToSink(inputs.flat(), (chunk) => writeAll(fd, chunk), {
      onProgress: bar ? (p) => bar.update(p.fraction, p.stage) : undefined,
    });
    bar?.done();
    if (!args.quiet) {
      for (const w of warnings) process.stderr.write(`strata: warning: ${w}\n`);
      process.stderr.write(
        `${out === '-' ? 'G-code' : out}: ${stats.layers} layers, print time ${formatDuration(stats.printTimeSeconds)}, ` +
          `filament ${(stats.filamentMm / 1000).toFixed(2)} m (${stats.filamentGrams.toFixed(1)} g), ` +
          `sliced in ${stats.sliceSeconds.toFixed(2)} s on ${stats.threads} thread${stats.threads === 1 ? '' : 's'}\n`,
      );
    }
  } finally {
    bar?.done();
    if (fd !== 1) closeSync(fd);
  }
}

function openFileForWrite(path: string): number {
  try {
    return openSync(path, 'w');
  } catch (e) {
    throw new StrataError('BAD_FILE', `cannot write ${path}: ${(e as Error).message}`);
  }
}

function writeAll(fd: number, chunk: string): void {
  const buf = Buffer.from(chunk, 'utf8');
  let off = 0;
  while (off < buf.length) off += writeSync(fd, buf, off, buf.length - off);
}

function cmdInfo(args: ParsedArgs): void {
  if (args.positional.length === 0) throw new StrataError('BAD_FILE', 'info needs a model file');
  for (const p of args.positional) {
    const objects = loadModelBytes(readInput(p), basename(p));
    const { report } = prepareMesh(mergeObjects(objects));
    const size = report.max.map((v, k) => v - report.min[k]);
    const lines = [
      `${p}:`,
      `  objects:            ${objects.length}`,
      `  triangles:          ${report.triangles}${report.degenerateRemoved ? ` (${report.degenerateRemoved} degenerate removed)` : ''}`,
      `  size:               ${size.map((v) => v.toFixed(2)).join(' × ')} mm`,
      `  bounds:             (${report.min.map((v) => v.toFixed(2)).join(', ')}) – (${report.max.map((v) => v.toFixed(2)).join(', ')})`,
      `  volume:             ${(Math.abs(report.volume) / 1000).toFixed(2)} cm³`,
      `  open edges:         ${report.openEdges}`,
      `  non-manifold edges: ${report.nonManifoldEdges}`,
      `  watertight:         ${report.openEdges === 0 && report.nonManifoldEdges === 0 ? 'yes' : 'no'}`,
    ];
    process.stdout.write(lines.join('\n') + '\n');
  }
}

async function cmdPreview(args: ParsedArgs): Promise<void> {
  if (args.positional.length === 0) throw new StrataError('BAD_FILE', 'preview needs a model file');
  const slicer = new Slicer(await optionsFrom(args));
  const inputs = args.positional.map((p) => loadModelBytes(readInput(p), p === '-' ? undefined : basename(p)));
  const { plan } = await slicer.slicePlan(inputs.flat());
  const n = plan.layers.length;
  const layerText = typeof args.flags.layer === 'string' ? args.flags.layer : String(Math.floor(n / 2));
  const index = Number(layerText);
  if (!Number.isInteger(index) || index < 0 || index >= n) throw new StrataError('BAD_SETTING', `--layer must be a layer number from 0 to ${n - 1}`);
  const width = typeof args.flags.width === 'string' ? Number(args.flags.width) : 800;
  if (!Number.isFinite(width) || width < 50 || width > 20000) throw new StrataError('BAD_SETTING', '--width must be 50 to 20000 pixels');
  const svg = layerToSvg(plan.layers[index], { travel: args.flags.travel === true, widthPx: width, title: `layer ${index} at Z ${plan.layers[index].z}` });
  const out = args.output ?? '-';
  if (out === '-') process.stdout.write(svg + '\n');
  else {
    const fd = openFileForWrite(out);
    try {
      writeAll(fd, svg + '\n');
    } finally {
      closeSync(fd);
    }
    if (!args.quiet) process.stderr.write(`${out}: layer ${index} of ${n}\n`);
  }
}

function cmdPresets(): void {
  const { printers, filaments } = listPresets();
  const w = Math.max(...printers.map((p) => p.id.length), ...filaments.map((f) => f.id.length));
  process.stdout.write('Printers:\n');
  for (const p of printers) process.stdout.write(`  ${p.id.padEnd(w)}  ${p.name}\n`);
  process.stdout.write('Filaments:\n');
  for (const f of filaments) process.stdout.write(`  ${f.id.padEnd(w)}  ${f.name}\n`);
}

function cmdSettings(): void {
  for (const key of SETTING_KEYS) {
    const d = SCHEMA[key];
    const range =
      d.type === 'number' || d.type === 'integer' ? ` [${d.min}–${d.max}]` : d.type === 'enum' ? ` {${d.values.join('|')}}` : d.type === 'boolean' ? ' (--no-' + kebab(key) + ')' : '';
    const def = d.type === 'string' ? '(template)' : JSON.stringify(d.default);
    process.stdout.write(`--${kebab(key)} ${d.unit ? `(${d.unit}) ` : ''}default ${def}${range}\n    ${d.description}\n`);
  }
}

export async function main(argv: readonly string[]): Promise<number> {
  try {
    if (argv[0] === 'serve') {
      await cmdServe(argv.slice(1));
      return 0;
    }
    const args = parseArgs(argv);
    if (args.flags.version) {
      process.stdout.write(`strata ${VERSION}\n`);
      return 0;
    }
    if (args.help || !args.command || args.command === 'help') {
      process.stdout.write(HELP);
      return 0;
    }
    switch (args.command) {
      case 'slice':
        await cmdSlice(args);
        return 0;
      case 'info':
        cmdInfo(args);
        return 0;
      case 'preview':
        await cmdPreview(args);
        return 0;
      case 'infillers':
        await cmdInfillers(args);
        return 0;
      case 'presets':
        cmdPresets();
        return 0;
      case 'settings':
        cmdSettings();
        return 0;
      default:
        throw new StrataError('BAD_SETTING', `unknown command "${args.command}" (commands: slice, info, preview, infillers, presets, settings, serve)`);
    }
  } catch (e) {
    if (e instanceof StrataError) {
      process.stderr.write(`strata: error: ${e.message}\n`);
      return 1;
    }
    if (process.env.STRATA_DEBUG) throw e;
    process.stderr.write(`strata: internal error: ${e instanceof Error ? e.message : String(e)} (STRATA_DEBUG=1 shows details)\n`);
    return 2;
  }
}

const code = await main(process.argv.slice(2));
process.exitCode = code;
