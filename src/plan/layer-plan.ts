/**
 * Turns one layer's paths into ordered plan steps: islands nearest-first; in each island the walls
 * (inner-first or outer-first, seams placed), then sparse infill, then skin; travels combed inside
 * the island, retracted when they leave it or are long.
 */
import { UM_PER_MM, type Polygon, type Polyline, type Pt } from '../geometry/types.js';
import type { IslandPaths, LayerPaths } from '../paths/types.js';
import type { Config } from '../settings/resolve.js';
import { combRoute, makeCombArea, pathLength, type CombArea } from './comb.js';
import { orderNearest, orderPolylines } from '../geometry/nearest-order.js';
import { chooseSeam, rotateLoop } from './seam.js';
import type { ExtrudeStep, FeatureType, LayerPlan, PlanStep } from './types.js';

export interface PlanState {
  /** Nozzle position after the previous layer, µm. */
  at: Pt;
}

interface Ctx {
  cfg: Config;
  layer: LayerPaths;
  steps: PlanStep[];
  at: Pt;
  first: boolean;
  /** The next travel is the first of the layer (retract on layer change). */
  layerStart: boolean;
  width: number;
  loopNo: number;
  /** Comb area of the island being printed, or null between islands. */
  comb: CombArea | null;
}

function speedFor(cfg: Config, feature: FeatureType, first: boolean): number {
  if (first) return cfg.firstLayerSpeed;
  switch (feature) {
    case 'WALL-OUTER':
      return cfg.perimeterSpeed;
    case 'WALL-INNER':
      return cfg.innerWallSpeed;
    case 'SKIN':
      return cfg.skinSpeed;
    case 'FILL':
      return cfg.infillSpeed;
    default:
      return cfg.firstLayerSpeed;
  }
}

function travelTo(ctx: Ctx, to: Pt, forceRetract = false): void {
  const { cfg } = ctx;
  const from = ctx.at;
  if (ctx.layerStart) {
    ctx.layerStart = false;
    if (cfg.retractOnLayerChange) forceRetract = true;
  }
  if (from.x === to.x && from.y === to.y) return;
  const speed = ctx.first ? cfg.firstLayerTravelSpeed : cfg.travelSpeed;
  const minTravelUm = cfg.retractionMinTravel * UM_PER_MM;
  let points: Pt[] = [to];
  let leaves = true;
  if (ctx.comb && cfg.combing && !forceRetract) {
    const route = combRoute(from, to, ctx.comb);
    if (route) {
      points = route;
      leaves = false;
    }
  } else if (ctx.comb && !cfg.combing && !forceRetract) {
    // Without combing a travel stays inside the island only when the straight line does.
    const route = combRoute(from, to, ctx.comb);
    leaves = !(route && route.length === 1);
  }
  const length = pathLength(from, points);
  const retract = cfg.retractionEnabled && cfg.retractionDistance > 0 && (forceRetract || ((leaves || length > minTravelUm) && length > minTravelUm * 0.25));
  ctx.steps.push({ kind: 'travel', points, retract, zHop: retract ? cfg.zHop : 0, speed });
  ctx.at = to;
}

function extrude(ctx: Ctx, feature: FeatureType, points: Pt[], closed: boolean, width = ctx.width): void {
  if (points.length < 2) return;
  travelTo(ctx, points[0]);
  const step: ExtrudeStep = {
    kind: 'extrude',
    feature,
    points,
    closed,
    width,
    height: ctx.layer.height,
    speed: speedFor(ctx.cfg, feature, ctx.first),
    flow: 1,
  };
  ctx.steps.push(step);
  ctx.at = closed ? points[0] : points[points.length - 1];
}

/** Print a set of closed loops nearest-first, each starting at its seam. */
function printLoops(ctx: Ctx, feature: FeatureType, loops: readonly Polygon[]): void {
  if (loops.length === 0) return;
  const mode = ctx.cfg.seamPosition;
  // For ordering purposes a loop is entered at its seam (or, for 'nearest', at any vertex: use the first).
  const seams = loops.map((l, i) => (mode === 'nearest' ? -1 : chooseSeam(l, mode, ctx.at, ctx.cfg.randomSeed, ctx.layer.index, ctx.loopNo + i)));
  const order = orderNearest(
    loops.length,
    (i) => [seams[i] >= 0 ? loops[i][seams[i]] : loops[i][0]],
    (i) => (seams[i] >= 0 ? loops[i][seams[i]] : loops[i][0]),
    ctx.at,
  );
  for (const [i] of order) {
    const loop = loops[i];
    const s = seams[i] >= 0 ? seams[i] : chooseSeam(loop, 'nearest', ctx.at, 0, 0, 0);
    extrude(ctx, feature, rotateLoop(loop, s), true);
  }
  ctx.loopNo += loops.length;
}

function printLines(ctx: Ctx, feature: FeatureType, lines: readonly Polyline[]): void {
  for (const line of orderPolylines(lines, ctx.at)) extrude(ctx, feature, line, false);
}

function islandEntry(island: IslandPaths): Pt {
  const outer = island.walls[0]?.[0] ?? island.outline.outer;
  return outer[0];
}

function printIsland(ctx: Ctx, island: IslandPaths): void {
  const boundary = island.walls[0] && island.walls[0].length ? island.walls[0] : [island.outline.outer, ...island.outline.holes];
  ctx.comb = null; // arriving from elsewhere: the first travel leaves the previous island
  const walls = island.walls;
  const orderIdx = walls.map((_, k) => k);
  if (ctx.cfg.wallOrder === 'inner-first') orderIdx.reverse();
  for (const k of orderIdx) {
    printLoops(ctx, k === 0 ? 'WALL-OUTER' : 'WALL-INNER', walls[k]);
    // once the first loop is printed the nozzle is inside the island: later travels comb
    if (!ctx.comb && walls[k].length) ctx.comb = makeCombArea(island.outline, boundary);
  }
  if (!ctx.comb) ctx.comb = makeCombArea(island.outline, boundary);
  printGapLoops(ctx, 'WALL-INNER', island.gapFill);
  printLoops(ctx, 'FILL', island.infillLoops);
  printLines(ctx, 'FILL', island.infillLines);
  printLoops(ctx, 'SKIN', island.skinWalls);
  printLines(ctx, 'SKIN', island.skinLines);
  printGapLoops(ctx, 'SKIN', island.skinGaps);
}

/** Thin loops with their own bead width, nearest first. */
function printGapLoops(ctx: Ctx, feature: FeatureType, gaps: IslandPaths['gapFill']): void {
  for (const [i] of orderNearest(gaps.length, (i) => [gaps[i].loop[0]], (i) => gaps[i].loop[0], ctx.at)) {
    const g = gaps[i];
    extrude(ctx, feature, rotateLoop(g.loop, chooseSeam(g.loop, 'nearest', ctx.at, 0, 0, 0)), true, g.width);
  }
}

/** Build the plan of one layer, starting from where the nozzle is. */
export function planLayer(layer: LayerPaths, cfg: Config, state: PlanState): LayerPlan {
  const first = layer.index === 0;
  const ctx: Ctx = { cfg, layer, steps: [], at: state.at, first, layerStart: layer.index > 0, width: layer.lineWidth, loopNo: 0, comb: null };
  if (layer.adhesion.length) {
    const feature: FeatureType = layer.adhesionFeature;
    printLoops(ctx, feature, layer.adhesion);
  }
  const islands = layer.islands.filter((i) => i.walls.some((w) => w.length) || i.gapFill.length || i.infillLines.length || i.skinLines.length || i.infillLoops.length || i.skinWalls.length || i.skinGaps.length);
  const order = orderNearest(
    islands.length,
    (i) => [islandEntry(islands[i])],
    (i) => islandEntry(islands[i]),
    ctx.at,
  );
  // travels into another island are not combed (printIsland starts each island without a comb area)
  for (const [i] of order) printIsland(ctx, islands[i]);
  state.at = ctx.at;
  const plan: LayerPlan = {
    index: layer.index,
    z: layer.z,
    height: layer.height,
    fan: (first ? cfg.firstLayerFanSpeed : cfg.fanSpeed) / 100,
    steps: ctx.steps,
  };
  if (layer.index === 1) {
    if (cfg.nozzleTemperature !== cfg.firstLayerNozzleTemp) plan.nozzleTemperature = cfg.nozzleTemperature;
    if (cfg.heatedBed && cfg.bedTemperature !== cfg.firstLayerBedTemp) plan.bedTemperature = cfg.bedTemperature;
  }
  return plan;
}
