/**
 * The threads a slice's layer jobs run on: the pool of workers the schedule asks for (if any) and the calling
 * thread, which paces its own share (a pause after each layer). Jobs run where a step says (schedule.ts).
 */
import type { CustomInfillSpec } from '../infill/patterns/custom.js';
import { loadCustomInfill, loadedCustomInfill } from '../infill/registry.js';
import { prepareMesh as prepareForSlicing, type PreparedMesh } from '../slice/index.js';
import type { LayerWork, RangeJob, ResultOf } from '../workers/layer-work.js';
import { rangeSteps } from '../workers/layer-work.js';
import { createPool, releaseWorkers, sharePrepared, type LayerPool } from '../workers/pool.js';
import type { Port } from '../workers/ports.js';
import { type Pacer, wait, type Steps } from './pacer.js';
import type { PlateSetup } from './print-setup.js';
import type { JobsOn, Schedule } from './schedule.js';
import type { SliceSetup } from './slice-setup.js';

/**
 * With workers, the calling thread plans the ranges as they arrive, and computes ranges too only when
 * the work left would keep the workers busy longer than this (ms). Its first range is slow (cold code),
 * and compiling that code costs about a second of CPU, which competes with the workers when no core is
 * spare: on two cores, two threads computing a Benchy were slower than one.
 */
const HELP_ABOVE_MS = 2000;

/** The meshes prepared for slicing on the calling thread (shared with the workers), made on first use. */
class Meshes {
  #meshes: PreparedMesh[] | null = null;
  constructor(
    readonly plate: PlateSetup,
    readonly shared: boolean,
  ) {}

  get(): PreparedMesh[] {
    this.#meshes ??= this.plate.meshes.map((m) =>
      this.shared ? sharePrepared(prepareForSlicing(m)) : prepareForSlicing(m),
    );
    return this.#meshes;
  }

  /** Prepare them one by one, pausing between objects. */
  *prepare(): Steps<void> {
    this.#meshes ??= [];
    for (let k = this.#meshes.length; k < this.plate.meshes.length; k++) {
      this.#meshes.push(prepareForSlicing(this.plate.meshes[k]));
      yield;
    }
  }

  /** Every layer is sliced: their slicing structures go (the pool's with them). */
  release(): void {
    this.#meshes = null;
  }
}

export class LayerThreads {
  readonly #pool: LayerPool | null;
  readonly #pacer: Pacer;
  readonly #signal?: AbortSignal;
  readonly #meshes: Meshes;
  /** The calling thread's share of the work (its custom infill, the regions it holds). */
  readonly here: LayerWork;
  /** Called after each layer the calling thread computes when there are no workers (progress). */
  onLayerHere: () => void = () => {};

  constructor(pool: LayerPool | null, meshes: Meshes, here: LayerWork, pacer: Pacer, signal?: AbortSignal) {
    this.#pool = pool;
    this.#meshes = meshes;
    this.here = here;
    this.#pacer = pacer;
    this.#signal = signal;
  }

  get hasWorkers(): boolean {
    return this.#pool !== null;
  }

  /** Compute a job on the calling thread, pausing after each layer. */
  *compute<J extends RangeJob>(job: J): Steps<ResultOf<J>> {
    const steps = rangeSteps(this.here, job);
    for (;;) {
      const s = steps.next();
      if (s.done) return s.value;
      if (!this.#pool) this.onLayerHere();
      yield;
    }
  }

  /**
   * Run jobs where `on` says; `onResult` sees each result as it arrives (in any order with workers), with
   * where it was computed (a worker's index, or -1 on this thread).
   */
  *run<J extends RangeJob>(
    jobs: J[],
    on: JobsOn,
    onResult: (id: number, r: ResultOf<J>, where: number) => void,
  ): Steps<void> {
    this.#pacer.check();
    const pool = this.#pool;
    if (!pool) {
      for (let id = 0; id < jobs.length; id++) onResult(id, yield* this.compute(jobs[id]), -1);
      return;
    }
    yield* wait(
      pool.run(jobs, {
        local: (job) => this.#pacer.drive(this.compute(job)),
        onResult,
        signal: this.#signal,
        helpAboveMs: on === 'workers' ? Infinity : HELP_ABOVE_MS,
      }),
    );
  }

  /** Run job i on worker `placement[i]` (which holds what it reads), not waiting for them. */
  place<J extends RangeJob>(
    jobs: J[],
    placement: number[],
    onResult: (id: number, r: ResultOf<J>) => void,
  ): Promise<void> {
    if (!this.#pool) throw new Error('jobs placed on workers, but there are none');
    const done = this.#pool.run(jobs, { placement, onResult, signal: this.#signal });
    // its failure is met where it is awaited
    done.catch(() => {});
    return done;
  }

  /** Every layer is sliced: the meshes' slicing structures go. */
  releaseMeshes(): void {
    this.#meshes.release();
  }

  /** End the workers (their memory goes back); again is harmless. */
  *close(): Steps<void> {
    this.#meshes.release();
    if (this.#pool) yield* wait(this.#pool.close());
  }
}

/**
 * Start the threads the schedule asks for: without workers, prepare the meshes here (pausing between
 * objects); with them, start the pool (or take the workers started early, `started`), which prepares the
 * meshes in shared memory while they load. Then compile the custom infill for this thread (loading its
 * module first if need be). Workers started early and not needed are ended.
 */
export function* startThreads(
  plate: PlateSetup,
  s: SliceSetup,
  sched: Schedule,
  opts: { custom?: CustomInfillSpec; started?: Promise<Port[]>; signal?: AbortSignal },
  pacer: Pacer,
): Steps<LayerThreads> {
  const meshes = new Meshes(plate, sched.workers > 0);
  if (sched.workers === 0) yield* meshes.prepare();
  const pool =
    sched.workers > 0
      ? yield* wait(createPool(sched.workers, () => meshes.get(), s.setup, opts.custom, opts.started))
      : null;
  if (!pool && opts.started) yield* wait(releaseWorkers(opts.started));
  const threads = new LayerThreads(
    pool,
    meshes,
    { meshes: () => meshes.get(), setup: s.setup, held: new Map() },
    pacer,
    opts.signal,
  );
  try {
    if (opts.custom) {
      const custom = loadedCustomInfill() ?? (yield* wait(loadCustomInfill()));
      threads.here.custom = custom.customPattern(opts.custom, s.cfg);
    }
  } catch (e) {
    yield* threads.close();
    throw e;
  }
  return threads;
}
