/**
 * The schedule of a slice, decided before anything is sliced, as a pure function of a few flags: how many
 * workers, which layer ranges, and the steps that run, in order, each with where it runs. run.ts carries the
 * steps out one after the other, as they are listed here.
 *
 * Why this way:
 * - Per-layer work (slicing, regions, paths) is most of a slice and independent from layer to layer, so it
 *   runs in ranges on a pool of workers. The calling thread plans the ranges as they arrive (travel planning
 *   is sequential: each layer starts where the last one ended), and computes ranges too only when the work
 *   left would keep the workers busy long enough (threads.ts); `threads` counts it, so N threads are N − 1
 *   workers and the calling thread.
 * - A whole-model pass (support, lightning, raft: passes.ts) reads every layer's regions, so it waits for all
 *   of them and runs on the calling thread. The model's own paths need none of them unless a pass says they
 *   read what it makes (lightning's infill, skin resting on support with no top Z gap): they are made with
 *   the regions, while both are at hand, and only the outlines are kept for the passes; the support and the
 *   skirt join them afterwards. With workers and a long pass (support), each range keeps its regions on the
 *   worker that made them, which makes their model paths while the calling thread runs the pass.
 * - A custom infill may spend seconds on a layer, which the calling thread cannot break off: with
 *   `customInWorkers` its layers go to as many workers as threads, and the calling thread only plans, so an
 *   abort ends the workers at once. A custom density given as a JS function cannot travel to a worker:
 *   such a slice runs on the calling thread alone.
 */

/** A whole-model pass (passes.ts). */
export type PassName = 'support' | 'lightning' | 'raft';

/** What the schedule needs to know of a whole-model pass the slice needs. */
export interface PassNeed {
  name: PassName;
  /** The model's own paths read what the pass makes, so they are made after it. */
  modelPathsWait: boolean;
  /** The pass takes long enough that the workers make the model paths meanwhile. */
  long: boolean;
}

export interface ScheduleInput {
  /** Layers in the print. */
  layers: number;
  /** Threads: the calling thread plus threads − 1 workers; 1 runs everything on the calling thread. */
  threads: number;
  /** The slice's custom infill: none, plain data (it can go to workers), or one bound to this thread. */
  custom: 'none' | 'plain' | 'this thread';
  /** A custom infill's layers go to workers only (see above). */
  customInWorkers: boolean;
  /** The whole-model passes the slice needs, in the order they run. */
  passes: readonly PassNeed[];
}

/**
 * Where the layer jobs of a step run: 'pool': on the workers, and on the calling thread when the work left is
 * long; 'workers': on the workers only; 'calling thread': there alone (no workers).
 */
export type JobsOn = 'pool' | 'workers' | 'calling thread';

/** What a 'regions' step keeps of each layer. */
export type RegionsKept =
  /** every layer's regions, for the passes and the 'paths' step */
  | 'regions'
  /** the outlines, after making the layer's model paths with its regions */
  | 'outlines, model paths made'
  /** the outlines, the regions held on the thread that made them for a 'held' step */
  | 'outlines, regions held';

export type Step =
  /** Each range's regions and at once its paths, planned on the calling thread as the ranges arrive. */
  | { stage: 'layers'; on: JobsOn }
  /** Each range's regions, for the whole-model passes. */
  | { stage: 'regions'; on: JobsOn; keep: RegionsKept }
  /**
   * The model paths of the held regions, each range on the thread that holds it: 'workers' starts those of
   * the workers' ranges, which run on while the next steps do; 'calling thread' makes those of the ranges it
   * made (if any), then waits for the workers'.
   */
  | { stage: 'held'; on: 'workers' | 'calling thread' }
  /** The whole-model passes, in order. */
  | { stage: 'passes'; on: 'calling thread'; passes: PassName[] }
  /** The raft's paths, planned before the model's. */
  | { stage: 'raft'; on: 'calling thread' }
  /** Each layer's model paths with the skirt or brim and the support joined to them, planned in layer order. */
  | { stage: 'shared'; on: 'calling thread' }
  /** Each range's paths from its regions and what the passes made, planned as the ranges arrive. */
  | { stage: 'paths'; on: JobsOn }
  /** The sequential order, the passes over the plan, the estimate, the G-code. */
  | { stage: 'finish'; on: 'calling thread' };

export interface Schedule {
  /** Layer ranges [from, to) of the layer jobs, in order. */
  ranges: Array<[number, number]>;
  /** Workers in the pool (0: none, everything on the calling thread). */
  workers: number;
  /** The steps, in the order they run. */
  steps: Step[];
}

/** Split [0, n) into ranges: several per thread for balance, each a few layers at least. */
export function ranges(n: number, threads: number): Array<[number, number]> {
  if (threads <= 1) return [[0, n]];
  const pieces = Math.min(n, threads * 4);
  const out: Array<[number, number]> = [];
  for (let k = 0; k < pieces; k++) {
    const a = Math.floor((k * n) / pieces),
      b = Math.floor(((k + 1) * n) / pieces);
    if (b > a) out.push([a, b]);
  }
  return out;
}

export function schedule(input: ScheduleInput): Schedule {
  // a custom infill in workers only: as many workers as threads, in two ranges at least so progress shows
  const workersOnly = input.customInWorkers && input.custom === 'plain';
  const split = ranges(input.layers, workersOnly ? Math.max(2, input.threads) : input.threads);
  const workers =
    input.custom === 'this thread'
      ? 0
      : workersOnly
        ? Math.min(Math.max(1, input.threads), split.length)
        : Math.min(input.threads, split.length) - 1;
  const on: JobsOn = workers === 0 ? 'calling thread' : workersOnly ? 'workers' : 'pool';
  const steps: Step[] = [];
  const { passes } = input;
  if (passes.length === 0) steps.push({ stage: 'layers', on });
  else {
    const early = !passes.some((p) => p.modelPathsWait);
    const hold = early && workers > 0 && passes.some((p) => p.long);
    const keep: RegionsKept = !early ? 'regions' : hold ? 'outlines, regions held' : 'outlines, model paths made';
    steps.push({ stage: 'regions', on, keep });
    if (hold) steps.push({ stage: 'held', on: 'workers' });
    steps.push({ stage: 'passes', on: 'calling thread', passes: passes.map((p) => p.name) });
    if (hold) steps.push({ stage: 'held', on: 'calling thread' });
    if (passes.some((p) => p.name === 'raft')) steps.push({ stage: 'raft', on: 'calling thread' });
    steps.push(early ? { stage: 'shared', on: 'calling thread' } : { stage: 'paths', on });
  }
  steps.push({ stage: 'finish', on: 'calling thread' });
  return { ranges: split, workers, steps };
}
