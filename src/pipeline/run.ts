/**
 * The whole pipeline for placed objects:
 *   per-layer regions (worker pool) → whole-model passes (support, lightning, raft) → per-layer paths (pool)
 *   → plan (in layer order, as ranges arrive) → passes over the plan → estimate → G-code to a sink.
 * When no whole-model pass needs every layer's regions first, each range computes its regions and paths in
 * one go. The calling thread paces its own work (progress per layer, an abort acts within a time slice).
 */
import { StrataError } from '../errors.js';
import { UM_PER_MM, type ExPolygon, type Pt } from '../geometry/types.js';
import { writeGcodeSteps } from '../gcode/writer.js';
import { PATTERNS } from '../infill/registry.js';
import type { InfillParams, PatternId } from '../infill/types.js';
import { withSharedGroups } from '../paths/layer-paths.js';
import type { LayerPaths } from '../paths/types.js';
import { estimatePlanSteps } from '../plan/estimate.js';
import { endSpiral, planLayer, type PlanState } from '../plan/layer-plan.js';
import { runPlanPasses } from '../plan/passes.js';
import { planSequential } from '../plan/sequential-plan.js';
import type { LayerPlan, PlanEstimate, PrintPlan } from '../plan/types.js';
import { layerSparse, layerTopSkin } from '../regions/layer-regions.js';
import { raftUnder } from '../regions/raft.js';
import { objectsSupportPass } from '../support/index.js';
import type { LayerRegions } from '../regions/types.js';
import type { PrintSetup } from '../regions/objects.js';
import type { Config } from '../settings/resolve.js';
import { evenLayers, prepareMesh as prepareForSlicing, type PreparedMesh } from '../slice/index.js';
import { planPlateLayers } from '../slice/z-plan.js';
import type { LayerZ } from '../slice/types.js';
import { renderThumbnails } from '../thumbnail/index.js';
import { createPool, releaseWorkers, sharePrepared, type LayerPool } from '../workers/pool.js';
import type { Port } from '../workers/ports.js';
import {
  pathsContext,
  pathsOf,
  rangeSteps,
  type HeldJob,
  type PathsParams,
  type RangeJob,
  type RangeResult,
  type RegionsHeld,
  type RegionsJob,
} from './layer-work.js';
import type { CustomInfillSpec } from './custom-infill.js';
import { isTransferable, loadCustomInfill, loadedCustomInfill } from './custom-infill-loader.js';
import { planObjects } from './objects.js';
import type { PlacedObject, PlateSetup } from './print-setup.js';
import { Pacer, paced, wait, type Steps } from './pacer.js';
import { liftZ, sequenceObjects } from './sequential.js';
import { LENGTH_EPS_MM } from '../geometry/tolerances.js';

export type { PlacedObject, PlateSetup } from './print-setup.js';

export const VERSION = '0.1.0';

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
  /** Custom infill (shader or image) replacing the built-in pattern. */
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

export interface RunResult {
  plan: PrintPlan;
  estimate: PlanEstimate;
  layers: number;
  /** Layers with parts too thin for any wall line, which are left out: layer number, Z (mm) and area (mm²). */
  thinLost: ThinLoss[];
  /** Spiral vase layers above the first that are not one wall loop, printed flat: layer number and Z (mm). */
  vaseFlat: VaseFlat[];
  /** Area the first layer took from the layer above under an open or pointed bottom, mm² (0: none). */
  firstLayerFilledMm2: number;
  /** Spiral vase layers with specks beside their main island left out (vaseOutline): layer, Z (mm), area (mm²). */
  vaseSpecks: ThinLoss[];
}

/** A spiral vase layer printed flat. */
export interface VaseFlat {
  layer: number;
  z: number;
}

/** Area of one layer left out as too thin to print. */
export interface ThinLoss {
  layer: number;
  z: number;
  areaMm2: number;
}

function bedCentre(cfg: Config): Pt {
  return cfg.originAtCenter
    ? { x: 0, y: 0 }
    : { x: Math.round((cfg.buildPlateWidth / 2) * UM_PER_MM), y: Math.round((cfg.buildPlateLength / 2) * UM_PER_MM) };
}

/** Infill parameters of one object: its bounding-box centre is the pattern origin with object centering. */
function infillParamsFor(cfg: Config, object: PlacedObject): InfillParams {
  const p = object.mesh.positions;
  let x0 = Infinity,
    y0 = Infinity,
    x1 = -Infinity,
    y1 = -Infinity;
  const idx = object.mesh.indices;
  for (let i = 0; i < idx.length; i++) {
    const v = idx[i];
    const x = p[3 * v],
      y = p[3 * v + 1];
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
  }
  const objCentre: Pt = { x: Math.round(((x0 + x1) / 2) * UM_PER_MM), y: Math.round(((y0 + y1) / 2) * UM_PER_MM) };
  return {
    density: cfg.infillDensity / 100,
    lineWidth: Math.round(cfg.lineWidthMm * UM_PER_MM),
    nozzleDiameter: Math.round(cfg.nozzleDiameter * UM_PER_MM),
    angle: cfg.infillAngle,
    centering: cfg.infillPatternCentering,
    origin: cfg.infillPatternCentering === 'global' ? bedCentre(cfg) : objCentre,
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
    const a = Math.floor((k * n) / pieces),
      b = Math.floor(((k + 1) * n) / pieces);
    if (b > a) out.push([a, b]);
  }
  return out;
}

interface Runner {
  pool: LayerPool | null;
  /** The calling thread computes no range (they all go to the pool). */
  plansOnly: boolean;
  /** Computes a job on the calling thread, step by step (a pause after each layer). */
  local: (job: RangeJob) => Steps<RangeResult>;
  pacer: Pacer;
  signal?: AbortSignal;
}

/**
 * Run the jobs; `onResult` sees each result as it arrives (in any order with a pool), with where it was
 * computed (a worker's index, or -1 on this thread).
 */
function* runJobs(
  jobs: RangeJob[],
  runner: Runner,
  onResult: (id: number, r: RangeResult, where: number) => void,
): Steps<void> {
  const { pool, local, pacer } = runner;
  pacer.check();
  if (pool)
    return yield* wait(
      pool.run(jobs, {
        local: (job) => pacer.drive(local(job)),
        onResult,
        signal: runner.signal,
        helpAboveMs: runner.plansOnly ? Infinity : HELP_ABOVE_MS,
      }),
    );
  for (let id = 0; id < jobs.length; id++) onResult(id, yield* local(jobs[id]), -1);
}

/** The config of the first region whose pattern is a whole-model pass (lightning), if any. */
function wholeModelInfill(setup: PrintSetup, custom: CustomInfillSpec | undefined): Config | undefined {
  if (custom) return undefined;
  return setup.configs.find((c) => !!PATTERNS[c.infillPattern as PatternId].prepare && c.infillDensity > 0);
}

/** Whether some object gets support (on, or enforced by a volume). */
function anySupport(setup: PrintSetup): boolean {
  return setup.objects.some((o) => setup.configs[o.config].supportEnabled || o.enforcers.length > 0);
}

/**
 * Whether support under layer i touches it, a top Z gap of no layers (with uneven layers, a gap in mm less
 * than half the layer's height; layer -1: on any layer).
 */
function noTopGap(c: Config, layers: readonly LayerZ[], uneven: boolean, i: number): boolean {
  if (!uneven) return c.supportTopGapLayers === 0;
  if (c.supportZGap === null) return false;
  const half = (h: number) => h / 2 > c.supportZGap! + LENGTH_EPS_MM;
  return i >= 0 ? half(layers[i].height) : layers.some((l) => half(l.height));
}

/** Whether some object's skin rests on its support with no Z gap (its paths then wait for the support pass). */
function skinOnSupport(setup: PrintSetup, layers: readonly LayerZ[], uneven: boolean): boolean {
  return setup.objects.some((o) => {
    const c = setup.configs[o.config];
    return (c.supportEnabled || o.enforcers.length > 0) && noTopGap(c, layers, uneven, -1);
  });
}

/** Whether some whole-model pass needs the regions of every layer before any paths are made. */
function needsRegionsFirst(setup: PrintSetup, custom: CustomInfillSpec | undefined): boolean {
  return anySupport(setup) || setup.configs[0].adhesionType === 'raft' || !!wholeModelInfill(setup, custom);
}

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

/**
 * The pipeline as steps: a pause point after each piece of calling-thread work (layer, object, pass step),
 * and a promise where it waits (workers, the compiler); the driver resumes it with the promise's value.
 */
export function* runPipelineSteps(plate: PlateSetup, opts: RunOptions, pacer: Pacer): Steps<RunResult> {
  const { signal } = opts;
  const { setup, objects } = plate;
  const cfg = setup.configs[0];
  pacer.check();
  let height = 0;
  for (const o of objects) {
    const p = o.mesh.positions;
    for (let i = 2; i < p.length; i += 3) if (p[i] > height) height = p[i];
  }
  const layers: LayerZ[] = planPlateLayers(
    height,
    cfg,
    objects.map((o) => o.mesh),
    plate.heightRanges,
    plate.heightProfile,
  );
  if (layers.length === 0)
    throw new StrataError('EMPTY_MODEL', 'the model is thinner than the first layer: nothing to print');
  // sequential printing: the order, and the print head's clearances checked before anything is sliced
  const sequence = cfg.sequentialPrinting && objects.length > 1 ? sequenceObjects(objects, cfg) : null;
  const uneven = !evenLayers(layers, cfg.layerHeight);
  const infillParams = objects.map((o, k) => infillParamsFor(setup.configs[setup.objects[k].config], o));
  // N threads: the calling thread and N-1 workers, or for a custom infill N workers and the calling thread
  // only planning (see customInWorkers; split in two ranges at least, so progress is seen)
  // (a custom density given as a JS function cannot travel to a worker)
  const plansOnly = !!opts.customInWorkers && !!opts.custom && isTransferable(opts.custom);
  const split = ranges(layers.length, plansOnly ? Math.max(2, opts.threads) : opts.threads);
  const workers =
    opts.custom && !isTransferable(opts.custom)
      ? 0
      : plansOnly
        ? Math.min(Math.max(1, opts.threads), split.length)
        : Math.min(opts.threads, split.length) - 1;
  let meshes: PreparedMesh[] | null = null;
  // with workers, the calling thread uses the copy it shares with them
  const prepared = () =>
    (meshes ??= plate.meshes.map((m) => (workers > 0 ? sharePrepared(prepareForSlicing(m)) : prepareForSlicing(m))));
  // each object's mesh made ready for slicing, pausing between objects
  for (let k = 0; k < plate.meshes.length && workers === 0; k++) {
    meshes ??= [];
    meshes.push(prepareForSlicing(plate.meshes[k]));
    yield;
  }
  const pool = workers > 0 ? yield* wait(createPool(workers, prepared, setup, opts.custom, opts.started)) : null;
  if (!pool && opts.started) yield* wait(releaseWorkers(opts.started));
  const report = (stage: Progress['stage'], fraction: number) => opts.onProgress?.({ stage, fraction });
  try {
    const custom = opts.custom
      ? (loadedCustomInfill() ?? (yield* wait(loadCustomInfill()))).customGenerator(opts.custom, cfg)
      : undefined;
    const twoPhase = needsRegionsFirst(setup, opts.custom);
    // progress: the layer work is 80 % of the run (regions and paths halves when there are two phases)
    const total = layers.length * (twoPhase ? 2 : 1);
    let doneLayers = 0;
    const layerDone = (count: number) => {
      doneLayers += count;
      report('slicing', (0.8 * doneLayers) / total);
    };
    // regions this thread keeps for its own 'held' jobs
    const heldHere: RegionsHeld = new Map();
    const runner: Runner = {
      pool,
      plansOnly: plansOnly && pool !== null,
      pacer,
      signal,
      local: function* (job) {
        // a paths or held job reads its regions, not the meshes
        const steps = rangeSteps(
          job.kind === 'paths' || job.kind === 'held' ? [] : prepared(),
          setup,
          job,
          custom,
          heldHere,
        );
        for (;;) {
          const s = steps.next();
          if (s.done) return s.value;
          if (!pool) layerDone(1);
          yield;
        }
      },
    };
    const jobDone = (job: RangeJob) => {
      if (pool) layerDone(job.to - job.from);
    };
    const common: PathsParams = {
      infillParams,
      zOffset: 0,
      adhesion: cfg.adhesionType === 'skirt' || cfg.adhesionType === 'brim',
    };

    // Travel planning is sequential (each layer starts where the last one ended), so ranges are
    // planned in order as they arrive, while later ones are still being computed.
    const state: PlanState = { at: { x: 0, y: 0 } as Pt };
    const planned: LayerPlan[] = [];
    const thinLost: ThinLoss[] = [];
    const vaseFlat: VaseFlat[] = [];
    const vaseSpecks: ThinLoss[] = [];
    // sequential printing plans the layers object by object once every layer's paths are made
    const collected: LayerPaths[] = [];
    let firstLayerFilledMm2 = 0;
    const plan = (lp: LayerPaths) => {
      if (lp.firstLayerFilledMm2) firstLayerFilledMm2 += lp.firstLayerFilledMm2;
      if (lp.lostMm2)
        thinLost.push({ layer: sequence ? collected.length : planned.length, z: lp.z, areaMm2: lp.lostMm2 });
      if (lp.vaseDroppedMm2)
        vaseSpecks.push({ layer: sequence ? collected.length : planned.length, z: lp.z, areaMm2: lp.vaseDroppedMm2 });
      if (sequence) {
        collected.push(lp);
        return;
      }
      const layerPlan = planLayer(lp, cfg, state, planned.length);
      if (lp.vase && lp.index > 0 && !layerPlan.spiral) vaseFlat.push({ layer: planned.length, z: lp.z });
      planned.push(layerPlan);
    };
    let jobs: RangeJob[] = [];
    if (twoPhase) {
      const lightningCfg = wholeModelInfill(setup, opts.custom);
      const lightning = !!lightningCfg;
      // The model's own paths wait for no whole-model pass unless lightning infill or skin resting on
      // support (no top Z gap) reads them: then each range makes them with its regions, while both are at
      // hand (coming back to every layer's regions later costs ~10 % more), and only the skirt and
      // support join them after the support pass.
      const early = !lightning && !skinOnSupport(setup, layers, uneven);
      const modelPaths: PathsParams | undefined = early ? { ...common, zOffset: 0, adhesion: false } : undefined;
      // With workers and support, each range keeps its regions where they were made, and the workers make
      // their ranges' model paths while this thread runs the support pass (which they would wait for idle).
      const hold = !!modelPaths && !!pool && anySupport(setup);
      const regionJobs: RegionsJob[] = split.map(([from, to]) => ({
        kind: 'regions',
        layers,
        from,
        to,
        modelPaths: hold ? undefined : modelPaths,
        hold,
      }));
      const regionResults: RangeResult[] = [];
      const where: number[] = [];
      yield* runJobs(regionJobs, runner, (id, r, w) => {
        regionResults[id] = r;
        where[id] = w;
        jobDone(regionJobs[id]);
      });
      const regions = regionResults.flatMap((r) => r.regions);
      // every layer is sliced: the meshes' slicing structures go (the calling thread's copy; the pool's with it)
      meshes = null;
      report('support', 0.4);
      const heldJob = (id: number): HeldJob => ({
        kind: 'held',
        layers,
        from: regionJobs[id].from,
        to: regionJobs[id].to,
        modelPaths: modelPaths!,
      });
      const heldIds = hold ? regionJobs.map((_, id) => id).filter((id) => where[id] >= 0) : [];
      const heldPaths: LayerPaths[][] = [];
      const heldRun = heldIds.length
        ? pool!.run(heldIds.map(heldJob), {
            placement: heldIds.map((id) => where[id]),
            onResult: (k, r) => (heldPaths[heldIds[k]] = r.paths),
            signal,
          })
        : null;
      // its failure is met where it is awaited, after the support pass
      heldRun?.catch(() => {});
      yield* paced(
        objectsSupportPass(
          regions,
          setup.configs,
          setup.objects.map((o) => o.config),
        ),
      );
      if (hold) {
        // the model paths of the ranges this thread made, then the workers'
        for (let id = 0; id < regionJobs.length; id++)
          if (where[id] < 0) heldPaths[id] = (yield* runner.local(heldJob(id))).paths;
        yield* wait(heldRun!);
        for (let id = 0; id < regionJobs.length; id++) regionResults[id].paths = heldPaths[id];
      }
      let preparedInfill: unknown[] | undefined;
      if (lightningCfg) {
        // every region printed with the pattern, with the first such region's density
        const pattern = lightningCfg.infillPattern;
        const ofPattern =
          setup.configs.length === 1 ? undefined : (region: number) => setup.configs[region].infillPattern === pattern;
        const density = lightningCfg.infillDensity / 100;
        preparedInfill = PATTERNS[pattern as PatternId].prepare!(
          {
            layers: regions.map((r) => ({
              layerIndex: r.index,
              z: r.z,
              layerHeight: r.height,
              region: layerSparse(r, ofPattern),
            })),
            supportNeeded: regions.map((_, i) => (i + 1 < regions.length ? layerTopSkin(regions[i + 1]) : [])),
          },
          infillParams[0].density === density ? infillParams[0] : { ...infillParams[0], density },
        );
      }
      const raft = raftUnder(regions[0], cfg);
      common.zOffset = raft.zOffset;
      if (raft.layers.length) {
        const raftParams = { ...common, zOffset: 0, adhesion: false };
        for (const r of raft.layers) plan(pathsOf(r, setup, raftParams, custom, []));
      }
      if (early) {
        const model = regionResults.flatMap((r) => r.paths);
        for (let i = 0; i < regions.length; i++) {
          plan(withSharedGroups(model[i], regions[i], pathsContext(regions[i], setup, common, custom, [])));
          layerDone(1);
          yield;
        }
      } else {
        // the support of layer i − 1 where it holds layer i with no gap
        const supportOf = (r: LayerRegions | undefined, i: number): ExPolygon[] => {
          if (!r?.support) return [];
          const held = (o: number) => noTopGap(setup.configs[setup.objects[o].config], layers, uneven, i);
          if (!r.supports) return held(0) ? [...r.support.body, ...r.support.roof] : [];
          return r.supports.flatMap((a, o) => (a && held(o) ? [...a.body, ...a.roof] : []));
        };
        jobs = split.map(([from, to]) => ({
          kind: 'paths',
          layers,
          from,
          to,
          ...common,
          regions: regions.slice(from, to),
          supportBelow: regions.slice(from, to).map((_, k) => supportOf(regions[from + k - 1], from + k)),
          prepared: preparedInfill?.slice(from, to),
        }));
      }
    } else {
      jobs = split.map(([from, to]) => ({ kind: 'layers', layers, from, to, ...common }));
    }

    const arrived: Array<RangeResult | undefined> = new Array(jobs.length);
    let nextToPlan = 0;
    if (jobs.length) {
      yield* runJobs(jobs, runner, (id, r) => {
        jobDone(jobs[id]);
        arrived[id] = r;
        for (let ready = arrived[nextToPlan]; ready; ready = arrived[nextToPlan]) {
          arrived[nextToPlan++] = undefined;
          for (const lp of ready.paths) plan(lp);
        }
      });
    }
    // a spiral vase that turns up to the last layer ends with its finishing turn
    endSpiral(state);
    // the workers' memory and the meshes' slicing structures go back before the G-code is written
    meshes = null;
    if (pool) yield* wait(pool.close());
    if (sequence) {
      planned.push(
        ...planSequential(
          {
            paths: collected,
            order: sequence.order,
            hulls: sequence.hulls,
            liftZ: (top) => liftZ(top, cfg.buildVolumeHeight),
          },
          cfg,
        ),
      );
      collected.length = 0;
    }
    pacer.check();
    report('planning', 0.8);
    const printPlan: PrintPlan = { layers: planned, objects: planObjects(objects), bounds: planBounds(planned) };
    runPlanPasses(printPlan, cfg);
    pacer.check();
    const n = planned.length;
    let k = 0;
    const estimate = yield* paced(estimatePlanSteps(printPlan, cfg), () => report('planning', 0.8 + (0.1 * ++k) / n));
    k = 0;
    const thumbnails = renderThumbnails(
      objects.map((o) => o.mesh),
      cfg.thumbnails,
    );
    yield* paced(
      writeGcodeSteps(printPlan, cfg.settings, estimate, opts.sink, {
        generator: `Strata ${VERSION}`,
        thumbnails,
        printerId: cfg.printerId,
        filamentId: cfg.filamentId,
      }),
      () => report('writing', 0.9 + (0.1 * ++k) / n),
    );
    report('writing', 1);
    return { plan: printPlan, estimate, layers: planned.length, thinLost, vaseFlat, vaseSpecks, firstLayerFilledMm2 };
  } finally {
    if (pool) yield* wait(pool.close());
  }
}

function planBounds(layers: readonly LayerPlan[]): PrintPlan['bounds'] {
  let minX = Infinity,
    minY = Infinity,
    maxX = -Infinity,
    maxY = -Infinity,
    minZ = Infinity,
    maxZ = -Infinity;
  // indexed loops: this runs once, mostly before the engine optimises it, and a for-of there makes an
  // iterator result per point (4 MB a BridgeTest slice with tree support)
  for (let li = 0; li < layers.length; li++) {
    const l = layers[li];
    for (let si = 0; si < l.steps.length; si++) {
      const s = l.steps[si];
      if (s.kind !== 'extrude') continue;
      if (l.z < minZ) minZ = l.z;
      if (l.z > maxZ) maxZ = l.z;
      const pts = s.points;
      for (let k = 0; k < pts.length; k++) {
        const p = pts[k];
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
