/**
 * The plan of a sequential print: every layer of the first object, then every layer of the next, and so on
 * (the order and the clearance checks: pipeline/sequential.ts). The layers are sliced once for the whole
 * plate as usual; here each layer's path groups are split by object and planned object by object.
 *
 * - Layers are numbered on through the whole print (as PrusaSlicer does): the plan's layer i is the i-th
 *   printed, and its Z goes down where a new object starts.
 * - Each object's first layer prints as a first layer (first-layer speeds, fan and nozzle temperature; its
 *   second layer sets the normal nozzle temperature again). The bed stays at its normal temperature once
 *   the first object's first layer is done, so the objects already on it stay put.
 * - The skirt or brim (one group round every object) prints once, with the first object's first layer.
 * - Support belongs to the object whose footprint it lies in (or nearest to).
 * - Between objects: a retracted travel at a safe Z (above everything printed so far, `liftZ`) to the next
 *   object's first point, then down to its first layer (TravelStep.liftTo; moves.ts walks it). After the last
 *   object the nozzle rises to that Z too (the end template's moves then clear every object).
 */
import { pointHullDistance } from '../geometry/hull-distance.js';
import { UM_PER_MM, type Pt } from '../geometry/types.js';
import type { LayerPaths, PathGroup } from '../paths/types.js';
import type { Config } from '../settings/resolve.js';
import { planLayer, type PlanState } from './layer-plan.js';
import type { LayerPlan, TravelStep } from './types.js';

/** The owner of groups printed with the first object: the skirt or brim round all of them. */
const SHARED = -1;

export interface SequentialInput {
  /** Every layer's paths, as sliced for the whole plate, bottom up. */
  paths: readonly LayerPaths[];
  /** Object indices in print order. */
  order: readonly number[];
  /** Each object's footprint (convex hull, mm), to give support to an object. */
  hulls: readonly (readonly [number, number][])[];
  /** The Z to travel at over objects printed up to `printedTop` (mm). */
  liftZ: (printedTop: number) => number;
}

/** A point of the group's paths (its first), or null when it has none. */
function firstPoint(group: PathGroup): Pt | null {
  for (const e of group.entries) for (const path of e.paths) if (path.length) return path[0];
  return null;
}

function ownerOf(group: PathGroup, hulls: SequentialInput['hulls']): number {
  if (group.object !== undefined) return group.object;
  if (group.kind === 'adhesion') return SHARED;
  // support: the object whose footprint it stands in, or the nearest
  const p = group.area?.outer[0] ?? firstPoint(group);
  if (!p) return SHARED;
  let best = 0,
    bestD = Infinity;
  for (let k = 0; k < hulls.length; k++) {
    const d = pointHullDistance([p.x / UM_PER_MM, p.y / UM_PER_MM], hulls[k]);
    if (d < bestD) (bestD = d), (best = k);
  }
  return best;
}

const hasPaths = (g: PathGroup) => g.entries.some((e) => e.paths.length > 0);

/** The layers of a sequential print, planned in print order (see the file comment). */
export function planSequential(input: SequentialInput, cfg: Config): LayerPlan[] {
  const { paths, order, hulls } = input;
  const owners = paths.map((lp) => lp.groups.map((g) => ownerOf(g, hulls)));
  const state: PlanState = { at: { x: 0, y: 0 } };
  const out: LayerPlan[] = [];
  let printedTop = 0;
  for (let k = 0; k < order.length; k++) {
    const object = order[k];
    let own = 0;
    for (let li = 0; li < paths.length; li++) {
      const lp = paths[li];
      const groups = lp.groups.filter(
        (g, gi) => hasPaths(g) && (owners[li][gi] === object || (k === 0 && owners[li][gi] === SHARED)),
      );
      if (groups.length === 0) continue;
      const first = own === 0;
      if (first) state.below = undefined;
      const layer = planLayer({ ...lp, groups }, cfg, state, out.length, first);
      // nothing long enough to print: the object's next layer is its first still
      if (!layer.steps.some((s) => s.kind === 'extrude')) continue;
      temperatures(layer, cfg, k, own);
      if (first && k > 0) liftOver(layer, input.liftZ(printedTop), cfg);
      out.push(layer);
      own++;
    }
    for (const l of out) if (l.z > printedTop) printedTop = l.z;
  }
  // at the end, up above every object, so the end template's moves (presenting the print) clear them
  const last = out[out.length - 1];
  if (last)
    last.steps.push({
      kind: 'travel',
      points: [state.at],
      retract: false,
      zHop: 0,
      speed: cfg.travelSpeed,
      liftTo: input.liftZ(printedTop),
    });
  return out;
}

/**
 * The layer's temperatures: each object's first layer at the first-layer nozzle temperature, its second
 * back to the normal one; the bed at its first-layer temperature for the first object's first layer only.
 */
function temperatures(layer: LayerPlan, cfg: Config, k: number, own: number): void {
  delete layer.nozzleTemperature;
  delete layer.bedTemperature;
  const nozzleDiffers = cfg.nozzleTemperature !== cfg.firstLayerNozzleTemperature;
  if (own === 0 && k > 0 && nozzleDiffers) layer.nozzleTemperature = cfg.firstLayerNozzleTemperature;
  if (own === 1 && nozzleDiffers) layer.nozzleTemperature = cfg.nozzleTemperature;
  if (own === 1 && k === 0 && cfg.heatedBed && cfg.bedTemperature !== cfg.firstLayerBedTemperature)
    layer.bedTemperature = cfg.bedTemperature;
}

/** Make the layer's first move the travel over the printed objects: retracted, at `z`, straight to its first point. */
function liftOver(layer: LayerPlan, z: number, cfg: Config): void {
  const s0 = layer.steps[0];
  const to = s0.kind === 'travel' ? s0.points[s0.points.length - 1] : s0.points[0];
  const travel: TravelStep = {
    kind: 'travel',
    points: [to],
    retract: true,
    zHop: 0,
    speed: cfg.travelSpeed,
    liftTo: z,
  };
  if (s0.kind === 'travel') layer.steps[0] = travel;
  else layer.steps.unshift(travel);
}
