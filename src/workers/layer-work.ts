/**
 * The per-layer work of the pipeline, as jobs over ranges of layers that run the same on the calling thread
 * or in a worker (it lives here, with the workers, so that the pipeline reads the workers and not back):
 * - 'regions': slice the objects and compute every layer's regions (for the whole-model passes), and with
 *   `modelPaths` each layer's model paths too, when they do not wait for those passes (support alone);
 * - 'paths': turn regions (after support, lightning and raft passes) into path groups;
 * - 'held': the model paths of a range whose 'regions' job (with `hold`) left its regions on the same thread,
 *   so that they are made while the calling thread runs the support pass;
 * - 'layers': both at once, when no whole-model pass needs the regions of every layer first.
 * This file only orchestrates: the regions stage is in regions/, the paths stage in paths/. Each job is a
 * generator that yields after every layer, so the calling thread can report progress and stay responsive.
 */
import type { ExPolygon } from '../geometry/types.js';
import type { InfillParams, InfillPattern } from '../infill/types.js';
import { layerPaths, modelPaths, type LayerPathsContext } from '../paths/layer-paths.js';
import type { LayerPaths } from '../paths/types.js';
import { RegionsRun } from '../regions/layer-regions.js';
import { outlinesOnly, type LayerRegions } from '../regions/types.js';
import type { PrintSetup } from '../regions/objects.js';
import type { PreparedMesh } from '../slice/index.js';
import type { LayerZ } from '../slice/types.js';

interface JobBase {
  layers: readonly LayerZ[];
  from: number;
  to: number;
}

export interface RegionsJob extends JobBase {
  kind: 'regions';
  /** Also make each layer's model paths (without support and skirt, which follow the support pass). */
  modelPaths?: PathsParams;
  /** Keep each layer's regions on this thread for a later 'held' job of the same range (outlines are returned). */
  hold?: boolean;
}

/** The model paths of the regions a 'regions' job with `hold` kept on this thread. */
export interface HeldJob extends JobBase {
  kind: 'held';
  modelPaths: PathsParams;
}

/** Regions kept by 'regions' jobs with `hold`, by the first layer of their range. */
export type RegionsHeld = Map<number, LayerRegions[]>;

/** What the paths stage needs besides the regions. */
export interface PathsParams {
  /** Infill parameters per object (with the object's config; a region's config changes density and angle). */
  infillParams: InfillParams[];
  /** Added to every model layer's Z (the raft), mm. */
  zOffset: number;
  /** Whether the model's first layer gets the skirt or brim (no raft under it). */
  adhesion: boolean;
}

export interface PathsJob extends JobBase, PathsParams {
  kind: 'paths';
  /** Regions of layers [from, to). */
  regions: LayerRegions[];
  /** Per layer of the range: support areas of the layer below, µm. */
  supportBelow: ExPolygon[][];
  /** Per layer of the range: the pattern's whole-model data (lightning). */
  prepared?: unknown[];
}

export interface LayersJob extends JobBase, PathsParams {
  kind: 'layers';
}

export type RangeJob = RegionsJob | PathsJob | LayersJob | HeldJob;

export interface RangeResult {
  /** For 'regions' jobs. */
  regions: LayerRegions[];
  /** For 'paths', 'layers' and 'held' jobs, and 'regions' jobs with `modelPaths`. */
  paths: LayerPaths[];
}

/** What the paths stage of one layer is given. */
export function pathsContext(
  regions: LayerRegions,
  setup: PrintSetup,
  job: PathsParams,
  custom: InfillPattern | undefined,
  supportBelow: ExPolygon[],
  prepared?: unknown,
): LayerPathsContext {
  return {
    cfg: setup.configs[0],
    configs: setup.configs,
    objectConfigs: setup.objects.map((o) => o.config),
    params: job.infillParams,
    prepared,
    custom,
    supportBelow,
    zOffset: job.zOffset,
    adhesion: job.adhesion && regions.index === 0,
  };
}

/** The paths of one layer from its regions. */
export function pathsOf(
  regions: LayerRegions,
  setup: PrintSetup,
  job: PathsParams,
  custom: InfillPattern | undefined,
  supportBelow: ExPolygon[],
  prepared?: unknown,
): LayerPaths {
  return layerPaths(regions, pathsContext(regions, setup, job, custom, supportBelow, prepared));
}

/** Run a job, yielding after each layer; returns its result. `held` keeps the thread's held regions. */
export function* rangeSteps(
  meshes: readonly PreparedMesh[],
  setup: PrintSetup,
  job: RangeJob,
  custom?: InfillPattern,
  held?: RegionsHeld,
): Generator<void, RangeResult> {
  const regions: LayerRegions[] = [];
  const paths: LayerPaths[] = [];
  if (job.kind === 'held') {
    const kept = held?.get(job.from);
    if (!kept || kept.length !== job.to - job.from) throw new Error(`no regions held for layers ${job.from}-${job.to}`);
    held!.delete(job.from);
    for (let k = 0; k < kept.length; k++) {
      paths.push(modelPaths(kept[k], pathsContext(kept[k], setup, job.modelPaths, custom, [])));
      yield;
    }
    return { regions, paths };
  }
  if (job.kind === 'paths') {
    for (let k = 0; k < job.regions.length; k++) {
      paths.push(pathsOf(job.regions[k], setup, job, custom, job.supportBelow[k] ?? [], job.prepared?.[k]));
      yield;
    }
    return { regions, paths };
  }
  const run = new RegionsRun(meshes, setup, job.layers, job.from, job.to);
  for (let i = job.from; i < job.to; i++) {
    const r = run.layer(i);
    if (job.kind === 'regions') {
      if (job.hold) {
        if (!held) throw new Error('a regions job that holds its regions needs somewhere to keep them');
        let kept = held.get(job.from);
        if (!kept) held.set(job.from, (kept = []));
        kept.push(r);
        regions.push(outlinesOnly(r));
      } else if (job.modelPaths) {
        // made while the layer's regions are at hand, after which only the outlines are kept
        paths.push(modelPaths(r, pathsContext(r, setup, job.modelPaths, custom, [])));
        regions.push(outlinesOnly(r));
      } else regions.push(r);
    } else paths.push(pathsOf(r, setup, job, custom, []));
    run.release(i);
    yield;
  }
  return { regions, paths };
}

/** Run a job to its end. */
export function computeRange(
  meshes: readonly PreparedMesh[],
  setup: PrintSetup,
  job: RangeJob,
  custom?: InfillPattern,
  held?: RegionsHeld,
): RangeResult {
  const steps = rangeSteps(meshes, setup, job, custom, held);
  for (;;) {
    const s = steps.next();
    if (s.done) return s.value;
  }
}
