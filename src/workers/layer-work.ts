/**
 * The per-layer work of the pipeline, as jobs over ranges of layers that run the same on the calling thread
 * or in a worker (it lives here, with the workers, so that the pipeline reads the workers and not back):
 * - 'layers': slice the objects, make each layer's regions and at once its paths, when no whole-model pass
 *   needs every layer's regions first;
 * - 'regions': every layer's regions, for the whole-model passes and then a 'paths' job;
 * - 'outlines': every layer's regions, of which only the outlines come back (what the support and raft
 *   passes and the skirt read), after each layer's model paths are made with them, or with the regions kept
 *   on this thread for a 'held' job (`hold`);
 * - 'held': the model paths of the regions an 'outlines' job kept on this thread, made while the calling
 *   thread runs the support pass;
 * - 'paths': the paths of every layer from its regions and what the whole-model passes made for it.
 * This file only orchestrates: the regions stage is in regions/, the paths stage in paths/. Each job is a
 * generator that yields after every layer, so the calling thread can report progress and stay responsive.
 */
import type { ExPolygon, Polyline } from '../geometry/types.js';
import type { InfillParams, InfillPattern } from '../infill/types.js';
import { layerPaths, modelPaths, type LayerPathsContext } from '../paths/layer-paths.js';
import type { LayerPaths } from '../paths/types.js';
import { RegionsRun } from '../regions/layer-regions.js';
import { outlinesOf, type LayerOutlines, type LayerRegions } from '../regions/types.js';
import type { PrintSetup } from '../regions/objects.js';
import type { PreparedMesh } from '../slice/index.js';
import type { LayerZ } from '../slice/types.js';

interface JobBase {
  layers: readonly LayerZ[];
  from: number;
  to: number;
}

/** What the paths stage needs besides the regions. */
export interface PathsParams {
  /** Infill parameters per object (with the object's config; a region's config changes density and angle). */
  infillParams: InfillParams[];
  /** Added to every model layer's Z (the raft), mm. */
  zOffset: number;
  /** Whether the model's first layer gets the skirt or brim (no raft under it). */
  adhesion: boolean;
}

export interface LayersJob extends JobBase, PathsParams {
  kind: 'layers';
}

export interface RegionsJob extends JobBase {
  kind: 'regions';
}

/**
 * Every layer's outlines, after making its model paths (without support and skirt, which follow the support
 * pass) with `modelPaths`, or with its regions kept on this thread for a later 'held' job of the range (`hold`).
 */
export type OutlinesJob = JobBase & { kind: 'outlines' } & ({ hold: false; modelPaths: PathsParams } | { hold: true });

/** The model paths of the regions an 'outlines' job with `hold` kept on this thread. */
export interface HeldJob extends JobBase {
  kind: 'held';
  modelPaths: PathsParams;
}

export interface PathsJob extends JobBase, PathsParams {
  kind: 'paths';
  /** Regions of layers [from, to). */
  regions: LayerRegions[];
  /** Per layer of the range: support areas of the layer below where they hold it with no gap, µm. */
  supportBelow: ExPolygon[][];
  /** Per layer of the range: the whole-model infill's lines on it (lightning's trees), µm. */
  infillLines?: Polyline[][];
}

export type RangeJob = LayersJob | RegionsJob | OutlinesJob | HeldJob | PathsJob;

export interface RegionsResult {
  regions: LayerRegions[];
}

export interface OutlinesResult {
  outlines: LayerOutlines[];
  /** The model paths made with the regions ([] when they are held). */
  paths: LayerPaths[];
}

export interface PathsResult {
  paths: LayerPaths[];
}

/** What a job gives back. */
export type ResultOf<J extends RangeJob> = J extends RegionsJob
  ? RegionsResult
  : J extends OutlinesJob
    ? OutlinesResult
    : PathsResult;

export type RangeResult = ResultOf<RangeJob>;

/** Regions kept by 'outlines' jobs that hold them, by the first layer of their range. */
export type RegionsHeld = Map<number, LayerRegions[]>;

/** What a thread (a worker, or the calling thread) keeps for the jobs of one slice. */
export interface LayerWork {
  /** The objects' meshes prepared for slicing (asked for only by the jobs that slice). */
  meshes(): readonly PreparedMesh[];
  setup: PrintSetup;
  /** The slice's custom infill, compiled on this thread. */
  custom?: InfillPattern;
  /** Regions kept on this thread for its 'held' jobs. */
  held: RegionsHeld;
}

/** What the paths stage of one layer is given. */
export function pathsContext(
  layer: LayerZ,
  setup: PrintSetup,
  job: PathsParams,
  custom: InfillPattern | undefined,
  supportBelow: ExPolygon[],
  infillLines?: Polyline[],
): LayerPathsContext {
  return {
    cfg: setup.configs[0],
    configs: setup.configs,
    objectConfigs: setup.objects.map((o) => o.config),
    params: job.infillParams,
    prepared: infillLines,
    custom,
    supportBelow,
    zOffset: job.zOffset,
    adhesion: job.adhesion && layer.index === 0,
  };
}

/** The paths of one layer from its regions. */
export function pathsOf(
  regions: LayerRegions,
  setup: PrintSetup,
  job: PathsParams,
  custom: InfillPattern | undefined,
  supportBelow: ExPolygon[],
  infillLines?: Polyline[],
): LayerPaths {
  return layerPaths(regions, pathsContext(regions, setup, job, custom, supportBelow, infillLines));
}

/** The model paths of one layer (no support, no skirt: they join after the support pass). */
function modelPathsOf(regions: LayerRegions, work: LayerWork, params: PathsParams): LayerPaths {
  return modelPaths(regions, pathsContext(regions, work.setup, params, work.custom, []));
}

/** Run a job, yielding after each layer; returns its result. */
export function rangeSteps<J extends RangeJob>(work: LayerWork, job: J): Generator<void, ResultOf<J>>;
export function* rangeSteps(work: LayerWork, job: RangeJob): Generator<void, RangeResult> {
  const { setup, custom } = work;
  const paths: LayerPaths[] = [];
  if (job.kind === 'held') {
    const kept = work.held.get(job.from);
    if (!kept || kept.length !== job.to - job.from) throw new Error(`no regions held for layers ${job.from}-${job.to}`);
    work.held.delete(job.from);
    for (let k = 0; k < kept.length; k++) {
      paths.push(modelPathsOf(kept[k], work, job.modelPaths));
      yield;
    }
    return { paths };
  }
  if (job.kind === 'paths') {
    for (let k = 0; k < job.regions.length; k++) {
      paths.push(pathsOf(job.regions[k], setup, job, custom, job.supportBelow[k] ?? [], job.infillLines?.[k]));
      yield;
    }
    return { paths };
  }
  const regions: LayerRegions[] = [];
  const outlines: LayerOutlines[] = [];
  let kept: LayerRegions[] | undefined;
  if (job.kind === 'outlines' && job.hold) work.held.set(job.from, (kept = []));
  const run = new RegionsRun(work.meshes(), setup, job.layers, job.from, job.to);
  for (let i = job.from; i < job.to; i++) {
    const r = run.layer(i);
    if (job.kind === 'layers') paths.push(pathsOf(r, setup, job, custom, []));
    else if (job.kind === 'regions') regions.push(r);
    else {
      // the model paths made while the layer's regions are at hand, or the regions kept here for them
      if (!job.hold) paths.push(modelPathsOf(r, work, job.modelPaths));
      else kept!.push(r);
      outlines.push(outlinesOf(r));
    }
    run.release(i);
    yield;
  }
  if (job.kind === 'layers') return { paths };
  if (job.kind === 'regions') return { regions };
  return { outlines, paths };
}

/** Run a job to its end. */
export function computeRange<J extends RangeJob>(work: LayerWork, job: J): ResultOf<J> {
  const steps = rangeSteps(work, job);
  for (;;) {
    const s = steps.next();
    if (s.done) return s.value;
  }
}
