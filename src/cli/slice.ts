/** `strata slice` and `strata preview`: models and settings in, G-code or one layer's SVG out. */
import { extname } from 'node:path';
// the library without its shader compiler, which loads when a custom infill is used (see newSlicer)
import { loadCustomInfill, Slicer } from '../exports.js';
import { StrataError } from '../errors.js';
import type { ModelInput } from '../mesh/place.js';
import { layerToSvg } from '../preview/svg.js';
import { findFilament, findPrinter } from '../settings/presets/index.js';
import { parseDecimal } from '../settings/resolve.js';
import type { ParsedArgs } from './args.js';
import { capYoungGeneration } from './engine-flags.js';
import type { Io } from './io.js';
import { InputReader, optionsFrom } from './inputs.js';
import { openOutput, refuseInputAsOutput, type Output } from './output.js';
import { progressBar } from './progress.js';

function formatDuration(s: number): string {
  const h = Math.floor(s / 3600),
    m = Math.floor((s % 3600) / 60),
    sec = Math.round(s % 60);
  return h ? `${h}h ${m}m` : m ? `${m}m ${sec}s` : `${sec}s`;
}

/** Let pending signals (Ctrl-C) run their handlers before the output is put in place. */
const settle = () => new Promise<void>((r) => setImmediate(r));

/** Write through `out`, putting it in place only if `body` succeeds; otherwise the target stays as it was. */
async function writing<T>(out: Output, body: (o: Output) => Promise<T> | T): Promise<T> {
  try {
    const result = await body(out);
    await settle();
    out.commit();
    return result;
  } catch (e) {
    out.abort();
    throw e;
  }
}

export async function cmdSlice(args: ParsedArgs, io: Io): Promise<void> {
  if (args.positional.length === 0)
    throw new StrataError('BAD_FILE', 'slice needs at least one model file (see strata --help)');
  const input = new InputReader();
  const quiet = args.flags.quiet === true;
  const slicer = await newSlicer(await optionsFrom(args, input, (w) => quiet || io.err(`strata: warning: ${w}\n`)));
  // let go once handed to the slicer, which keeps the files' bytes only until it has read them
  let models: ModelInput[] | undefined = await input.models(args.positional, slicer.config, args.modelFlags);
  const first = args.positional[0];
  const given = typeof args.flags.output === 'string' ? args.flags.output : undefined;
  const outPath = given ?? (first === '-' ? '-' : first.slice(0, first.length - extname(first).length) + '.gcode');
  refuseInputAsOutput(outPath, input.read, given === undefined);
  const project = args.flags['save-project'];
  if (typeof project === 'string') {
    refuseInputAsOutput(project, input.read, false);
    if (project === outPath) throw new StrataError('BAD_SETTING', `--save-project ${project} is the G-code output too`);
    const bytes = await slicer.saveProject(models);
    await writing(openOutput(project), (out) => out.write(bytes));
    if (!quiet) io.err(`${project}: project saved\n`);
  }
  const bar = !quiet && io.errIsTTY && outPath !== '-' ? progressBar(process.stderr) : null;
  const uncap = capYoungGeneration();
  try {
    const { stats, warnings } = await writing(openOutput(outPath), (out) => {
      const handed = models;
      models = undefined;
      return slicer.sliceToSink(handed, (chunk) => out.write(chunk), {
        onProgress: bar ? (p) => bar.update(p.fraction, p.stage) : undefined,
      });
    });
    bar?.done();
    if (!quiet) {
      for (const w of warnings) io.err(`strata: warning: ${w}\n`);
      io.err(
        `${outPath === '-' ? 'G-code' : outPath}: ${stats.layers} layers, print time ${formatDuration(stats.printTimeSeconds)}, ` +
          `filament ${(stats.filamentMm / 1000).toFixed(2)} m (${stats.filamentGrams.toFixed(1)} g), ` +
          `sliced in ${stats.sliceSeconds.toFixed(2)} s on ${stats.threads} thread${stats.threads === 1 ? '' : 's'}\n`,
      );
    }
  } finally {
    uncap();
    bar?.done();
  }
}

export async function cmdPreview(args: ParsedArgs, io: Io): Promise<void> {
  if (args.positional.length === 0) throw new StrataError('BAD_FILE', 'preview needs a model file');
  const input = new InputReader();
  const slicer = await newSlicer(
    await optionsFrom(args, input, (w) => args.flags.quiet === true || io.err(`strata: warning: ${w}\n`)),
  );
  const models = await input.models(args.positional, slicer.config, args.modelFlags);
  const outPath = typeof args.flags.output === 'string' ? args.flags.output : '-';
  refuseInputAsOutput(outPath, input.read, false);
  const width = typeof args.flags.width === 'string' ? parseDecimal(args.flags.width) : 800;
  if (!Number.isFinite(width) || width < 50 || width > 20000)
    throw new StrataError('BAD_SETTING', '--width must be 50 to 20000 pixels');
  const uncap = capYoungGeneration();
  const { plan } = await slicer.slicePlan(models).finally(uncap);
  const n = plan.layers.length;
  const layerText = typeof args.flags.layer === 'string' ? args.flags.layer : String(Math.floor(n / 2));
  const index = parseDecimal(layerText);
  if (!Number.isInteger(index) || index < 0 || index >= n)
    throw new StrataError('BAD_SETTING', `--layer must be a layer number from 0 to ${n - 1}`);
  const cfg = slicer.config;
  const title = `layer ${index} of ${n} at Z ${plan.layers[index].z} mm, ${findPrinter(cfg.printerId)?.name ?? cfg.printerId}, ${findFilament(cfg.filamentId)?.name ?? cfg.filamentId}`;
  const svg = layerToSvg(plan.layers[index], { travel: args.flags.travel === true, widthPx: width, title });
  await writing(openOutput(outPath), (out) => out.write(svg + '\n'));
  if (outPath !== '-' && args.flags.quiet !== true) io.err(`${outPath}: layer ${index} of ${n}\n`);
}

/** A slicer for these options; with a custom infill the shader compiler is loaded first, so a broken shader is reported at once. */
async function newSlicer(options: ConstructorParameters<typeof Slicer>[0]): Promise<Slicer> {
  if (options?.customInfill) await loadCustomInfill();
  return new Slicer(options);
}
