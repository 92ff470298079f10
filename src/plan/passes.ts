/**
 * The passes over a finished print plan, in the order they run. Each pass reads and rewrites the plan
 * in place (speeds, steps, annotations); the estimate and the G-code writer come after all of them.
 * Adding a pass (arc fitting, progress, speed limits) is adding it to `PLAN_PASSES`.
 */
import type { Config } from '../settings/resolve.js';
import { fitPlanArcs } from './arc-fit.js';
import { applyLayerFans, applyMinLayerTime } from './cooling.js';
import type { PrintPlan } from './types.js';

export interface PlanPass {
  readonly name: string;
  run(plan: PrintPlan, cfg: Config): void;
}

/** The fan of each layer (by its place in its object and its time), then the minimum layer time: slow short layers down so the plastic below can cool. */
const cooling: PlanPass = {
  name: 'cooling',
  run(plan, cfg) {
    applyLayerFans(plan, cfg);
    for (const layer of plan.layers) applyMinLayerTime(layer, cfg.minLayerTime, cfg.minPrintSpeed);
  },
};

/**
 * Arc fitting (when `arcFitting` is on): runs of short segments on curves become arc segments. It runs
 * after every pass that reads or moves points, since the points it keeps are arc end points.
 */
const arcFitting: PlanPass = {
  name: 'arc fitting',
  run(plan, cfg) {
    if (cfg.arcFitting) fitPlanArcs(plan, cfg.arcTolerance);
  },
};

export const PLAN_PASSES: readonly PlanPass[] = [cooling, arcFitting];

/** Run every pass over the plan, in order. */
export function runPlanPasses(plan: PrintPlan, cfg: Config): void {
  for (const pass of PLAN_PASSES) pass.run(plan, cfg);
}
