/**
 * The whole pipeline for placed objects, as stages over explicit data. Where each runs, and why:
 *
 *   1. setup       calling thread   the plate's layers, each object's infill origin, the sequential order
 *                                   (slice-setup.ts) and the whole-model passes it needs (passes.ts)
 *   2. schedule    calling thread   a pure function of those flags (schedule.ts): the layer ranges, how many
 *                                   workers, and the steps below in order, each with where it runs
 *   3. threads     calling thread   the meshes prepared for slicing (in shared memory for the workers), the
 *                                   pool started, the custom infill compiled (threads.ts)
 *   4. layer work  workers (and the calling thread when the work left is long; alone with threads = 1):
 *                  ranges of layers sliced into regions and paths (workers/layer-work.ts): at once when no
 *                  pass needs every layer's regions ('layers'), else 'regions', then after the passes the
 *                  'paths' (or, when the model's paths need no pass, made with the regions and only 'shared'
 *                  groups, skirt and support, joined after them; 'held' on the workers during the passes)
 *   5. passes      calling thread   support, lightning, raft: each reads every layer's regions (passes.ts)
 *   6. plan        calling thread   each layer's travel, in layer order, as the ranges arrive: overlapped with
 *                                   the layer work, since each layer starts where the one before ended
 *   7. finish      calling thread   sequential order, passes over the plan, estimate, G-code to the sink
 *                                   (planner.ts)
 *
 * The per-layer work is most of a slice and independent from layer to layer, so it is what goes to workers;
 * the passes and the plan read across layers. The calling thread paces its own work (progress per layer, an
 * abort acts within a time slice: pacer.ts).
 */
import { isTransferable } from '../infill/registry.js';
import type { CustomInfillSpec } from '../infill/patterns/custom.js';
import type { Port } from '../workers/ports.js';
import { Pacer, type Steps } from './pacer.js';
import { neededPasses, type PassSetup } from './passes.js';
import { Planner, VERSION, type Planned, type ThinLoss, type VaseFlat } from './planner.js';
import type { PlateSetup } from './print-setup.js';
import { schedule, type ScheduleInput } from './schedule.js';
import { sliceSetup } from './slice-setup.js';
import { LayerProgress, runStep, type SliceRun } from './stages.js';
import { startThreads } from './threads.js';

export type { PlacedObject, PlateSetup } from './print-setup.js';
export { VERSION, type ThinLoss, type VaseFlat };

export interface Progress {
  stage: 'slicing' | 'support' | 'planning' | 'writing';
  /** 0..1 over the whole run. */
  fraction: number;
}

export interface RunOptions {
  /** Threads: the calling thread plus threads − 1 workers; 1 runs inline. */
  threads: number;
  onProgress?: (p: Progress) => void;
  signal?: AbortSignal;
  /** Receives the G-code in chunks. */
  sink: (chunk: string) => void;
  /** Custom infill (shader or image) in place of every region's pattern. */
  custom?: CustomInfillSpec;
  /** Workers started early (`startWorkers`); used, or ended, here. */
  started?: Promise<Port[]>;
  /**
   * Compute a custom infill's layers in workers only (as many as `threads`; the calling thread plans the
   * ranges and computes none): a shader may spend many seconds on one layer, which the calling thread
   * cannot break off, so an abort (a signal, Ctrl-C) would wait for it there; a worker is ended at once.
   * For runs that can wait (not the synchronous slice); a density given as a JS function stays inline.
   */
  customInWorkers?: boolean;
}

/** The plan, its estimate, and what was left out or printed flat. */
export type RunResult = Planned;

/** Run the pipeline, pacing the calling thread's work (see Pacer). */
export function runPipeline(plate: PlateSetup, opts: RunOptions): Promise<RunResult> {
  const pacer = new Pacer(opts.signal);
  return pacer.drive(runPipelineSteps(plate, opts, pacer));
}

/**
 * Run the pipeline on the calling thread at once, without workers: the same stages and the same G-code as
 * `runPipeline` with any thread count. Throws if something would have to be waited for (a custom infill's
 * compiler not loaded yet).
 */
export function runPipelineSync(plate: PlateSetup, opts: Omit<RunOptions, 'threads' | 'started'>): RunResult {
  const pacer = new Pacer(opts.signal);
  return pacer.driveSync(runPipelineSteps(plate, { ...opts, threads: 1 }, pacer));
}

/** The schedule's flags of a slice. */
export function scheduleInput(s: PassSetup, opts: RunOptions): ScheduleInput {
  return {
    layers: s.layers.length,
    threads: opts.threads,
    custom: !opts.custom ? 'none' : isTransferable(opts.custom) ? 'plain' : 'this thread',
    customInWorkers: !!opts.customInWorkers,
    passes: neededPasses(s),
  };
}

/** 'finish': the plan's last layer, the workers ended, then the passes over the plan, the estimate, the G-code. */
function* finish(
  run: SliceRun,
  plate: PlateSetup,
  sink: (chunk: string) => void,
  report: (stage: Progress['stage'], fraction: number) => void,
): Steps<RunResult> {
  run.planner.end();
  // the workers' memory and the meshes' slicing structures go back before the G-code is written
  yield* run.threads.close();
  return yield* run.planner.finish(plate.objects, sink, (stage, done, total) =>
    stage === 'estimate'
      ? report('planning', 0.8 + (0.1 * done) / total)
      : report('writing', stage === 'write' ? 0.9 + (0.1 * done) / total : 1),
  );
}

/**
 * The pipeline as steps: a pause point after each piece of calling-thread work (layer, object, pass step),
 * and a promise where it waits (workers, the compiler); the driver resumes it with the promise's value.
 */
export function* runPipelineSteps(plate: PlateSetup, opts: RunOptions, pacer: Pacer): Steps<RunResult> {
  pacer.check();
  const s: PassSetup = { ...sliceSetup(plate), custom: !!opts.custom };
  const input = scheduleInput(s, opts);
  const sched = schedule(input);
  const report = (stage: Progress['stage'], fraction: number) => opts.onProgress?.({ stage, fraction });
  const threads = yield* startThreads(plate, s, sched, opts, pacer);
  try {
    const progress = new LayerProgress(s.layers.length, input.passes.length > 0, (f) => report('slicing', f));
    threads.onLayerHere = () => progress.layersDone(1);
    const run: SliceRun = {
      s,
      sched,
      threads,
      planner: new Planner(s),
      progress,
      onPasses: () => report('support', 0.4),
      where: [],
      layers: { outlines: [], regions: null },
      modelPaths: [],
      heldOnWorkers: null,
      passes: {},
    };
    for (const step of sched.steps) {
      if (step.stage === 'finish') return yield* finish(run, plate, opts.sink, report);
      yield* runStep(run, step);
    }
    throw new Error('a schedule ends with its finish step');
  } finally {
    yield* threads.close();
  }
}
