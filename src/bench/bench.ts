/**
 * The benchmark itself: slices each model with Strata's CLI (a child process) and with the peer slicers found
 * on PATH, then Strata once per infill pattern on 3DBenchy. Returns the results as data (see report.ts).
 */
import { existsSync, mkdirSync } from 'node:fs';
import { availableParallelism, cpus, loadavg, platform } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { PATTERN_IDS } from '../infill/types.js';
import type { BenchOptions } from './args.js';
import { selectModels } from './args.js';
import { detectMemoryMethod, measureCommand, type Measurement, type MemoryMethod } from './measure.js';
import { defaultModelsDir, listModelFiles, prepareModels, type BenchModel } from './models.js';
import { curaCommand, findCuraDefinitions, findOnPath, PEER_EXECUTABLES, peerReads, peerVersion, prusaCommand } from './peers.js';
import type { BenchReport, ModelRow, PatternRow, SlicerStats } from './report.js';
import { notRun, relativeToGrid, summarize } from './report.js';

export interface BenchContext {
  /** A folder for unpacked models and G-code output; the caller removes it. */
  workDir: string;
  /** Progress lines (stderr in the CLI). */
  log: (line: string) => void;
  /** Aborting kills the running slicer and skips the rest. */
  signal?: AbortSignal;
  /** Environment for finding peers (PATH, CURA_FDMPRINTER); default process.env. */
  env?: NodeJS.ProcessEnv;
  /** Memory method; default: detected. */
  memoryMethod?: MemoryMethod;
}

/** dist/cli/main.js of this build (from dist/bench/). */
export function defaultStrataCli(): string {
  return fileURLToPath(new URL('../cli/main.js', import.meta.url));
}

const safeName = (s: string) => s.replace(/[^A-Za-z0-9._-]+/g, '_');

/** The model the infill-pattern section uses: 3DBenchy as STL if selected, else its 3MF, else none. */
export function patternModel(models: readonly BenchModel[]): BenchModel | null {
  const benchies = models.filter((m) => m.name.toLowerCase().startsWith('3dbenchy.'));
  return benchies.find((m) => m.name.toLowerCase().endsWith('.stl')) ?? benchies[0] ?? null;
}

export async function runBench(options: BenchOptions, ctx: BenchContext): Promise<BenchReport> {
  const env = ctx.env ?? process.env;
  const modelsDir = resolve(options.modelsDir ?? defaultModelsDir());
  if (!existsSync(modelsDir)) throw new Error(`models folder not found: ${modelsDir}`);
  const available = listModelFiles(modelsDir);
  const names = selectModels(available, options.only);
  if (names.length === 0) {
    throw new Error(`no model matches --only ${options.only.join(',')}; models in ${modelsDir}: ${available.join(', ') || 'none'}`);
  }
  const models = prepareModels(modelsDir, names, ctx.workDir);
  const outDir = join(ctx.workDir, 'out');
  mkdirSync(outDir, { recursive: true });
  const prusaData = join(ctx.workDir, 'prusa-datadir');
  mkdirSync(prusaData, { recursive: true });

  const loadAtStart = loadavg()[0]!;
  const memoryMethod = ctx.memoryMethod ?? detectMemoryMethod();
  const threads = options.threads ?? availableParallelism();
  const timeoutMs = options.timeoutSeconds * 1000;
  const strataPath = resolve(options.strataCli ?? defaultStrataCli());
  const strataBuilt = existsSync(strataPath);

  const curaExe = options.peers ? findOnPath(PEER_EXECUTABLES.cura, env) : null;
  const curaDefs = curaExe ? findCuraDefinitions(env) : null;
  const prusaExe = options.peers ? findOnPath(PEER_EXECUTABLES.prusa, env) : null;
  const notes: string[] = [];
  if (curaExe && !curaDefs) notes.push(`CuraEngine found at ${curaExe} but no fdmprinter.def.json (install Debian's \`cura\` package or set CURA_FDMPRINTER)`);

  const measure = (command: string, args: readonly string[]) => measureCommand(command, args, { method: memoryMethod, timeoutMs, env, ...(ctx.signal ? { signal: ctx.signal } : {}) });

  /** Runs one slicer `repeat` times (stopping at the first failure) and folds the results. */
  const repeatRuns = async (label: string, run: (i: number) => Promise<Measurement>): Promise<SlicerStats> => {
    const runs: Measurement[] = [];
    for (let i = 0; i < options.repeat; i++) {
      if (ctx.signal?.aborted) return notRun('skipped', 'interrupted');
      const m = await run(i);
      runs.push(m);
      ctx.log(`  ${label} run ${i + 1}/${options.repeat}: ${m.wallSeconds.toFixed(2)} s${m.exitCode === 0 ? '' : ' (failed)'}`);
      if (m.exitCode !== 0 || m.timedOut) break;
    }
    return summarize(runs);
  };

  const strataRun = (model: BenchModel, tag: string, extra: readonly string[]) => {
    if (!strataBuilt) return Promise.resolve(notRun('missing', 'strata CLI not built'));
    const out = join(outDir, `${safeName(model.name)}.${tag}.gcode`);
    const args = [strataPath, 'slice', model.path, '-o', out, '--threads', String(threads), ...extra];
    return repeatRuns(['Strata', ...extra].join(' '), () => measure(process.execPath, args));
  };

  const rows: ModelRow[] = [];
  for (const [index, model] of models.entries()) {
    ctx.log(`[${index + 1}/${models.length}] ${model.name}`);
    const strata = await strataRun(model, 'strata', []);
    let cura: SlicerStats = notRun('missing');
    if (curaExe && curaDefs) {
      if (!peerReads('cura', model.path)) cura = notRun('unsupported', 'CuraEngine reads STL only');
      else {
        const { command, args } = curaCommand(curaExe, curaDefs, model.path, join(outDir, `${safeName(model.name)}.cura.gcode`), threads);
        cura = await repeatRuns('CuraEngine', () => measure(command, args));
      }
    }
    let prusa: SlicerStats = notRun('missing');
    if (prusaExe) {
      if (!peerReads('prusa', model.path)) prusa = notRun('unsupported');
      else {
        const { command, args } = prusaCommand(prusaExe, prusaData, model.path, join(outDir, `${safeName(model.name)}.prusa.gcode`));
        prusa = await repeatRuns('PrusaSlicer', () => measure(command, args));
      }
    }
    rows.push({ model: model.name, triangles: model.triangles, strata, cura, prusa });
  }

  const benchy = options.patterns && strataBuilt ? patternModel(models) : null;
  let patterns: PatternRow[] = [];
  if (benchy) {
    ctx.log(`infill patterns on ${benchy.name}`);
    const raw: Omit<PatternRow, 'relativeToGrid'>[] = [];
    for (const pattern of PATTERN_IDS) {
      raw.push({ pattern, strata: await strataRun(benchy, `infill-${pattern}`, ['--infill-pattern', pattern]) });
    }
    patterns = relativeToGrid(raw);
  } else if (options.patterns && strataBuilt) {
    notes.push('infill-pattern section skipped: 3DBenchy is not among the selected models');
  }

  const cpuList = cpus();
  return {
    startedAt: new Date().toISOString(),
    machine: {
      cpus: availableParallelism(),
      cpuModel: cpuList[0]?.model.trim() ?? 'unknown',
      node: process.version,
      platform: `${platform()} ${process.arch}`,
      loadAverage: { start: loadAtStart, end: loadavg()[0]! },
    },
    threads,
    repeat: options.repeat,
    memoryMethod,
    strataCli: { path: strataPath, built: strataBuilt },
    peers: {
      cura: curaExe && curaDefs ? { path: curaExe, version: peerVersion('cura', curaExe), definitions: curaDefs } : null,
      prusa: prusaExe ? { path: prusaExe, version: peerVersion('prusa', prusaExe) } : null,
    },
    models: rows,
    patternModel: benchy?.name ?? null,
    patterns,
    notes,
  };
}
