/**
 * The whole pipeline for a placed mesh: layer plan, per-layer work (inline or on a worker pool),
 * the whole-model infill pass where a pattern needs one, adhesion, travel planning, cooling,
 * estimates and G-code written to a sink.
 */
import { StrataError } from '../errors.js';
import { UM_PER_MM, type Pt } from '../geometry/types.js';
import { writeGcode } from '../gcode/writer.js';
import { PATTERNS } from '../infill/registry.js';
import type { InfillParams, PatternId } from '../infill/types.js';
import type { Mesh } from '../mesh/types.js';
import type { LayerPaths } from '../paths/types.js';
import { estimatePlan } from '../plan/estimate.js';
import { planLayer } from '../plan/layer-plan.js';
import { runPlanPasses } from '../plan/passes.js';
import type { LayerPlan, PlanEstimate, PrintPlan } from '../plan/types.js';
import { adhesionLoops } from '../regions/adhesion.js';
import type { Config } from '../settings/resolve.js';
import { planLayers, prepareMesh as prepareForSlicing, type PreparedMesh } from '../slice/index.js';
import type { LayerZ } from '../slice/types.js';
import { renderThumbnails } from '../thumbnail/index.js';
import { createPool, releaseWorkers, sharePrepared, type LayerPool } from '../workers/pool.js';
import type { Port } from '../workers/ports.js';
import { computeRange, lineWidthUm, type RangeJob, type RangeResult } from './layer-work.js';
import { customGenerator, isTransferable, type CustomInfillSpec } from './custom-infill.js';

export const VERSION = '0.1.0';

export interface Progress {
  stage: 'slicing' | 'planning' | 'writing';
  /** 0..1 over the whole run. */
  fraction: number;
}

export interface RunOptions {
  /** Worker threads; 1 runs inline. */
  threads: number;
  onProgress?: (p: Progress) => void;
  signal?: AbortSignal;
  /** Receives the G-code in chunks. */
  sink: (chunk: string) => void;
  /** Centre of the model's bounding box on the bed, mm (object centering origin). */
  objectCenter: [number, number];
  /** Model height, mm. */
  height: number;
  /** Custom infill (shader or image) replacing the built-in pattern. */
  custom?: CustomInfillSpec;
  /** Workers started early (`startWorkers`); used, or ended, here. */
  started?: Promise<Port[]>;
}

export interface RunResult {
  plan: PrintPlan;
  estimate: PlanEstimate;
  layers: number;
}

function checkAbort(signal?: AbortSignal): void {
  if (signal?.aborted) throw new StrataError('CANCELLED', 'slicing was cancelled');
}

function infillParamsFor(cfg: Config, objectCenter: [number, number]): InfillParams {
  const bedCentre: Pt = cfg.originAtCenter
    ? { x: 0, y: 0 }
    : { x: Math.round((cfg.buildPlateWidth / 2) * UM_PER_MM), y: Math.round((cfg.buildPlateLength / 2) * UM_PER_MM) };
  const objCentre: Pt = { x: Math.round(objectCenter[0] * UM_PER_MM), y: Math.round(objectCenter[1] * UM_PER_MM) };
  return {
    density: cfg.infillDensity / 100,
    lineWidth: Math.round(cfg.lineWidthMm * UM_PER_MM),
    nozzleDiameter: Math.round(cfg.nozzleDiameter * UM_PER_MM),
    angle: cfg.infillAngle,
    centering: cfg.infillPatternCentering,
    origin: cfg.infillPatternCentering === 'global' ? bedCentre : objCentre,
    connect: cfg.infillConnect,
  };
}

/**
 * With workers, the calling thread plans the ranges as they arrive, and computes ranges too only when
 * the work left would keep the workers busy longer than this (ms). Its first range is slow (cold code),
 * and compiling that code costs about a second of CPU, which competes with the workers when no core is
 * spare: on two cores, two threads computing a Benchy were slower than one.
 */
const HELP_ABOVE_MS = 2000;

/** Split [0, n) into ranges: several per thread for balance, each a few layers at least. */
function ranges(n: number, threads: number): Array<[number, number]> {
  if (threads <= 1) return [[0, n]];
  const pieces = Math.min(n, threads * 4);
  const out: Array<[number, number]> = [];
  for (let k = 0; k < pieces; k++) {
    const a = Math.floor((k * n) / pieces), b = Math.floor(((k + 1) * n) / pieces);
    if (b > a) out.push([a, b]);
  }
  return out;
}

interface JobRunner {
  pool: LayerPool | null;
  /** Computes a job on the calling thread. */
  local: (job: RangeJob) => RangeResult;
  signal?: AbortSignal;
}

/** Run the jobs; `onResult` sees each result as it arrives (in any order with a pool). */
async function runJobs(jobs: RangeJob[], runner: JobRunner, onResult: (id: number, r: RangeResult) => void): Promise<void> {
  const { pool, local, signal } = runner;
  if (pool) return pool.run(jobs, { local, onResult, signal, helpAboveMs: HELP_ABOVE_MS });
  for (let id = 0; id < jobs.length; id++) {
    checkAbort(signal);
    onResult(id, local(jobs[id]));
    // let the event loop breathe (progress, cancellation)
    await new Promise((r) => setTimeout(r, 0));
  }
}

export async function runPipeline(mesh: Mesh, cfg: Config, opts: RunOptions): Promise<RunResult> {
  const { signal } = opts;
  checkAbort(signal);
  const layers: LayerZ[] = planLayers(opts.height, cfg.firstLayerHeight, cfg.layerHeight);
  if (layers.length === 0) throw new StrataError('EMPTY_MODEL', 'the model is thinner than the first layer: nothing to print');
  const params = infillParamsFor(cfg, opts.objectCenter);
  const pattern = PATTERNS[cfg.infillPattern as PatternId];
  const split = ranges(layers.length, opts.threads);
  // N threads: the calling thread and N-1 workers
  // (a custom density given as a JS function cannot travel to a worker)
  const workers = opts.custom && !isTransferable(opts.custom) ? 0 : Math.min(opts.threads, split.length) - 1;
  let sliceable: PreparedMesh | null = null;
  // with workers, the calling thread uses the copy it shares with them
  const local = () => (sliceable ??= workers > 0 ? sharePrepared(prepareForSlicing(mesh)) : prepareForSlicing(mesh));
  const pool = workers > 0 ? await createPool(workers, local, cfg, opts.custom, opts.started) : null;
  if (!pool && opts.started) await releaseWorkers(opts.started);
  const report = (stage: Progress['stage'], fraction: number) => opts.onProgress?.({ stage, fraction });
  try {
    let prepared: unknown[] | undefined;
    const custom = opts.custom ? customGenerator(opts.custom, cfg) : undefined;
    const runner: JobRunner = { pool, local: (j) => computeRange(local(), cfg, j, custom), signal };
    const passes = pattern.prepare && !custom && cfg.infillDensity > 0 ? 2 : 1;
    let doneLayers = 0;
    const total = layers.length * passes;
    const onDone = (j: RangeJob) => {
      doneLayers += j.to - j.from;
      report('slicing', (0.8 * doneLayers) / total);
    };
    if (passes === 2 && pattern.prepare) {
      const regionJobs = split.map(([from, to]) => ({ layers, from, to, regionsOnly: true, infillParams: params }));
      const regionResults: RangeResult[] = [];
      await runJobs(regionJobs, runner, (id, r) => {
        regionResults[id] = r;
        onDone(regionJobs[id]);
      });
      const regions = regionResults.flatMap((r) => r.regions);
      prepared = pattern.prepare(
        {
          layers: regions.map((r) => ({ layerIndex: r.index, z: layers[r.index].z, layerHeight: layers[r.index].height, region: r.infill })),
          supportNeeded: regions.map((_, i) => (i + 1 < regions.length ? regions[i + 1].topSkin : [])),
        },
        params,
      );
    }
    const jobs = split.map(([from, to]) => ({ layers, from, to, regionsOnly: false, infillParams: params, prepared }));

    // Travel planning is sequential (each layer starts where the last one ended), so ranges are
    // planned in order as they arrive, while later ones are still being computed.
    const state = { at: { x: 0, y: 0 } as Pt };
    const planned: LayerPlan[] = [];
    const arrived: Array<RangeResult | undefined> = new Array(jobs.length);
    let nextToPlan = 0;
    const onResult = (id: number, r: RangeResult) => {
      onDone(jobs[id]);
      arrived[id] = r;
      for (let ready = arrived[nextToPlan]; ready; ready = arrived[nextToPlan]) {
        arrived[nextToPlan++] = undefined;
        for (const lp of ready.paths) {
          if (planned.length === 0) addAdhesion(lp, cfg);
          planned.push(planLayer(lp, cfg, state));
        }
      }
    };
    await runJobs(jobs, runner, onResult);
    // the workers' memory goes back before the G-code is written
    await pool?.close();
    checkAbort(signal);
    report('planning', 0.8);
    const plan: PrintPlan = { layers: planned, objects: [], bounds: planBounds(planned) };
    runPlanPasses(plan, cfg);
    checkAbort(signal);
    const estimate = estimatePlan(plan, cfg);
    report('writing', 0.9);
    const thumbnails = renderThumbnails(mesh, cfg.thumbnails);
    writeGcode(plan, cfg, estimate, opts.sink, { generator: `Strata ${VERSION}`, thumbnails });
    report('writing', 1);
    return { plan, estimate, layers: planned.length };
  } finally {
    await pool?.close();
  }
}

/** Skirt or brim around the first layer. */
function addAdhesion(first: LayerPaths, cfg: Config): void {
  first.adhesion = adhesionLoops(
    first.islands.map((i) => i.outline),
    cfg,
    lineWidthUm(cfg, 0),
  );
  first.adhesionFeature = cfg.adhesionType === 'brim' ? 'BRIM' : 'SKIRT';
}

function planBounds(layers: readonly LayerPlan[]): PrintPlan['bounds'] {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity, minZ = Infinity, maxZ = -Infinity;
  for (const l of layers) {
    for (const s of l.steps) {
      if (s.kind !== 'extrude') continue;
      if (l.z < minZ) minZ = l.z;
      if (l.z > maxZ) maxZ = l.z;
      for (const p of s.points) {
        if (p.x < minX) minX = p.x;
        if (p.y < minY) minY = p.y;
        if (p.x > maxX) maxX = p.x;
        if (p.y > maxY) maxY = p.y;
      }
    }
  }
  if (minX === Infinity) return { minX: 0, minY: 0, minZ: 0, maxX: 0, maxY: 0, maxZ: 0 };
  return { minX: minX / UM_PER_MM, minY: minY / UM_PER_MM, minZ, maxX: maxX / UM_PER_MM, maxY: maxY / UM_PER_MM, maxZ };
}
