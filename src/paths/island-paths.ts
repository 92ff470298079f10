/**
 * The paths of one island, from its regions: walls and wall gap fill as the regions stage found them, skin
 * walls and skin lines or loops by the skin patterns in the areas the regions stage lays out for them
 * (regions/skin-layout.ts; bridge direction where the skin lies over air), skin gap fill, sparse infill from
 * the pattern, and ironing over the top surfaces. Walls over air and skin over air are flagged so the planner
 * slows them / prints them as bridges. Nothing here computes areas: it turns them into lines.
 */
import { UM_PER_MM, type ExPolygon, type Polyline, type Pt } from '../geometry/types.js';
import { generateInfill, regionPattern } from '../infill/index.js';
import { SKIN_PATTERNS } from '../infill/skin-patterns.js';
import type { InfillParams, InfillPattern, PatternId } from '../infill/types.js';
import { skinGapFill } from '../regions/skin-gaps.js';
import { skinLayout, type BridgeLayout, type SkinLayout } from '../regions/skin-layout.js';
import { gapLoopWidthsMm, type GapLoop } from '../regions/gap-loops.js';
import type { IslandRegions, RegionFill, WallSet } from '../regions/types.js';
import type { Config } from '../settings/resolve.js';
import type { LayerZ } from '../slice/types.js';
import { makeEntry } from './entry.js';
import { solidFill } from '../infill/solid-fill.js';
import { overAirMatters } from './roles.js';
import { ironingEntry } from './ironing-paths.js';
import { fuzzyWalls } from './fuzzy-skin.js';
import type { PathEntry, PathGroup } from './types.js';

export interface IslandContext {
  /** Every config of the print (the island's walls read `configs[island.region]`, each fill its own). */
  configs: readonly Config[];
  layer: LayerZ;
  /** Line width of the layer, µm. */
  widthUm: number;
  /** The object's infill parameters (a region's config changes their density, angle and linking). */
  params: InfillParams;
  /** The pattern's whole-model data for this layer (lightning), if any. */
  prepared?: Polyline[];
  /** The slice's custom infill, which fills every region in place of its pattern. */
  custom?: InfillPattern;
  /** Area of the layer below that support holds up (its bottom skin there is not a bridge), µm. */
  supportBelow: readonly ExPolygon[];
}

/** What one region of an island prints with: its config and infill parameters. */
interface FillContext extends IslandContext {
  cfg: Config;
}

/** The skin of one region of an island, as bridge, skin-wall, skin and skin-gap entries, in its layout's areas. */
function skinEntries(island: RegionFill, ctx: FillContext, layout: SkinLayout): PathEntry[] {
  const { cfg, widthUm: w, layer } = ctx;
  const out: PathEntry[] = layout.bridge ? bridgeEntries(layout.bridge, ctx) : [];
  // lines, loops or both, by the region's top and bottom skin patterns
  const angle = skinAngleOf(island, cfg, layer.index);
  const fills = layout.parts.map((p) => SKIN_PATTERNS[p.pattern].fill(p.area, angle, w, ctx.params.origin));
  const lines = fills.length === 1 ? fills[0].lines : fills.flatMap((f) => f.lines);
  const loops = fills.flatMap((f) => f.loops);
  const skinWalls = layout.walls;
  const gaps = skinGapFill(layout.exposed, loops.length ? skinWalls.concat(loops) : skinWalls, lines, w);
  const air = layout.overAir.length ? layout.overAir : null;
  if (skinWalls.length) out.push(makeEntry(cfg, 'skin-wall', true, skinWalls, w / UM_PER_MM, { overAir: air }));
  for (const f of fills) {
    for (const [closed, paths] of [
      [false, f.lines],
      [true, f.loops],
    ] as const) {
      if (paths.length === 0) continue;
      const e = makeEntry(cfg, 'skin', closed, paths, w / UM_PER_MM, { overAir: air });
      if (f.ordered) e.ordered = true;
      out.push(e);
    }
  }
  if (gaps.length) out.push(gapEntry(cfg, 'skin-gap', gaps));
  return out;
}

/** Bridge lines this close to their area's edge, µm, are laid just inside it. */
const BRIDGE_EDGE_UM = 5;
/** A bridge's lines turn by up to this much, degrees, to run parallel to a long side of their piece. */
const BRIDGE_SNAP_DEG = 5;

/**
 * The direction of a bridge piece's lines: the bridge's, or the direction of the piece's longest side within
 * BRIDGE_SNAP_DEG of it, so that lines beside a straight wall run along it and are not cut into pieces by it.
 */
function pieceAngle(piece: ExPolygon, angle: number, minLengthUm: number): number {
  let best = angle,
    bestLength = minLengthUm;
  const ring = piece.outer;
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
    const dx = ring[i].x - ring[j].x,
      dy = ring[i].y - ring[j].y;
    const length = Math.hypot(dx, dy);
    if (length <= bestLength) continue;
    const dir = (Math.atan2(dy, dx) * 180) / Math.PI;
    const turn = ((((dir - angle) % 180) + 270) % 180) - 90;
    if (Math.abs(turn) <= BRIDGE_SNAP_DEG) {
      best = angle + turn;
      bestLength = length;
    }
  }
  return best;
}

/**
 * The bridge lines of a region: straight lines in the bridge direction across each piece of the anchored bridge
 * (the area of its beads' centres), spread evenly from one side of the piece to the other at most bridgeSpacing
 * apart (so no strip is left between the last line and the walls), each a round bead of the nozzle's diameter at
 * bridgeFlow (the entry's width is that bead's cross-section over the layer height), every run printed as bridge.
 */
function bridgeEntries(bridge: BridgeLayout, ctx: FillContext): PathEntry[] {
  const { cfg, layer } = ctx;
  const spacing = bridge.spacingUm;
  const lines: Pt[][] = [];
  for (const piece of bridge.centres) {
    const angle = pieceAngle(piece, bridge.angle, 4 * spacing);
    const a = (angle * Math.PI) / 180;
    const c = Math.cos(a),
      sn = Math.sin(a);
    let lo = Infinity,
      hi = -Infinity;
    for (const p of piece.outer) {
      const v = -p.x * sn + p.y * c;
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
    const width = hi - lo - 2 * BRIDGE_EDGE_UM;
    // n lines from one side to the other, at most `spacing` apart (one line down the middle of a narrow piece)
    const n = width > 0 ? Math.ceil(width / spacing) + 1 : 1;
    const step = n > 1 ? width / (n - 1) : spacing;
    const first = n > 1 ? lo + BRIDGE_EDGE_UM : (lo + hi) / 2;
    const origin = { x: -first * sn, y: first * c };
    for (const l of solidFill([piece], angle, step, origin)) lines.push(l);
  }
  if (lines.length === 0) return [];
  // E follows width × layer height × flow: the width that gives the round bead's cross-section at this height
  const bead = (Math.PI / 4) * cfg.nozzleDiameter * cfg.nozzleDiameter;
  const e = makeEntry(cfg, 'skin', false, lines, bead / layer.height);
  if (overAirMatters(e.style)) e.overAir = lines.map((l) => new Uint8Array(l.length - 1).fill(1));
  return [e];
}

/** Direction of a region's skin lines on a layer: across its bridge where it has one, else by the skin angle. */
function skinAngleOf(fill: RegionFill, cfg: Config, layerIndex: number): number {
  return fill.bridgeAngle ?? cfg.skinAngle + (layerIndex % 2 === 1 ? 90 : 0);
}

/** Gap loops with their own widths, as one entry of per-path widths. */
function gapEntry(cfg: Config, role: 'skin-gap', gaps: readonly GapLoop[]): PathEntry {
  const widths = gapLoopWidthsMm(gaps);
  return makeEntry(
    cfg,
    role,
    true,
    gaps.map((g) => g.loop),
    widths[0][0],
    { widths },
  );
}

function infillEntries(island: RegionFill, ctx: FillContext): PathEntry[] {
  if (island.sparse.length === 0) return [];
  const { cfg, layer, widthUm } = ctx;
  const input = { layerIndex: layer.index, zMm: layer.z, layerHeightMm: layer.height, region: island.sparse };
  const params = { ...ctx.params, lineWidthUm: widthUm };
  const res = generateInfill(regionPattern(cfg.infillPattern as PatternId, ctx.custom), input, params, ctx.prepared);
  const out: PathEntry[] = [];
  const width = widthUm / UM_PER_MM;
  if (res.loops.length) out.push(makeEntry(cfg, 'infill', true, res.loops, width));
  if (res.lines.length) out.push(makeEntry(cfg, 'infill', false, res.lines, width));
  return out;
}

/** The infill parameters of a region: the object's, with the region's density, angle and linking. */
function regionParams(params: InfillParams, cfg: Config): InfillParams {
  const density = cfg.infillDensity / 100;
  if (params.density === density && params.angle === cfg.infillAngle && params.connect === cfg.infillConnect)
    return params;
  return { ...params, density, angle: cfg.infillAngle, connect: cfg.infillConnect };
}

/** The infill and skin entries of one region of an island. */
function fillEntries(fill: RegionFill, ctx: IslandContext): PathEntry[] {
  const cfg = ctx.configs[fill.region];
  const fctx: FillContext = { ...ctx, cfg, params: regionParams(ctx.params, cfg) };
  const entries = infillEntries(fill, fctx);
  entries.push(...skinEntries(fill, fctx, skinLayout(fill, cfg, ctx.widthUm, ctx.supportBelow)));
  const iron = ironingEntry(fill, cfg, skinAngleOf(fill, cfg, ctx.layer.index), fctx.params.origin);
  if (iron) entries.push(iron);
  return entries;
}

/** The closed loops of the island's innermost wall, or null when it has no closed wall. */
function innermostLoops(walls: readonly WallSet[]): Pt[][] | null {
  let deepest = -1;
  for (const set of walls)
    if (set.role === 'wall' && set.closed && set.paths.length > 0 && set.wall > deepest) deepest = set.wall;
  if (deepest < 0) return null;
  const loops: Pt[][] = [];
  for (const set of walls)
    if (set.role === 'wall' && set.closed && set.wall === deepest) for (const p of set.paths) loops.push(p);
  return loops;
}

/** The island's group of entries (unsorted: the planner puts them in print order). */
export function islandGroup(island: IslandRegions, ctx: IslandContext): PathGroup {
  const cfg = ctx.configs[island.region];
  const w = ctx.widthUm / UM_PER_MM;
  const entries: PathEntry[] = [];
  const wallsOverAir = island.unsupported.length ? island.unsupported : null;
  for (const set of island.walls) {
    if (set.paths.length === 0) continue;
    // the outer wall made rough where fuzzy skin is on (fuzzy-skin.ts), its widths with it
    const { paths, widths } = fuzzyWalls(set, cfg, ctx.layer.index);
    const isWall = set.role === 'wall';
    const opts = {
      wall: isWall ? set.wall : undefined,
      widths: widths ?? undefined,
      overAir: isWall ? wallsOverAir : null,
      overhangLevels: isWall ? island.overhangLevels : null,
    };
    entries.push(makeEntry(cfg, set.role, set.closed, paths, w, opts));
  }
  // extra walls over overhangs: a ring an entry, in the order they were made (the planner keeps it)
  for (const ring of island.extraWalls ?? []) {
    entries.push(
      makeEntry(cfg, 'extra-wall', false, ring.paths, w, {
        widths: ring.widths ?? undefined,
        overAir: wallsOverAir,
        overhangLevels: island.overhangLevels,
      }),
    );
  }
  entries.push(...fillEntries(island, ctx));
  if (island.fills) for (const f of island.fills) entries.push(...fillEntries(f, ctx));
  // travel follows the outer wall's loops round the island
  const outer = island.walls.find((set) => set.role === 'wall' && set.wall === 0 && set.closed && set.paths.length > 0);
  const boundary = outer?.paths;
  const group: PathGroup = { kind: 'island', object: island.object, area: island.outline, entries };
  if (boundary) group.boundary = boundary;
  const inner = innermostLoops(island.walls);
  if (inner) group.inner = inner;
  return group;
}
