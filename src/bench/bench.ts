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

/** One slicer invocation to measure. */
interface Job {
  label: string;
  command: string;
  args: string[];
}

const isJob = (x: Job | SlicerStats): x is Job => 'command' in x;

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

  /**
   * Runs each job `repeat` times, round-robin (one run of every job per round, so a change in machine load
   * during the run hits every slicer alike), dropping a job after its first failure; folds each job's runs.
   * An entry that is already a SlicerStats (missing, unsupported) is passed through.
   */
  const runRounds = async <K extends string>(jobs: Record<K, Job | SlicerStats>): Promise<Record<K, SlicerStats>> => {
    const keys = Object.keys(jobs) as K[];
    const runs = new Map<K, Measurement[]>();
    const active = new Set(keys.filter((k) => isJob(jobs[k])));
    for (const k of active) runs.set(k, []);
    for (let round = 1; round <= options.repeat && active.size > 0; round++) {
      for (const k of [...active]) {
        if (ctx.signal?.aborted) break;
        const job = jobs[k] as Job;
        const m = await measure(job.command, job.args);
        runs.get(k)!.push(m);
        ctx.log(`  ${job.label} run ${round}/${options.repeat}: ${m.wallSeconds.toFixed(2)} s${m.exitCode === 0 && !m.timedOut ? '' : ' (failed)'}`);
        if (m.exitCode !== 0 || m.timedOut) active.delete(k);
      }
    }
    const out = {} as Record<K, SlicerStats>;
    for (const k of keys) {
      const job: Job | SlicerStats = jobs[k];
      if (!isJob(job)) out[k] = job;
      else out[k] = runs.get(k)!.length > 0 ? summarize(runs.get(k)!) : notRun('skipped', 'interrupted');
    }
    return out;
  };

  const strataJob = (model: BenchModel, tag: string, extra: readonly string[]): Job | SlicerStats => {
    if (!strataBuilt) return notRun('missing', 'strata CLI not built');
    const out = join(outDir, `${safeName(model.name)}.${tag}.gcode`);
    // without --threads, Strata picks its own default (what a user gets); CuraEngine gets one per core
    const args = [strataPath, 'slice', model.path, '-o', out, ...(options.threads !== null ? ['--threads', String(options.threads)] : []), ...extra];
    return { label: ['Strata', ...extra].join(' '), command: process.execPath, args };
  };
  const curaJob = (model: BenchModel): Job | SlicerStats => {
    if (!curaExe || !curaDefs) return notRun('missing');
    if (!peerReads('cura', model.path)) return notRun('unsupported', 'CuraEngine reads STL only');
    return { label: 'CuraEngine', ...curaCommand(curaExe, curaDefs, model.path, join(outDir, `${safeName(model.name)}.cura.gcode`), threads) };
  };
  const prusaJob = (model: BenchModel): Job | SlicerStats => {
    if (!prusaExe) return notRun('missing');
    if (!peerReads('prusa', model.path)) return notRun('unsupported');
    return { label: 'PrusaSlicer', ...prusaCommand(prusaExe, prusaData, model.path, join(outDir, `${safeName(model.name)}.prusa.gcode`)) };
  };

  const rows: ModelRow[] = [];
  for (const [index, model] of models.entries()) {
    ctx.log(`[${index + 1}/${models.length}] ${model.name}`);
    const r = await runRounds({ strata: strataJob(model, 'strata', []), cura: curaJob(model), prusa: prusaJob(model) });
    rows.push({ model: model.name, triangles: model.triangles, ...r });
  }

  const benchy = options.patterns && strataBuilt ? patternModel(models) : null;
  let patterns: PatternRow[] = [];
  if (benchy) {
    ctx.log(`infill patterns on ${benchy.name}`);
    const jobs = Object.fromEntries(PATTERN_IDS.map((p) => [p, strataJob(benchy, `infill-${p}`, ['--infill-pattern', p])])) as Record<string, Job | SlicerStats>;
    const results = await runRounds(jobs);
    const raw = PATTERN_IDS.map((pattern) => ({ pattern, strata: results[pattern]! }));
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
    threadsGiven: options.threads !== null,
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
