/**
 * The benchmark itself. Each section is one or more interleaved blocks (interleave.ts):
 *  1. every model: Strata with its default settings, CuraEngine and PrusaSlicer (where installed);
 *  2. 3DBenchy with --threads 1 and --threads 2 (and whether their G-code equals the default's);
 *  3. 3DBenchy with every infill pattern, against grid;
 *  4. support (normal, tree) against none on SupportTest, Overhang, spot, 3DBenchy, BridgeTest (also scaled 2× in X
 *     and Y) and the hollow cube;
 *  5. variable walls against classic (--wall-generator) on 3DBenchy, the hollow cube and BridgeTest, and
 *     variable against CuraEngine's runs of section 1 on the same model.
 * Every block records how much other processes ran meanwhile (load.ts). Returns the results as data (report.ts).
 */
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readFileSync } from 'node:fs';
import { availableParallelism, cpus, loadavg, platform } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { PATTERN_IDS } from '#strata/infill/types.js';
import type { BenchOptions } from './args.js';
import { selectModels } from './args.js';
import { runInterleaved, type Job } from './interleave.js';
import { blockLoad, busyThreshold, loadMark, loadWarnings, startLoadWarning, type BlockLoad } from './load.js';
import { detectMemoryMethod, measureCommand, type MemoryMethod } from './measure.js';
import {
  BIG_MODEL,
  bigModelSource,
  defaultModelsDir,
  listModelFiles,
  prepareModels,
  type BenchModel,
} from './models.js';
import {
  curaCommand,
  findCuraDefinitions,
  findOnPath,
  PEER_EXECUTABLES,
  peerReads,
  peerVersion,
  prusaCommand,
} from './peers.js';
import { readSelfTimes } from './proc.js';
import type { BenchReport, ModelRow, PatternRow, SlicerStats, SupportRow, ThreadScaling, WallsRow } from './report.js';
import { notRun, pairedRatio, relativeToGrid, supportRow, triangleScaling, wallsRow } from './report.js';
import { checkTargets, TARGET_MODELS } from './targets.js';

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

/** Models the support section runs on, when selected. */
export const SUPPORT_MODELS = Object.freeze([
  'SupportTest.stl',
  'Overhang.stl',
  'spot.stl',
  '3DBenchy.stl',
  'BridgeTest.stl',
  'HollowCalibrationCube.stl',
]);

/**
 * The support section also runs this model scaled (X and Y twice, the same layers): four times the overhang
 * over a part that is quick to slice, so the tree's work outweighs the part's more than on any shared model.
 */
export const SUPPORT_SCALED = Object.freeze({ model: 'BridgeTest.stl', scale: '2,2,1' });

/** Models the walls section runs on, when selected (3DBenchy as the 3DBenchy sections pick it: see wallsModels). */
export const WALLS_MODELS = Object.freeze(['3DBenchy.stl', 'HollowCalibrationCube.stl', 'BridgeTest.stl']);

/**
 * The selected models the walls section runs on, in their order: those of WALLS_MODELS, with 3DBenchy the one
 * the 3DBenchy sections use (its 3MF when only that is selected).
 */
export function wallsModels(models: readonly BenchModel[]): BenchModel[] {
  const benchy = patternModel(models);
  return models.filter((m) => m === benchy || WALLS_MODELS.includes(m.name));
}

/** dist/bin/main.js of this build (from dist-dev/tools/bench/): the bundled CLI users run. */
export function defaultStrataCli(): string {
  return fileURLToPath(new URL('../../../dist/bin/main.js', import.meta.url));
}

const safeName = (s: string) => s.replace(/[^A-Za-z0-9._-]+/g, '_');

/** The model the 3DBenchy sections use: 3DBenchy as STL if selected, else its 3MF, else none. */
export function patternModel(models: readonly BenchModel[]): BenchModel | null {
  const benchies = models.filter((m) => m.name.toLowerCase().startsWith('3dbenchy.'));
  return benchies.find((m) => m.name.toLowerCase().endsWith('.stl')) ?? benchies[0] ?? null;
}

/** The model files on offer: the folder's, plus the big mesh when it can be made (and is wanted). */
export function availableModels(files: readonly string[], big: boolean): string[] {
  const withoutBig = files.filter((f) => f !== BIG_MODEL);
  if (!big) return withoutBig;
  return files.includes(BIG_MODEL) || bigModelSource(files) ? [...withoutBig, BIG_MODEL] : withoutBig;
}

function fileHash(path: string): string | null {
  try {
    return createHash('sha256').update(readFileSync(path)).digest('hex');
  } catch {
    return null;
  }
}

export async function runBench(options: BenchOptions, ctx: BenchContext): Promise<BenchReport> {
  const startedAt = new Date().toISOString();
  const env = ctx.env ?? process.env;
  const modelsDir = resolve(options.modelsDir ?? defaultModelsDir());
  if (!existsSync(modelsDir)) throw new Error(`models folder not found: ${modelsDir}`);
  const available = availableModels(listModelFiles(modelsDir), options.big);
  const names = selectModels(available, options.models);
  if (names.length === 0) {
    throw new Error(
      `no model matches --models ${options.models.join(',')}; models in ${modelsDir}: ${available.join(', ') || 'none'}`,
    );
  }
  if (names.includes(BIG_MODEL)) ctx.log(`making ${BIG_MODEL} (3DBenchy, subdivided once) …`);
  const models = prepareModels(modelsDir, names, ctx.workDir);
  const outDir = join(ctx.workDir, 'out');
  mkdirSync(outDir, { recursive: true });
  const prusaData = join(ctx.workDir, 'prusa-datadir');
  mkdirSync(prusaData, { recursive: true });

  const cpuCount = availableParallelism();
  const memoryMethod = ctx.memoryMethod ?? detectMemoryMethod();
  const curaThreads = options.threads ?? cpuCount;
  const timeoutMs = options.timeoutSeconds * 1000;
  const strataPath = resolve(options.strataCli ?? defaultStrataCli());
  const strataBuilt = existsSync(strataPath);

  const curaExe = options.peers ? findOnPath(PEER_EXECUTABLES.cura, env) : null;
  const curaDefs = curaExe ? findCuraDefinitions(env) : null;
  const prusaExe = options.peers && options.prusa ? findOnPath(PEER_EXECUTABLES.prusa, env) : null;
  const notes: string[] = [];
  if (curaExe && !curaDefs)
    notes.push(
      `CuraEngine found at ${curaExe} but no fdmprinter.def.json (install Debian's \`cura\` package or set CURA_FDMPRINTER)`,
    );
  const peers: BenchReport['peers'] = {
    cura: curaExe && curaDefs ? { path: curaExe, version: peerVersion('cura', curaExe), definitions: curaDefs } : null,
    prusa: prusaExe ? { path: prusaExe, version: peerVersion('prusa', prusaExe) } : null,
  };

  // Read last, just before the first run (after unpacking, subdividing and asking the peers their versions).
  const loadBefore = loadavg()[0]!;
  const startWarning = startLoadWarning(loadBefore, cpuCount);
  if (startWarning) ctx.log(`WARNING: ${startWarning}`);

  const blocks: BlockLoad[] = [];
  const block = async <K extends string>(
    label: string,
    jobs: Record<K, Job | SlicerStats>,
  ): Promise<Record<K, SlicerStats>> => {
    const mark = loadMark();
    const result = await runInterleaved(jobs, {
      repeat: options.repeat,
      warmup: options.warmup,
      measure: (job) =>
        measureCommand(job.command, job.args, {
          method: memoryMethod,
          timeoutMs,
          env,
          ...(ctx.signal ? { signal: ctx.signal } : {}),
        }),
      log: ctx.log,
      ...(ctx.signal ? { signal: ctx.signal } : {}),
    });
    blocks.push(blockLoad(label, mark, cpuCount));
    return result;
  };
  const aborted = () => ctx.signal?.aborted === true;

  const gcodePath = (model: BenchModel, tag: string) => join(outDir, `${safeName(model.name)}.${tag}.gcode`);
  const strataJob = (model: BenchModel, tag: string, extra: readonly string[]): Job | SlicerStats => {
    if (!strataBuilt) return notRun('missing', 'strata CLI not built');
    // without --threads, Strata picks its own default (what a user gets)
    const threads =
      options.threads !== null && !extra.includes('--threads') ? ['--threads', String(options.threads)] : [];
    const args = [strataPath, 'slice', model.path, '-o', gcodePath(model, tag), ...threads, ...extra];
    return { label: ['Strata', ...extra].join(' '), command: process.execPath, args };
  };
  const curaJob = (model: BenchModel): Job | SlicerStats => {
    if (!curaExe || !curaDefs) return notRun('missing');
    if (!peerReads('cura', model.path)) return notRun('unsupported', 'CuraEngine reads STL only');
    return {
      label: 'CuraEngine',
      ...curaCommand(curaExe, curaDefs, model.path, gcodePath(model, 'cura'), curaThreads),
    };
  };
  const prusaJob = (model: BenchModel): Job | SlicerStats => {
    if (!prusaExe) return notRun('missing');
    if (!peerReads('prusa', model.path)) return notRun('unsupported');
    return { label: 'PrusaSlicer', ...prusaCommand(prusaExe, prusaData, model.path, gcodePath(model, 'prusa')) };
  };

  // 1. every model against the peers
  const rows: ModelRow[] = [];
  for (const [index, model] of models.entries()) {
    if (aborted()) break;
    ctx.log(`[${index + 1}/${models.length}] ${model.name}`);
    const r = await block(model.name, {
      strata: strataJob(model, 'strata', []),
      cura: curaJob(model),
      prusa: prusaJob(model),
    });
    rows.push({
      model: model.name,
      triangles: model.triangles,
      ...(model.madeFrom ? { madeFrom: model.madeFrom } : {}),
      ...r,
      wallRatio: pairedRatio(r.strata, r.cura, 'wallSeconds'),
      cpuRatio: pairedRatio(r.strata, r.cura, 'cpuSeconds'),
    });
  }

  const benchy = strataBuilt ? patternModel(models) : null;
  const needsBenchy = (section: string) => {
    if (strataBuilt && !benchy) notes.push(`${section} skipped: 3DBenchy is not among the selected models`);
  };

  // 2. one thread against two
  let threadScaling: ThreadScaling | null = null;
  if (options.threadScaling && !aborted()) {
    if (benchy) {
      ctx.log(`threads on ${benchy.name}`);
      const r = await block(`${benchy.name} threads`, {
        one: strataJob(benchy, 'threads-1', ['--threads', '1']),
        two: strataJob(benchy, 'threads-2', ['--threads', '2']),
      });
      const defaultRow = rows.find((row) => row.model === benchy.name);
      const allOk = r.one.status === 'ok' && r.two.status === 'ok' && defaultRow?.strata.status === 'ok';
      const hashes = allOk ? ['threads-1', 'threads-2', 'strata'].map((tag) => fileHash(gcodePath(benchy, tag))) : [];
      threadScaling = {
        model: benchy.name,
        one: r.one,
        two: r.two,
        speedup: pairedRatio(r.one, r.two, 'wallSeconds'),
        cpuRatio: pairedRatio(r.two, r.one, 'cpuSeconds'),
        gcodeIdentical: allOk && hashes.every((h) => h !== null) ? hashes.every((h) => h === hashes[0]) : null,
      };
    } else needsBenchy('thread section');
  }

  // 3. infill patterns against grid
  let patterns: PatternRow[] = [];
  if (options.patterns && !aborted()) {
    if (benchy) {
      ctx.log(`infill patterns on ${benchy.name}`);
      const jobs = Object.fromEntries(
        PATTERN_IDS.map((p) => [p, strataJob(benchy, `infill-${p}`, ['--infill-pattern', p])]),
      ) as Record<string, Job | SlicerStats>;
      const results = await block(`${benchy.name} patterns`, jobs);
      patterns = relativeToGrid(PATTERN_IDS.map((pattern) => ({ pattern, strata: results[pattern]! })));
    } else needsBenchy('infill-pattern section');
  }

  // 4. support against none
  const support: SupportRow[] = [];
  if (options.support && strataBuilt) {
    const supportModels = models.filter((m) => SUPPORT_MODELS.includes(m.name));
    if (supportModels.length === 0)
      notes.push(`support section skipped: none of ${SUPPORT_MODELS.join(', ')} is among the selected models`);
    // each model as it is, and the one whose support outweighs the part most scaled up as well
    const cases = supportModels.flatMap((model) => {
      const plain = { model, name: model.name, extra: [] as string[], tag: '' };
      if (model.name !== SUPPORT_SCALED.model) return [plain];
      return [
        plain,
        {
          model,
          name: `${model.name} --scale ${SUPPORT_SCALED.scale}`,
          extra: ['--scale', SUPPORT_SCALED.scale],
          tag: '-scaled',
        },
      ];
    });
    for (const { model, name, extra, tag } of cases) {
      if (aborted()) break;
      ctx.log(`support on ${name}`);
      const r = await block(`${name} support`, {
        none: strataJob(model, `support-none${tag}`, extra),
        normal: strataJob(model, `support-normal${tag}`, [...extra, '--support-enabled', '--support-type', 'normal']),
        tree: strataJob(model, `support-tree${tag}`, [...extra, '--support-enabled', '--support-type', 'tree']),
      });
      support.push(supportRow(name, r.none, r.normal, r.tree));
    }
  }

  // 5. variable walls against classic, and against CuraEngine's runs of section 1
  const walls: WallsRow[] = [];
  if (options.walls && strataBuilt) {
    const picked = wallsModels(models);
    if (picked.length === 0)
      notes.push(`walls section skipped: none of ${WALLS_MODELS.join(', ')} is among the selected models`);
    for (const model of picked) {
      if (aborted()) break;
      ctx.log(`walls on ${model.name}`);
      // Strata's `wallGenerator` setting; interleaved variable, classic, variable, classic …
      const r = await block(`${model.name} walls`, {
        variable: strataJob(model, 'walls-variable', ['--wall-generator', 'variable']),
        classic: strataJob(model, 'walls-classic', ['--wall-generator', 'classic']),
      });
      walls.push(
        wallsRow(model.name, r.variable, r.classic, rows.find((row) => row.model === model.name)?.cura ?? null),
      );
    }
  }

  if (aborted()) notes.push('interrupted: the sections after the interruption did not run');
  const cpuList = cpus();
  const load = { cpus: cpuCount, busyAbove: busyThreshold(cpuCount), before: loadBefore, blocks };
  const report: BenchReport = {
    startedAt,
    machine: {
      cpus: cpuCount,
      cpuModel: cpuList[0]?.model.trim() ?? 'unknown',
      node: process.version,
      platform: `${platform()} ${process.arch}`,
    },
    load,
    warnings: loadWarnings(load),
    repeat: options.repeat,
    warmup: options.warmup,
    threads: options.threads,
    curaThreads,
    memoryMethod,
    cpuMeasured: readSelfTimes() !== null,
    strataCli: { path: strataPath, built: strataBuilt },
    peers,
    models: rows,
    threadScaling,
    patternModel: patterns.length > 0 ? benchy!.name : null,
    patterns,
    support,
    walls,
    triangleScaling: triangleScaling(rows, TARGET_MODELS.benchy, BIG_MODEL),
    targets: [],
    notes,
  };
  report.targets = checkTargets(report);
  return report;
}
