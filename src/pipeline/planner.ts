/**
 * The calling thread's share of a slice after the layer work: plan each layer's travel as its paths arrive, in
 * layer order (each layer starts where the last one ended), noting what was left out or printed flat; then
 * finish: the sequential order, the passes over the plan, the estimate and the G-code, to the sink.
 */
import { UM_PER_MM, type Pt } from '../geometry/types.js';
import { writeGcodeSteps } from '../gcode/writer.js';
import type { LayerPaths } from '../paths/types.js';
import { estimatePlanSteps } from '../plan/estimate.js';
import { endSpiral, planLayer, type PlanState } from '../plan/layer-plan.js';
import { runPlanPasses } from '../plan/passes.js';
import { planSequential } from '../plan/sequential-plan.js';
import type { LayerPlan, PlanEstimate, PrintPlan } from '../plan/types.js';
import { renderThumbnails } from '../thumbnail/index.js';
import { planObjects } from './objects.js';
import { paced, type Steps } from './pacer.js';
import type { PlacedObject } from './print-setup.js';
import { liftZ } from './sequential.js';
import type { SliceSetup } from './slice-setup.js';

export const VERSION = '0.1.0';

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

export interface Planned {
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

/** Plans layers in the order they are given (raft first, then the model bottom up). */
export class Planner {
  readonly #s: SliceSetup;
  readonly #state: PlanState = { at: { x: 0, y: 0 } as Pt };
  readonly #planned: LayerPlan[] = [];
  /** Sequential printing plans the layers object by object once every layer's paths are made. */
  readonly #collected: LayerPaths[] = [];
  readonly thinLost: ThinLoss[] = [];
  readonly vaseFlat: VaseFlat[] = [];
  readonly vaseSpecks: ThinLoss[] = [];
  firstLayerFilledMm2 = 0;

  constructor(s: SliceSetup) {
    this.#s = s;
  }

  /** Plan the next layer. */
  plan(lp: LayerPaths): void {
    const { cfg, sequence } = this.#s;
    const index = sequence ? this.#collected.length : this.#planned.length;
    if (lp.firstLayerFilledMm2) this.firstLayerFilledMm2 += lp.firstLayerFilledMm2;
    if (lp.lostMm2) this.thinLost.push({ layer: index, z: lp.z, areaMm2: lp.lostMm2 });
    if (lp.vaseDroppedMm2) this.vaseSpecks.push({ layer: index, z: lp.z, areaMm2: lp.vaseDroppedMm2 });
    if (sequence) {
      this.#collected.push(lp);
      return;
    }
    const layerPlan = planLayer(lp, cfg, this.#state, this.#planned.length);
    if (lp.vase && lp.index > 0 && !layerPlan.spiral) this.vaseFlat.push({ layer: this.#planned.length, z: lp.z });
    this.#planned.push(layerPlan);
  }

  /** Every layer is planned: a spiral vase that turns up to the last layer ends with its finishing turn. */
  end(): void {
    endSpiral(this.#state);
  }

  /**
   * The print's plan: with sequential printing, the layers object by object; then the passes over the plan.
   * `progress` hears each layer estimated and written (`done` of `total`).
   */
  *finish(
    objects: readonly PlacedObject[],
    sink: (chunk: string) => void,
    progress: (stage: 'estimate' | 'write' | 'written', done: number, total: number) => void,
  ): Steps<Planned> {
    const { cfg, sequence } = this.#s;
    const planned = this.#planned;
    if (sequence) {
      planned.push(
        ...planSequential(
          {
            paths: this.#collected,
            order: sequence.order,
            hulls: sequence.hulls,
            liftZ: (top) => liftZ(top, cfg.buildVolumeHeight),
          },
          cfg,
        ),
      );
      this.#collected.length = 0;
    }
    yield;
    const n = planned.length;
    progress('estimate', 0, n);
    const printPlan: PrintPlan = { layers: planned, objects: planObjects(objects), bounds: planBounds(planned) };
    runPlanPasses(printPlan, cfg);
    yield;
    let k = 0;
    const estimate = yield* paced(estimatePlanSteps(printPlan, cfg), () => progress('estimate', ++k, n));
    k = 0;
    const thumbnails = renderThumbnails(
      objects.map((o) => o.mesh),
      cfg.thumbnails,
    );
    yield* paced(
      writeGcodeSteps(printPlan, cfg.settings, estimate, sink, {
        generator: `Strata ${VERSION}`,
        thumbnails,
        printerId: cfg.printerId,
        filamentId: cfg.filamentId,
      }),
      () => progress('write', ++k, n),
    );
    progress('written', n, n);
    return {
      plan: printPlan,
      estimate,
      layers: planned.length,
      thinLost: this.thinLost,
      vaseFlat: this.vaseFlat,
      vaseSpecks: this.vaseSpecks,
      firstLayerFilledMm2: this.firstLayerFilledMm2,
    };
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
