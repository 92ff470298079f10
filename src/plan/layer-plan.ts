/**
 * Turns one layer's path groups into ordered plan steps: groups by kind (adhesion, support, islands; see
 * print-order.ts), nearest-first within a kind; in each group its entries in print order (walls by the wall
 * order setting, seams placed; lines nearest-first); runs over air printed their own way (bridges, slowed
 * overhang walls). Travels are combed inside the group, retracted when they leave it or are long.
 */
import { UM_PER_MM, type ExPolygon, type Polygon, type Pt } from '../geometry/types.js';
import { orderNearest } from '../geometry/nearest-order.js';
import type { LayerPaths, PathEntry, PathGroup } from '../paths/types.js';
import type { Config } from '../settings/resolve.js';
import { combRoute, makeCombArea, pathLength, type CombArea } from './comb.js';
import { GROUP_ORDER, OVER_AIR_STYLE, roleFeature, roleSpeed, sortEntries } from './print-order.js';
import { chooseSeam, rotateLoop } from './seam.js';
import { PartGuard } from './support-travel.js';
import type { ExtrudeStep, FeatureType, LayerPlan, PlanStep } from './types.js';

export interface PlanState {
  /** Nozzle position after the previous layer, µm. */
  at: Pt;
  /** The part's islands on the previous layer (kept for support travels, see support-travel.ts). */
  below?: ExPolygon[];
}

interface Ctx {
  cfg: Config;
  layer: LayerPaths;
  steps: PlanStep[];
  at: Pt;
  /** The plan's first layer (first-layer speeds). */
  first: boolean;
  /** The next travel is the first of the layer (retract on layer change). */
  layerStart: boolean;
  loopNo: number;
  /** The group being printed once the nozzle is inside it (its comb area made at its first travel), or null between groups. */
  comb: PathGroup | null;
  /** The comb area of `comb`, once made (undefined: not yet). */
  combArea: CombArea | null | undefined;
  /** Kind of the group being printed, and of the group the last extrusion belonged to. */
  kind: PathGroup['kind'] | null;
  lastKind: PathGroup['kind'] | null;
  /** The part's islands of this layer and of the one below, and their guard, made when a support travel first asks. */
  islands: readonly ExPolygon[];
  below: readonly ExPolygon[];
  guard: PartGuard | null;
  object?: number;
  /** Styles of the entries that set no speed or flow of their own, by role and wall (a layer's support has hundreds of groups). */
  styles: Map<string, { normal: Style; overAir: Style }>;
}

/** How one entry's extrusions print. */
interface Style {
  feature: FeatureType;
  speed: number;
  flow: number;
  fan?: number;
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
  const inside = ctx.comb && !forceRetract ? ctx.comb : null;
  // in a convex group the straight travel is the combed one, with or without combing
  const area = inside && !inside.convex ? (ctx.combArea ??= comb(inside)) : null;
  if (inside?.convex) leaves = false;
  else if (area && cfg.combing) {
    const route = combRoute(from, to, area);
    if (route) {
      points = route;
      leaves = false;
    }
  } else if (area) {
    // Without combing a travel stays inside the group only when the straight line does.
    const route = combRoute(from, to, area);
    leaves = !(route && route.length === 1);
  }
  const length = pathLength(from, points);
  let retract = cfg.retractionEnabled && cfg.retractionDistance > 0 && (forceRetract || ((leaves || length > minTravelUm) && length > minTravelUm * 0.25));
  if (retract && !forceRetract && cfg.supportLimitRetractions && ctx.kind === 'support' && ctx.lastKind === 'support' && points.length === 1) {
    retract = !(ctx.guard ??= new PartGuard([ctx.islands, ctx.below])).clear(from, to);
  }
  ctx.steps.push({ kind: 'travel', points, retract, zHop: retract ? cfg.zHop : 0, speed });
  ctx.at = to;
}

function extrude(ctx: Ctx, style: Style, points: Pt[], closed: boolean, width: number): void {
  if (points.length < 2) return;
  travelTo(ctx, points[0]);
  const step: ExtrudeStep = {
    kind: 'extrude',
    feature: style.feature,
    points,
    closed,
    width,
    height: ctx.layer.height,
    speed: style.speed,
    flow: style.flow,
    // always present (undefined when unset), so every extrusion has one shape and the passes over the
    // plan read its steps through monomorphic property loads
    object: ctx.object,
    fan: style.fan,
  };
  ctx.steps.push(step);
  ctx.lastKind = ctx.kind;
  ctx.at = closed ? points[0] : points[points.length - 1];
}

function styleOf(ctx: Ctx, entry: PathEntry): { normal: Style; overAir: Style } {
  if (entry.speed !== undefined || entry.flow !== undefined) return makeStyle(ctx, entry);
  const key = entry.wall === undefined ? entry.role : entry.role + entry.wall;
  let s = ctx.styles.get(key);
  if (!s) ctx.styles.set(key, (s = makeStyle(ctx, entry)));
  return s;
}

function makeStyle(ctx: Ctx, entry: PathEntry): { normal: Style; overAir: Style } {
  const { cfg } = ctx;
  const feature = roleFeature(entry);
  const speed = ctx.first ? cfg.firstLayerSpeed : entry.speed ?? roleSpeed(entry, cfg);
  const normal: Style = { feature, speed, flow: entry.flow ?? 1 };
  const air = OVER_AIR_STYLE[entry.role];
  if (!air || ctx.first) return { normal, overAir: normal };
  const airSpeed = air.speed(cfg);
  const overAir: Style = {
    feature: air.feature ?? feature,
    // a run that keeps its feature is only ever slowed down
    speed: air.feature ? airSpeed : Math.min(speed, airSpeed),
    flow: air.flow ? air.flow(cfg) : normal.flow,
  };
  if (air.fan) overAir.fan = air.fan(cfg);
  const same = overAir.feature === normal.feature && overAir.speed === normal.speed && overAir.flow === normal.flow && overAir.fan === undefined;
  return { normal, overAir: same ? normal : overAir };
}

/**
 * Extrude a path whose edges may be flagged as over air: runs of equal flags become steps of their own
 * (contiguous, so no travel between them).
 */
function extrudeFlagged(ctx: Ctx, styles: { normal: Style; overAir: Style }, points: Pt[], closed: boolean, width: number, flags: Uint8Array | null): void {
  if (!flags || (styles.overAir === styles.normal)) return extrude(ctx, styles.normal, points, closed, width);
  const n = points.length;
  const edges = closed ? n : n - 1;
  let runStart = 0;
  for (let e = 1; e <= edges; e++) {
    if (e < edges && flags[e] === flags[runStart]) continue;
    const run: Pt[] = [];
    for (let k = runStart; k <= e; k++) run.push(points[k % n]);
    extrude(ctx, flags[runStart] ? styles.overAir : styles.normal, run, false, width);
    runStart = e;
  }
}

function widthOf(entry: PathEntry, k: number): number {
  return typeof entry.width === 'number' ? entry.width : entry.width[k];
}

/** Closed loops nearest-first, each starting at its seam (walls and most loops) or wherever is nearest (gap loops). */
function printLoops(ctx: Ctx, entry: PathEntry, styles: { normal: Style; overAir: Style }): void {
  const loops = entry.paths;
  if (loops.length === 0) return;
  if (typeof entry.width !== 'number') {
    // gap loops with their own widths: nearest first, entered at their nearest point
    const order = orderNearest(loops.length, (i) => [loops[i][0]], (i) => loops[i][0], ctx.at);
    for (let k = 0; k < order.length; k++) {
      const i = order[k][0];
      const s = chooseSeam(loops[i], 'nearest', ctx.at, 0, 0, 0);
      extrudeFlagged(ctx, styles, rotateLoop(loops[i], s), true, widthOf(entry, i), rotateFlags(entry.overAir?.[i] ?? null, s));
    }
    return;
  }
  // support's loops have no seam to hide: each starts where the nozzle is nearest
  const mode = entry.role === 'support' || entry.role === 'support-roof' || entry.role === 'support-floor' ? 'nearest' : ctx.cfg.seamPosition;
  if (loops.length === 1) {
    // one loop (a tree branch's wall, most of a layer's support): no order to find
    const loop = loops[0];
    const s = mode === 'nearest' ? chooseSeam(loop, 'nearest', ctx.at, 0, 0, 0) : chooseSeam(loop, mode, ctx.at, ctx.cfg.randomSeed, ctx.layer.index, ctx.loopNo);
    extrudeFlagged(ctx, styles, rotateLoop(loop, s), true, entry.width, rotateFlags(entry.overAir?.[0] ?? null, s));
    ctx.loopNo += 1;
    return;
  }
  // For ordering purposes a loop is entered at its seam (or, for 'nearest', at any vertex: use the first).
  const seams = loops.map((l, i) => (mode === 'nearest' ? -1 : chooseSeam(l, mode, ctx.at, ctx.cfg.randomSeed, ctx.layer.index, ctx.loopNo + i)));
  const order = orderNearest(
    loops.length,
    (i) => [seams[i] >= 0 ? loops[i][seams[i]] : loops[i][0]],
    (i) => (seams[i] >= 0 ? loops[i][seams[i]] : loops[i][0]),
    ctx.at,
  );
  for (let k = 0; k < order.length; k++) {
    const i = order[k][0];
    const loop = loops[i];
    const s = seams[i] >= 0 ? seams[i] : chooseSeam(loop, 'nearest', ctx.at, 0, 0, 0);
    extrudeFlagged(ctx, styles, rotateLoop(loop, s), true, entry.width, rotateFlags(entry.overAir?.[i] ?? null, s));
  }
  ctx.loopNo += loops.length;
}

function rotateFlags(flags: Uint8Array | null, start: number): Uint8Array | null {
  if (!flags || start === 0) return flags;
  const out = new Uint8Array(flags.length);
  out.set(flags.subarray(start), 0);
  out.set(flags.subarray(0, start), flags.length - start);
  return out;
}

/** Open lines nearest-first, each from whichever end is nearer. */
function printLines(ctx: Ctx, entry: PathEntry, styles: { normal: Style; overAir: Style }): void {
  const lines = entry.paths;
  if (lines.length === 1) {
    // one line (a tree branch's chord): from its nearer end, the first on a tie
    const line = lines[0];
    const a = line[0], b = line[line.length - 1];
    const ax = a.x - ctx.at.x, ay = a.y - ctx.at.y, bx = b.x - ctx.at.x, by = b.y - ctx.at.y;
    const flip = bx * bx + by * by < ax * ax + ay * ay;
    const flags = entry.overAir?.[0] ?? null;
    extrudeFlagged(ctx, styles, flip ? line.slice().reverse() : line, false, widthOf(entry, 0), flags && flip ? flags.slice().reverse() : flags);
    return;
  }
  const order = orderNearest(
    lines.length,
    (i) => [lines[i][0], lines[i][lines[i].length - 1]],
    (i, s) => (s === 0 ? lines[i][lines[i].length - 1] : lines[i][0]),
    ctx.at,
  );
  for (let k = 0; k < order.length; k++) {
    const i = order[k][0], s = order[k][1];
    const flags = entry.overAir?.[i] ?? null;
    const pts = s === 0 ? lines[i] : lines[i].slice().reverse();
    extrudeFlagged(ctx, styles, pts, false, widthOf(entry, i), flags && s !== 0 ? flags.slice().reverse() : flags);
  }
}

function comb(group: PathGroup): CombArea | null {
  if (!group.area) return null;
  const boundary: Polygon[] = group.boundary ?? [group.area.outer, ...group.area.holes];
  return makeCombArea(group.area, boundary);
}

function printGroup(ctx: Ctx, group: PathGroup): void {
  ctx.comb = null; // arriving from elsewhere: the first travel leaves the previous group
  ctx.combArea = undefined;
  ctx.kind = group.kind;
  ctx.object = group.object;
  const entries = sortEntries(group.entries, ctx.cfg.wallOrder);
  let combed = false;
  for (const entry of entries) {
    // walls: once the first wall is printed the nozzle is inside the island, and later travels comb;
    // any other entry starts combed
    if (!combed && entry.role !== 'wall') {
      ctx.comb = group;
      combed = true;
    }
    const styles = styleOf(ctx, entry);
    if (entry.closed) printLoops(ctx, entry, styles);
    else printLines(ctx, entry, styles);
    if (!combed && entry.paths.length) {
      ctx.comb = group;
      combed = true;
    }
  }
  ctx.object = undefined;
}

/** Where a group is entered, for ordering groups nearest-first. */
function groupEntry(group: PathGroup): Pt {
  const outer = group.boundary?.[0];
  if (outer && outer.length) return outer[0];
  if (group.area) return group.area.outer[0];
  for (const e of group.entries) if (e.paths.length && e.paths[0].length) return e.paths[0][0];
  return { x: 0, y: 0 };
}

function hasPaths(group: PathGroup): boolean {
  return group.entries.some((e) => e.paths.length > 0);
}

/**
 * Build the plan of one layer, starting from where the nozzle is.
 * @param position the layer's place in the print (0: the first layer, with first-layer speeds, fan and
 *   temperatures; the second sets the normal temperatures)
 */
export function planLayer(layer: LayerPaths, cfg: Config, state: PlanState, position = layer.index): LayerPlan {
  const first = position === 0;
  // the part's islands, here and on the layer below (support travels keep off them)
  const islands: ExPolygon[] = [];
  for (const g of layer.groups) if (g.kind === 'island' && g.area) islands.push(g.area);
  const ctx: Ctx = {
    cfg, layer, steps: [], at: state.at, first, layerStart: !first, loopNo: 0, comb: null, combArea: undefined,
    kind: null, lastKind: null, islands, below: state.below ?? [], guard: null, styles: new Map(),
  };
  for (const kind of GROUP_ORDER) {
    const groups = layer.groups.filter((g) => g.kind === kind && hasPaths(g));
    // travels into another group are not combed (printGroup starts each group without a comb area)
    const order = orderNearest(groups.length, (i) => [groupEntry(groups[i])], (i) => groupEntry(groups[i]), ctx.at);
    for (let k = 0; k < order.length; k++) printGroup(ctx, groups[order[k][0]]);
  }
  state.at = ctx.at;
  state.below = islands;
  const plan: LayerPlan = {
    index: position,
    z: layer.z,
    height: layer.height,
    fan: (first ? cfg.firstLayerFanSpeed : cfg.fanSpeed) / 100,
    steps: ctx.steps,
  };
  if (position === 1) {
    if (cfg.nozzleTemperature !== cfg.firstLayerNozzleTemp) plan.nozzleTemperature = cfg.nozzleTemperature;
    if (cfg.heatedBed && cfg.bedTemperature !== cfg.firstLayerBedTemp) plan.bedTemperature = cfg.bedTemperature;
  }
  return plan;
}
