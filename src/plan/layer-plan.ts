/**
 * Turns one layer's path groups into ordered plan steps: groups by kind (adhesion, support, islands; see
 * print-order.ts), nearest-first within a kind; in each group its entries in print order (walls by the wall
 * order setting, seams placed; lines nearest-first); runs over air printed their own way (bridges, slowed
 * overhang walls). Travels are combed inside the group, retracted when they leave it or are long.
 */
import { UM_PER_MM, type ExPolygon, type Polygon, type Pt } from '../geometry/types.js';
import { pointInArea } from '../geometry/clip.js';
import { entryPoint, exitPoint, orderPaths, shortenOrder, type PathSet, type Visit } from '../order/index.js';
import type { LayerPaths, PathEntry, PathGroup } from '../paths/types.js';
import type { Config } from '../settings/resolve.js';
import { combRoute, insideRings, makeCombArea, pathLengthUm, type CombArea } from './comb.js';
import { flagStyle, GROUP_ORDER, overAirMatters, type EntryStyle, type ExtrusionStyle } from '../paths/roles.js';
import { sortEntries } from './print-order.js';
import { scarfRuns } from './scarf.js';
import { finishingTurn, openLoopNear, spiralTurn } from './spiral-vase.js';
import { chooseSeam, rotateLoop } from './seam.js';
import { PartGuard } from './support-travel.js';
import { printedIsland, RetractionWindow, routeOverIslands, type PrintedIsland } from './travel-rules.js';
import type { ExtrudeStep, LayerPlan, PlanStep } from './types.js';

export interface PlanState {
  /** Nozzle position after the previous layer, µm. */
  at: Pt;
  /** The part's islands on the previous layer (kept for support travels, see support-travel.ts). */
  below?: ExPolygon[];
  /** The previous layer's Z, mm (absent before the first layer). */
  z?: number;
  /**
   * After a spiral vase turn (spiral-vase.ts): the flat finishing turn that ends the spiral, and the steps of
   * the turn's layer it goes into, should the next layer not go on turning (endSpiral).
   */
  spiralEnd?: { finish: PlanStep[]; into: PlanStep[] };
  /** The retractions counted for retractionCountMax (travel-rules.ts), from layer to layer; made when first needed. */
  retractions?: RetractionWindow;
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
  /** The area inside the innermost wall of `comb` (PathGroup.inner), once made (undefined: not yet). */
  innerArea: CombArea | null | undefined;
  /** Kind of the group being printed, and of the group the last extrusion belonged to. */
  kind: PathGroup['kind'] | null;
  lastKind: PathGroup['kind'] | null;
  /** The part's islands of this layer and of the one below, and their guard, made when a support travel first asks. */
  islands: readonly ExPolygon[];
  below: readonly ExPolygon[];
  guard: PartGuard | null;
  object?: number;
  /** On the first layer: each entry style as the first layer prints it (every run at the first-layer speed). */
  firstStyles: Map<EntryStyle, EntryStyle>;
  /** The islands printed so far on this layer (zHopOnlyOverParts). */
  printed: PrintedIsland[];
  /** The area of the group being printed, and of the group of the last extrusion (the one a travel leaves). */
  groupArea: ExPolygon | null;
  leaving: ExPolygon | null;
  /** With retractionCountMax: the retractions counted and the filament extruded. */
  window: RetractionWindow | null;
}

/** One path as the planner prints it: its points and the channels that go with them. */
interface Run {
  points: Pt[];
  closed: boolean;
  /** Bead width, mm, where `widths` is null. */
  width: number;
  widths: Float64Array | null;
  z: Float64Array | null;
  flags: Uint8Array | null;
}

function travelTo(ctx: Ctx, to: Pt, forceRetract = false): void {
  const { cfg } = ctx;
  const from = ctx.at;
  if (ctx.layerStart) {
    ctx.layerStart = false;
    if (cfg.retractOnLayerChange) forceRetract = true;
  }
  const speed = ctx.first ? cfg.firstLayerTravelSpeed : cfg.travelSpeed;
  if (from.x === to.x && from.y === to.y) {
    // a layer that starts where the last one ended still retracts on the layer change when asked
    if (forceRetract && cfg.retractionEnabled && cfg.retractionDistance > 0) {
      ctx.window?.add();
      ctx.steps.push({
        kind: 'travel',
        points: [to],
        retract: true,
        zHop: cfg.zHopOnlyOverParts ? 0 : cfg.zHop,
        speed,
      });
    }
    return;
  }
  const minTravelUm = cfg.retractionMinTravel * UM_PER_MM;
  if (ctx.comb && !forceRetract && ctx.comb.inner && cfg.retractCrossingWallsOnly) {
    // inside the innermost wall: over the island's own skin and infill, crossing no wall
    const inner = (ctx.innerArea ??= makeCombArea(ctx.comb.area!, ctx.comb.inner));
    const route = travelInside(ctx, inner, from, to);
    if (route) {
      ctx.steps.push({ kind: 'travel', points: route, retract: false, zHop: 0, speed });
      ctx.at = to;
      return;
    }
  }
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
  const length = pathLengthUm(from, points);
  let retract =
    cfg.retractionEnabled &&
    cfg.retractionDistance > 0 &&
    (forceRetract || ((leaves || length > minTravelUm) && length > minTravelUm * 0.25));
  if (
    retract &&
    !forceRetract &&
    cfg.supportLimitRetractions &&
    ctx.kind === 'support' &&
    ctx.lastKind === 'support' &&
    points.length === 1
  ) {
    retract = !(ctx.guard ??= new PartGuard([ctx.islands, ctx.below])).clear(from, to);
  }
  // retractionCountMax: a travel that stays inside skips the retraction once the window is full
  if (retract && !forceRetract && !leaves && ctx.window?.full()) retract = false;
  if (retract) ctx.window?.add();
  let zHop = retract ? cfg.zHop : 0;
  if (zHop > 0 && cfg.zHopOnlyOverParts && !routeOverIslands(from, points, ctx.printed, ctx.leaving)) zHop = 0;
  ctx.steps.push({ kind: 'travel', points, retract, zHop, speed });
  ctx.at = to;
}

/** Filament of a run as the moves extrude it (mm; rectangular cross-section, moves.ts), for retractionCountMax. */
function runFilament(ctx: Ctx, run: Run, flow: number): number {
  const { points, widths } = run;
  const n = points.length;
  const edges = run.closed ? n : n - 1;
  let sum = 0;
  for (let i = 0; i < edges; i++) {
    const j = i + 1 === n ? 0 : i + 1;
    const length = Math.hypot(points[j].x - points[i].x, points[j].y - points[i].y) / UM_PER_MM;
    sum += length * (widths ? (widths[i]! + widths[j]!) / 2 : run.width);
  }
  const r = ctx.cfg.filamentDiameter / 2;
  return (sum * ctx.layer.height * flow * (ctx.cfg.flowRate / 100)) / (Math.PI * r * r);
}

/**
 * The route of a travel that stays inside the innermost wall (its ends inside or on it, combed round the
 * holes in it, or straight when combing is off and the straight line stays inside), no longer than
 * combingMaxDistance; null when there is none.
 */
function travelInside(ctx: Ctx, inner: CombArea, from: Pt, to: Pt): Pt[] | null {
  // a travel that starts where the innermost wall's loop ended is on it: half a line width of tolerance
  const tolerance = ctx.layer.lineWidthMm * UM_PER_MM * 0.5;
  if (!insideRings(from, inner, tolerance) || !insideRings(to, inner, tolerance)) return null;
  const route = combRoute(from, to, inner);
  if (!route || (!ctx.cfg.combing && route.length > 1)) return null;
  const limit = ctx.cfg.combingMaxDistance * UM_PER_MM;
  if (limit > 0 && pathLengthUm(from, route) > limit) return null;
  return route;
}

function extrude(ctx: Ctx, style: ExtrusionStyle, run: Run): void {
  const points = run.points;
  if (points.length < 2) return;
  travelTo(ctx, points[0]);
  const step: ExtrudeStep = {
    kind: 'extrude',
    feature: style.feature,
    points,
    closed: run.closed,
    width: run.width,
    // always present (undefined when unset), so every extrusion has one shape and the passes over the
    // plan read its steps through monomorphic property loads
    widths: run.widths ?? undefined,
    z: run.z ?? undefined,
    height: ctx.layer.height,
    speed: style.speed,
    flow: style.flow,
    object: ctx.object,
    fan: style.fan,
  };
  ctx.steps.push(step);
  if (ctx.window) ctx.window.extruded += runFilament(ctx, run, style.flow);
  ctx.leaving = ctx.groupArea;
  ctx.lastKind = ctx.kind;
  ctx.at = run.closed ? points[0] : points[points.length - 1];
}

/** The entry's style as this layer prints it: on the first layer every run at the first-layer speed, nothing over air. */
function layerStyle(ctx: Ctx, style: EntryStyle): EntryStyle {
  if (!ctx.first) return style;
  let s = ctx.firstStyles.get(style);
  if (!s) {
    const normal = { ...style.normal, speed: ctx.cfg.firstLayerSpeed };
    ctx.firstStyles.set(style, (s = { ...style, normal, overAir: normal }));
    delete s.levels;
  }
  return s;
}

/**
 * Extrude a path whose edges may be flagged as over air: runs of equal flags become steps of their own
 * (contiguous, so no travel between them).
 */
function extrudeFlagged(ctx: Ctx, style: EntryStyle, run: Run): void {
  const flags = run.flags;
  if (!flags || !overAirMatters(style)) return extrude(ctx, style.normal, run);
  const { points, widths, z } = run;
  const n = points.length;
  const edges = run.closed ? n : n - 1;
  let runStart = 0;
  let runStyle = flagStyle(style, flags[0]);
  for (let e = 1; e <= edges; e++) {
    // edges whose flags print alike (graded levels that share a style) are one run
    const next = e < edges ? flagStyle(style, flags[e]) : null;
    if (next === runStyle) continue;
    const count = e - runStart + 1;
    const part: Pt[] = new Array(count);
    for (let k = 0; k < count; k++) part[k] = points[(runStart + k) % n];
    extrude(ctx, runStyle, {
      points: part,
      closed: false,
      width: run.width,
      widths: widths && channelRun(widths, runStart, count),
      z: z && channelRun(z, runStart, count),
      flags: null,
    });
    runStart = e;
    if (next) runStyle = next;
  }
}

/** `count` values of a per-point channel from `start`, wrapping round a loop's end. */
function channelRun(values: Float64Array, start: number, count: number): Float64Array {
  const n = values.length;
  if (start + count <= n) return values.slice(start, start + count);
  const out = new Float64Array(count);
  for (let k = 0; k < count; k++) out[k] = values[(start + k) % n];
  return out;
}

/** A loop's channel turned to start at point `s`. */
function rotateChannel<T extends Float64Array | Uint8Array>(values: T | null, s: number): T | null {
  if (!values || s === 0) return values;
  const out = new (values.constructor as { new (n: number): T })(values.length);
  out.set(values.subarray(s), 0);
  out.set(values.subarray(0, s), values.length - s);
  return out;
}

/** A line's channel reversed (point channels, or edge flags). */
function reverseChannel<T extends Float64Array | Uint8Array>(values: T | null): T | null {
  return values ? (values.slice().reverse() as T) : null;
}

/** Per-point widths that are all one value are that one width. */
function runWidthMm(entry: PathEntry, i: number): { width: number; widths: Float64Array | null } {
  const widths = entry.widths?.[i] ?? null;
  if (!widths || widths.length === 0) return { width: entry.width, widths: null };
  const w0 = widths[0];
  for (let k = 1; k < widths.length; k++) if (widths[k] !== w0) return { width: w0, widths };
  return { width: w0, widths: null };
}

/** Loop i of the entry, started at point s. */
function loopRun(entry: PathEntry, i: number, s: number): Run {
  const { width, widths } = runWidthMm(entry, i);
  return {
    points: rotateLoop(entry.paths[i], s),
    closed: true,
    width,
    widths: rotateChannel(widths, s),
    z: rotateChannel(entry.z?.[i] ?? null, s),
    flags: rotateChannel(entry.overAir?.[i] ?? null, s),
  };
}

/** Line i of the entry, from its first point or (flip) its last. */
function lineRun(entry: PathEntry, i: number, flip: boolean): Run {
  const { width, widths } = runWidthMm(entry, i);
  const line = entry.paths[i];
  const z = entry.z?.[i] ?? null;
  const flags = entry.overAir?.[i] ?? null;
  if (!flip) return { points: line, closed: false, width, widths, z, flags };
  return {
    points: line.slice().reverse(),
    closed: false,
    width,
    widths: reverseChannel(widths),
    z: reverseChannel(z),
    flags: reverseChannel(flags),
  };
}

/**
 * Loop i of the entry from point s: on a scarf ramp where the entry's style asks for one (scarf.ts; never on
 * the object's first layer, which has nothing below to ramp from), else with a plain seam.
 */
function printLoop(ctx: Ctx, entry: PathEntry, style: EntryStyle, i: number, s: number): void {
  const run = loopRun(entry, i, s);
  const scarf = entry.style.scarf;
  const runs = scarf && !ctx.first && ctx.layer.index > 0 ? scarfRuns(run, scarf, ctx.layer.height) : null;
  if (!runs) return extrudeFlagged(ctx, style, run);
  for (const r of runs) extrudeFlagged(ctx, style, r);
}

/**
 * Entries printed as one tour (a block of the group): the fill inside the walls (see `mixable`), or one entry
 * of another role (a wall's loops, support lines), or an entry whose paths keep their given order
 * (PathEntry.ordered).
 */
interface Block {
  entries: readonly PathEntry[];
  /** Each entry's loops' seams (vertex), or -1 where the loop is entered at whichever vertex is nearest. */
  seams: Int32Array[];
  /** The block's paths, entry after entry: path n is entry items[n][0]'s path items[n][1]. */
  items: Array<[e: number, i: number]>;
  /** The paths as the ordering takes them: lines entered at either end, loops at their `candidates`. */
  paths: PathSet;
  /** The paths in print order, each entered at its candidate (see `candidates`). */
  visits: Visit[];
  /** Where the nearest-first visits were found from. */
  from: Pt | null;
  /** The paths keep the order the entry gives them (lines from their first point). */
  ordered: boolean;
  /**
   * The tour is shortened (fill inside the innermost wall, where a travel goes straight; not walls, whose
   * travels comb round holes the straight distance does not see).
   */
  shorten: boolean;
}

/** Vertices of a loop entered anywhere that the ordering considers (evenly spread; all of a small loop). */
const LOOP_ENTRIES = 16;

/** Where a block's path can be entered: a line at either end, a loop at its seam or (no seam) at some of its vertices. */
function candidates(block: Block, e: number, i: number): readonly Pt[] {
  const path = block.entries[e].paths[i];
  if (!block.entries[e].closed) return [path[0], path[path.length - 1]];
  const s = block.seams[e][i];
  return s >= 0 ? [path[s]] : spreadPoints(path, LOOP_ENTRIES);
}

/**
 * The group's entries as blocks: consecutive mixable entries one block (but skin lines a block after their
 * skin walls), every other entry a block of its own; each loop's seam chosen by the seam setting (nearest:
 * where the nozzle comes to it).
 */
function groupBlocks(ctx: Ctx, entries: readonly PathEntry[]): Block[] {
  const blocks: Block[] = [];
  for (let k = 0; k < entries.length; k++) {
    let last = k;
    let walled = entries[k].role === 'skin-wall';
    while (mixable(entries[k]) && last + 1 < entries.length && mixable(entries[last + 1])) {
      const next = entries[last + 1];
      // skin lines after their skin walls
      if (walled && next.role === 'skin' && next.paths.length > 0) break;
      if (next.role === 'skin-wall') walled = true;
      last++;
    }
    const members = entries.slice(k, last + 1).filter((e) => e.paths.length > 0);
    k = last;
    if (members.length === 0) continue;
    const seams = members.map((entry) => {
      const s = new Int32Array(entry.closed ? entry.paths.length : 0).fill(-1);
      const mode = entry.style.seam === 'nearest' ? 'nearest' : ctx.cfg.seamPosition;
      if (entry.closed && !entry.ordered && mode !== 'nearest')
        for (let i = 0; i < s.length; i++)
          s[i] = chooseSeam(entry.paths[i], mode, ctx.at, ctx.cfg.randomSeed, ctx.layer.index, ctx.loopNo + i);
      if (entry.closed && !entry.ordered) ctx.loopNo += s.length;
      return s;
    });
    const ordered = members.length === 1 && !!members[0].ordered;
    const items: Array<[number, number]> = [];
    for (let e = 0; e < members.length; e++) for (let i = 0; i < members[e].paths.length; i++) items.push([e, i]);
    const block: Block = {
      entries: members,
      seams,
      items,
      paths: {
        count: items.length,
        entries: (n) => candidates(block, items[n][0], items[n][1]),
        line: (n) => !members[items[n][0]].closed,
      },
      visits: [],
      from: null,
      ordered,
      shorten: !ordered && mixable(members[0]),
    };
    blocks.push(block);
  }
  return blocks;
}

/** A block's paths nearest-first from `from`: lines from whichever end is nearer, loops from their nearest candidate. */
function nearestVisits(block: Block, from: Pt): Visit[] {
  if (block.ordered) return block.items.map((_, n) => [n, 0]);
  return orderPaths(block.paths, { from });
}

/**
 * The order of a group's blocks' paths: nearest-first, block after block; then, block after block again, each
 * fill block nearest-first from where the block before it now ends, its tour shortened (order/shorten.ts) on
 * to where the block after it starts (after the last block: `to`, where the nozzle goes next), so that it also
 * ends near where the next begins.
 */
function orderBlocks(blocks: readonly Block[], from: Pt, to: Pt | null): void {
  let at = from;
  for (const b of blocks) {
    b.visits = nearestVisits(b, at);
    b.from = at;
    at = exitPoint(b.paths, b.visits[b.visits.length - 1]);
  }
  at = from;
  for (let k = 0; k < blocks.length; k++) {
    const b = blocks[k];
    const next = k + 1 < blocks.length ? entryPoint(blocks[k + 1].paths, blocks[k + 1].visits[0]) : to;
    if (b.from !== at) {
      b.visits = nearestVisits(b, at);
      b.from = at;
    }
    if (b.shorten) b.visits = shortenOrder(b.paths, b.visits, at, next);
    at = exitPoint(b.paths, b.visits[b.visits.length - 1]);
  }
}

/** A block's paths in their order: loops from their seam (or the vertex nearest the nozzle), lines from the end visited. */
function printBlock(ctx: Ctx, block: Block): void {
  for (const [n, c] of block.visits) {
    const [e, i] = block.items[n];
    const entry = block.entries[e];
    const style = layerStyle(ctx, entry.style);
    if (entry.closed) {
      const s = block.seams[e][i];
      const start = s >= 0 ? s : chooseSeam(entry.paths[i], 'nearest', ctx.at, 0, 0, 0);
      if (entry.ordered) extrudeFlagged(ctx, style, loopRun(entry, i, start));
      else printLoop(ctx, entry, style, i, start);
    } else extrudeFlagged(ctx, style, lineRun(entry, i, c !== 0));
  }
}

function comb(group: PathGroup): CombArea | null {
  if (!group.area) return null;
  const boundary: Polygon[] = group.boundary ?? [group.area.outer, ...group.area.holes];
  return makeCombArea(group.area, boundary);
}

/** Print a group, its last path ending near `next` (where the nozzle goes after it) when given. */
function printGroup(ctx: Ctx, group: PathGroup, next: Pt | null): void {
  ctx.comb = null; // arriving from elsewhere: the first travel leaves the previous group
  ctx.combArea = undefined;
  ctx.innerArea = undefined;
  ctx.kind = group.kind;
  ctx.object = group.object;
  ctx.groupArea = group.area ?? null;
  const blocks = groupBlocks(ctx, sortEntries(group.entries, ctx.cfg.wallOrder));
  orderBlocks(blocks, ctx.at, next);
  let combed = false;
  // without a retraction on the layer change, a layer that starts over the island the nozzle is already
  // above travels into it as within it (retracting only as such a travel would)
  if (
    ctx.layerStart &&
    !ctx.cfg.retractOnLayerChange &&
    group.kind === 'island' &&
    group.area &&
    pointInArea(ctx.at, group.area)
  ) {
    ctx.comb = group;
    combed = true;
  }
  for (const block of blocks) {
    // walls: once the first wall is printed the nozzle is inside the island, and later travels comb;
    // any other entry starts combed
    if (!combed && block.entries[0].role !== 'wall') {
      ctx.comb = group;
      combed = true;
    }
    printBlock(ctx, block);
    if (!combed) {
      ctx.comb = group;
      combed = true;
    }
  }
  if (ctx.cfg.zHopOnlyOverParts && group.kind === 'island' && group.area) ctx.printed.push(printedIsland(group.area));
  ctx.object = undefined;
}

/**
 * The fill inside the walls, printed as one tour: infill and skin lines in no fixed order, the skin's walls
 * (from their seams) and its gap fill loops (entered anywhere).
 */
function mixable(entry: PathEntry): boolean {
  return (
    !entry.ordered &&
    (((entry.role === 'skin' || entry.role === 'infill') && !entry.closed) ||
      (entry.role === 'skin-gap' && entry.closed && entry.style.seam === 'nearest') ||
      (entry.role === 'skin-wall' && entry.closed))
  );
}

/**
 * Where a group is entered, for ordering groups nearest-first: an island at its outer wall's seam (the
 * walls' seams lie together with an aligned or rear seam), or, where seams go to the nearest point, at
 * any of some of the outer wall's vertices.
 */
function groupEntries(group: PathGroup, cfg: Config, layer: number): readonly Pt[] {
  const outer = group.boundary?.[0];
  if (outer && outer.length >= 3) {
    if (cfg.seamPosition === 'aligned' || cfg.seamPosition === 'rear')
      return [outer[chooseSeam(outer, cfg.seamPosition, outer[0], cfg.randomSeed, layer, 0)]];
    if (cfg.seamPosition === 'nearest') return spreadPoints(outer, LOOP_ENTRIES);
  }
  return [groupEntry(group)];
}

/** Up to `most` of a loop's vertices, evenly spread (all of a small loop). */
function spreadPoints(loop: readonly Pt[], most: number): readonly Pt[] {
  if (loop.length <= most) return loop;
  const out: Pt[] = [];
  for (let k = 0; k < most; k++) out.push(loop[Math.floor((k * loop.length) / most)]);
  return out;
}

/** Where a group is entered when nothing better is known: the first point of its outer wall, area or paths. */
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

/** A spiral vase layer's one wall loop, when its only paths are one island's one closed wall loop. */
function spiralLoop(layer: LayerPaths): { group: PathGroup; entry: PathEntry } | null {
  let found: { group: PathGroup; entry: PathEntry } | null = null;
  for (const group of layer.groups) {
    for (const entry of group.entries) {
      if (entry.paths.length === 0) continue;
      if (
        found ||
        group.kind !== 'island' ||
        entry.role !== 'wall' ||
        !entry.closed ||
        entry.paths.length !== 1 ||
        entry.paths[0].length < 3
      )
        return null;
      found = { group, entry };
    }
  }
  return found;
}

/**
 * Print the layer's one wall loop as a spiral turn (spiral-vase.ts): on from the previous turn's end, or
 * (a first turn) from where the nozzle is, by the usual travel; then keep the finishing turn that ends the
 * spiral should the next layer not turn.
 */
function printTurn(ctx: Ctx, state: PlanState, group: PathGroup, entry: PathEntry, onFromTurn: boolean): PlanStep[] {
  ctx.kind = group.kind;
  ctx.object = group.object;
  const style = layerStyle(ctx, entry.style);
  const loop = loopRun(entry, 0, 0);
  const opened = openLoopNear(loop, ctx.at);
  // going on from a turn: no travel, so no retraction on the layer change either
  if (onFromTurn) ctx.layerStart = false;
  const turn = spiralTurn(opened, onFromTurn ? ctx.at : null, state.z! - ctx.layer.z, !onFromTurn);
  extrudeFlagged(ctx, style, turn);
  const finish: PlanStep[] = [];
  extrudeFlagged({ ...ctx, steps: finish }, style, finishingTurn(opened));
  ctx.object = undefined;
  return finish;
}

/**
 * End a spiral whose last turn was the previous layer: its flat finishing turn goes after that turn.
 * Called by planLayer when a layer does not go on turning, and once after the last layer.
 */
export function endSpiral(state: PlanState): void {
  if (state.spiralEnd) state.spiralEnd.into.push(...state.spiralEnd.finish);
  state.spiralEnd = undefined;
}

/**
 * Build the plan of one layer, starting from where the nozzle is.
 * @param position the layer's place in the print (0: the first layer, with first-layer speeds, fan and
 *   temperatures; the second sets the normal temperatures)
 * @param first the layer is printed on the bed as a first layer (first-layer speeds and fan, no retraction
 *   on the layer change): the print's first, or in sequential printing each object's first
 */
export function planLayer(
  layer: LayerPaths,
  cfg: Config,
  state: PlanState,
  position = layer.index,
  first = position === 0,
): LayerPlan {
  // the part's islands, here and on the layer below (support travels keep off them)
  const islands: ExPolygon[] = [];
  for (const g of layer.groups) if (g.kind === 'island' && g.area) islands.push(g.area);
  const ctx: Ctx = {
    cfg,
    layer,
    steps: [],
    at: state.at,
    first,
    layerStart: !first,
    loopNo: 0,
    comb: null,
    combArea: undefined,
    innerArea: undefined,
    kind: null,
    lastKind: null,
    islands,
    below: state.below ?? [],
    guard: null,
    firstStyles: new Map(),
    printed: [],
    groupArea: null,
    leaving: null,
    window:
      cfg.retractionCountMax > 0
        ? (state.retractions ??= new RetractionWindow(
            cfg.retractionCountMax,
            cfg.retractionExtrusionWindow ?? cfg.retractionDistance,
          ))
        : null,
  };
  // a spiral vase layer above the model's first, over a layer below it, turns when it is one loop
  const turn =
    layer.vase && layer.index > 0 && !first && state.z !== undefined && layer.z > state.z ? spiralLoop(layer) : null;
  const onFromTurn = !!turn && !!state.spiralEnd;
  if (!onFromTurn) endSpiral(state);
  state.spiralEnd = undefined;
  let finish: PlanStep[] | null = null;
  if (turn) finish = printTurn(ctx, state, turn.group, turn.entry, onFromTurn);
  else {
    for (const kind of GROUP_ORDER) {
      const groups = layer.groups.filter((g) => g.kind === kind && hasPaths(g));
      // travels into another group are not combed (printGroup starts each group without a comb area)
      const entries = groups.map((g) => groupEntries(g, cfg, position));
      const order = orderPaths(
        { count: groups.length, entries: (i) => entries[i], line: () => false },
        { from: ctx.at },
      );
      for (let k = 0; k < order.length; k++) {
        // each group ends near the next one's entry; the layer's last island near its own (the next layer's
        // walls start above it)
        const [g, c] = k + 1 < order.length ? order[k + 1] : order[k];
        printGroup(ctx, groups[order[k][0]], k + 1 < order.length || kind === 'island' ? entries[g][c] : null);
      }
    }
  }
  state.at = ctx.at;
  state.below = islands;
  state.z = layer.z;
  const plan: LayerPlan = {
    index: position,
    z: layer.z,
    height: layer.height,
    fan: (first ? cfg.firstLayerFanSpeed : cfg.fanSpeed) / 100,
    steps: ctx.steps,
  };
  if (finish) {
    plan.spiral = true;
    state.spiralEnd = { finish, into: plan.steps };
  }
  if (position === 1) {
    if (cfg.nozzleTemperature !== cfg.firstLayerNozzleTemperature) plan.nozzleTemperature = cfg.nozzleTemperature;
    if (cfg.heatedBed && cfg.bedTemperature !== cfg.firstLayerBedTemperature) plan.bedTemperature = cfg.bedTemperature;
  }
  return plan;
}
