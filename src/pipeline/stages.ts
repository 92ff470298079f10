/**
 * The steps of a slice's schedule (schedule.ts), each a function of what the steps before it made. Layer jobs
 * run where their step says (threads.ts); everything else here runs on the calling thread, which plans each
 * layer as its paths arrive, in layer order (planner.ts).
 */
import type { LayerPaths } from '../paths/types.js';
import { withSharedGroups } from '../paths/layer-paths.js';
import type { LayerOutlines, LayerRegions } from '../regions/types.js';
import type {
  HeldJob,
  LayersJob,
  OutlinesJob,
  PathsJob,
  PathsParams,
  PathsResult,
  RegionsJob,
} from '../workers/layer-work.js';
import { pathsContext, pathsOf } from '../workers/layer-work.js';
import { paced, wait, type Steps } from './pacer.js';
import { runPasses, supportUnder, type PassLayers, type PassOutputs, type PassSetup } from './passes.js';
import type { Planner } from './planner.js';
import type { JobsOn, PassName, RegionsKept, Schedule, Step } from './schedule.js';
import type { LayerThreads } from './threads.js';

/** Progress of the layer work: 80 % of the run, its regions and paths halves when there are passes between. */
export class LayerProgress {
  #done = 0;
  readonly #total: number;
  constructor(
    layers: number,
    twoPhases: boolean,
    readonly report: (fraction: number) => void,
  ) {
    this.#total = layers * (twoPhases ? 2 : 1);
  }

  layersDone(count: number): void {
    this.#done += count;
    this.report((0.8 * this.#done) / this.#total);
  }
}

/** What the steps of one slice share, and what each makes for the ones after it. */
export interface SliceRun {
  s: PassSetup;
  sched: Schedule;
  threads: LayerThreads;
  planner: Planner;
  progress: LayerProgress;
  /** Reports that the whole-model passes begin. */
  onPasses: () => void;
  /** Per range, where its regions were made: a worker's index, or −1 (the calling thread). */
  where: number[];
  /** Every layer as the 'regions' step left it. */
  layers: PassLayers;
  /** Per range, its model paths (made with its regions, or by the 'held' steps). */
  modelPaths: LayerPaths[][];
  /** The model paths being made on the workers that hold the regions ('held' on the workers). */
  heldOnWorkers: Promise<void> | null;
  passes: Partial<PassOutputs>;
}

/** Carry out one step of the schedule. */
export function runStep(run: SliceRun, step: Exclude<Step, { stage: 'finish' }>): Steps<void> {
  switch (step.stage) {
    case 'layers':
      return layersStep(run, step.on);
    case 'regions':
      return regionsStep(run, step.on, step.keep);
    case 'held':
      return step.on === 'workers' ? heldOnWorkers(run) : heldHere(run);
    case 'passes':
      return passesStep(run, step.passes);
    case 'raft':
      return raftStep(run);
    case 'shared':
      return sharedStep(run);
    case 'paths':
      return pathsStep(run, step.on);
  }
}

/** What the paths stage needs besides the regions: the infill origins, the raft's lift, the skirt. */
function pathsParams(run: SliceRun): PathsParams {
  const { cfg, infillParams } = run.s;
  return {
    infillParams,
    zOffset: run.passes.raft?.zOffset ?? 0,
    adhesion: cfg.adhesionType === 'skirt' || cfg.adhesionType === 'brim',
  };
}

/** The same for a layer's own paths, made apart from the support and skirt (which join them later) and the raft's. */
function ownPathsParams(run: SliceRun): PathsParams {
  return { ...pathsParams(run), zOffset: 0, adhesion: false };
}

/** Layer jobs that make paths, each range planned once it and those before it have arrived. */
function* planJobs(run: SliceRun, jobs: Array<LayersJob | PathsJob>, on: JobsOn): Steps<void> {
  const arrived: Array<PathsResult | undefined> = new Array(jobs.length);
  let next = 0;
  yield* run.threads.run(jobs, on, (id, r) => {
    if (run.threads.hasWorkers) run.progress.layersDone(jobs[id].to - jobs[id].from);
    arrived[id] = r;
    for (let ready = arrived[next]; ready; ready = arrived[next]) {
      arrived[next++] = undefined;
      for (const lp of ready.paths) run.planner.plan(lp);
    }
  });
}

/** 'layers': no pass reads every layer's regions, so each range makes its regions and paths at once. */
function layersStep(run: SliceRun, on: JobsOn): Steps<void> {
  const { layers } = run.s;
  const common = pathsParams(run);
  const jobs = run.sched.ranges.map(([from, to]): LayersJob => ({ kind: 'layers', layers, from, to, ...common }));
  return planJobs(run, jobs, on);
}

/** 'regions': every layer's regions (or their outlines) for the passes. */
function* regionsStep(run: SliceRun, on: JobsOn, keep: RegionsKept): Steps<void> {
  const { layers } = run.s;
  const modelPaths = ownPathsParams(run);
  const jobs = run.sched.ranges.map(([from, to]): RegionsJob | OutlinesJob =>
    keep === 'regions'
      ? { kind: 'regions', layers, from, to }
      : keep === 'outlines, regions held'
        ? { kind: 'outlines', layers, from, to, hold: true }
        : { kind: 'outlines', layers, from, to, hold: false, modelPaths },
  );
  const regions: LayerRegions[][] = [];
  const outlines: LayerOutlines[][] = [];
  yield* run.threads.run(jobs, on, (id, r, where) => {
    if ('regions' in r) regions[id] = r.regions;
    else {
      outlines[id] = r.outlines;
      run.modelPaths[id] = r.paths;
    }
    run.where[id] = where;
    if (run.threads.hasWorkers) run.progress.layersDone(jobs[id].to - jobs[id].from);
  });
  const full = keep === 'regions' ? regions.flat() : null;
  run.layers = { outlines: full ?? outlines.flat(), regions: full };
  run.threads.releaseMeshes();
}

/** The model paths of the regions held on the thread that made them (the one 'outlines' job's range). */
function heldJob(run: SliceRun, id: number): HeldJob {
  const [from, to] = run.sched.ranges[id];
  return { kind: 'held', layers: run.s.layers, from, to, modelPaths: ownPathsParams(run) };
}

/** 'held' on the workers: start the model paths of the ranges each worker holds; they run on meanwhile. */
function* heldOnWorkers(run: SliceRun): Steps<void> {
  const ids = run.sched.ranges.map((_, id) => id).filter((id) => run.where[id] >= 0);
  if (ids.length === 0) return;
  run.heldOnWorkers = run.threads.place(
    ids.map((id) => heldJob(run, id)),
    ids.map((id) => run.where[id]),
    (k, r) => (run.modelPaths[ids[k]] = r.paths),
  );
}

/** 'held' on the calling thread: the model paths of the ranges it made, then those the workers make. */
function* heldHere(run: SliceRun): Steps<void> {
  for (let id = 0; id < run.sched.ranges.length; id++)
    if (run.where[id] < 0) run.modelPaths[id] = (yield* run.threads.compute(heldJob(run, id))).paths;
  if (run.heldOnWorkers) yield* wait(run.heldOnWorkers);
}

/** 'passes': the whole-model passes, in order, on this thread. */
function* passesStep(run: SliceRun, names: PassName[]): Steps<void> {
  run.onPasses();
  run.passes = yield* paced(runPasses(names, run.layers, run.s));
}

/** 'raft': the raft's layers, planned first. */
function* raftStep(run: SliceRun): Steps<void> {
  const raft = run.passes.raft;
  if (!raft) return;
  const params = ownPathsParams(run);
  for (const r of raft.layers) {
    run.planner.plan(pathsOf(r, run.s.setup, params, run.threads.here.custom, []));
    yield;
  }
}

/** 'shared': each layer's model paths with what joins them after the passes (skirt or brim, support). */
function* sharedStep(run: SliceRun): Steps<void> {
  const { outlines } = run.layers;
  const common = pathsParams(run);
  const model = run.modelPaths.flat();
  for (let i = 0; i < outlines.length; i++) {
    const ctx = pathsContext(outlines[i], run.s.setup, common, run.threads.here.custom, []);
    run.planner.plan(withSharedGroups(model[i], outlines[i], ctx));
    run.progress.layersDone(1);
    yield;
  }
}

/** 'paths': every range's paths from its regions and what the passes made for them. */
function pathsStep(run: SliceRun, on: JobsOn): Steps<void> {
  const { layers } = run.s;
  const regions = run.layers.regions;
  if (!regions) throw new Error('a paths step needs every layer’s regions');
  const common = pathsParams(run);
  const lines = run.passes.lightning;
  const jobs = run.sched.ranges.map(
    ([from, to]): PathsJob => ({
      kind: 'paths',
      layers,
      from,
      to,
      ...common,
      regions: regions.slice(from, to),
      supportBelow: regions.slice(from, to).map((_, k) => supportUnder(regions, from + k, run.s)),
      infillLines: lines?.slice(from, to),
    }),
  );
  return planJobs(run, jobs, on);
}
