/**
 * The paths of one island, from its regions: walls and wall gap fill as the regions stage found them, skin
 * walls and skin lines (bridge direction where the skin lies over air), skin gap fill, and sparse infill from
 * the pattern. Walls over air and skin over air are flagged so the planner slows them / prints them as bridges.
 */
import { difference, flatten, offset } from '../geometry/clip.js';
import { UM_PER_MM, type ExPolygon, type Polygon, type Pt } from '../geometry/types.js';
import { generateInfill, solidFill } from '../infill/index.js';
import type { InfillParams, PatternId } from '../infill/types.js';
import { skinGapFill } from '../regions/skin-gaps.js';
import { allSkin } from '../regions/skin-areas.js';
import type { IslandRegions } from '../regions/types.js';
import type { Config } from '../settings/resolve.js';
import type { CustomInfillGenerator } from '../shader/index.js';
import type { LayerZ } from '../slice/types.js';
import { flagOverAir, indexArea } from './over-air.js';
import { overAirMatters } from '../plan/print-order.js';
import type { PathEntry, PathGroup, PathRole } from './types.js';

export interface IslandContext {
  cfg: Config;
  layer: LayerZ;
  /** Line width of the layer, µm. */
  widthUm: number;
  params: InfillParams;
  /** The pattern's whole-model data for this layer (lightning), if any. */
  prepared?: unknown;
  custom?: CustomInfillGenerator;
  /** Area of the layer below that support holds up (its bottom skin there is not a bridge), µm. */
  supportBelow: readonly ExPolygon[];
}

/** Entry of closed or open paths, with over-air flags where an area over air is given. */
function entry(cfg: Config, role: PathRole, closed: boolean, paths: Pt[][], width: number | number[], overAir: readonly ExPolygon[] | null, wall?: number): PathEntry {
  const e: PathEntry = { role, closed, paths, width };
  if (wall !== undefined) e.wall = wall;
  if (overAir && overAir.length && paths.length && overAirMatters(role, cfg)) {
    const idx = indexArea(overAir);
    let flags: (Uint8Array | null)[] | null = null;
    for (let k = 0; k < paths.length; k++) {
      const f = flagOverAir(paths[k], closed, idx);
      if (!f) continue;
      if (!flags) {
        flags = new Array(paths.length).fill(null);
        e.paths = paths = paths.slice(); // the regions' own arrays stay as they are
      }
      paths[k] = f.points;
      flags[k] = f.flags;
    }
    if (flags) e.overAir = flags;
  }
  return e;
}

/** The skin of the island, as skin-wall, skin and skin-gap entries. */
function skinEntries(island: IslandRegions, ctx: IslandContext, bridgeArea: readonly ExPolygon[]): PathEntry[] {
  const { cfg, widthUm: w, layer } = ctx;
  const skinAll = allSkin({ top: island.topSkin, bottom: island.bottomSkin, exposed: island.exposed });
  if (skinAll.length === 0 && island.exposed.length === 0) return [];
  const overlapSkin = (cfg.skinOverlap / 100) * w;
  let skinWalls: Polygon[] = [];
  let fillArea: ExPolygon[];
  if (cfg.skinWall && skinAll.length) {
    const wallCentre = offset(skinAll, -w / 2);
    skinWalls = flatten(wallCentre);
    fillArea = offset(wallCentre, -(w - overlapSkin));
    // pieces too narrow for a skin-wall loop still get their lines
    if (skinAll.length > 1 || wallCentre.length === 0) {
      for (const piece of skinAll) {
        if (offset([piece], -w / 2).length === 0) fillArea.push(...offset([piece], -(w / 2 - overlapSkin)));
      }
    }
  } else {
    fillArea = offset(skinAll, -(w / 2 - overlapSkin));
  }
  const angle = island.bridgeAngle ?? cfg.skinAngle + (layer.index % 2 === 1 ? 90 : 0);
  const lines = fillArea.length ? solidFill(fillArea, angle, w, ctx.params.origin) : [];
  const gaps = skinGapFill(island.exposed, skinWalls, lines, w);
  const out: PathEntry[] = [];
  const air = bridgeArea.length ? bridgeArea : null;
  if (skinWalls.length) out.push(entry(cfg, 'skin-wall', true, skinWalls, w / UM_PER_MM, air));
  if (lines.length) out.push(entry(cfg, 'skin', false, lines, w / UM_PER_MM, air));
  if (gaps.length) out.push(entry(cfg, 'skin-gap', true, gaps.map((g) => g.loop), gaps.map((g) => g.widthUm / UM_PER_MM), null));
  return out;
}

function infillEntries(island: IslandRegions, ctx: IslandContext): PathEntry[] {
  if (island.sparse.length === 0) return [];
  const { cfg, layer, widthUm } = ctx;
  const input = { layerIndex: layer.index, z: layer.z, layerHeight: layer.height, region: island.sparse };
  const params = { ...ctx.params, lineWidth: widthUm };
  const res = ctx.custom ? ctx.custom(input, params) : generateInfill(cfg.infillPattern as PatternId, input, params, ctx.prepared);
  const out: PathEntry[] = [];
  const width = widthUm / UM_PER_MM;
  if (res.loops.length) out.push(entry(cfg, 'infill', true, res.loops, width, null));
  if (res.lines.length) out.push(entry(cfg, 'infill', false, res.lines, width, null));
  return out;
}

/** The island's group of entries (unsorted: the planner puts them in print order). */
export function islandGroup(island: IslandRegions, ctx: IslandContext): PathGroup {
  const { cfg } = ctx;
  const w = ctx.widthUm / UM_PER_MM;
  const entries: PathEntry[] = [];
  const wallsOverAir = island.unsupported.length ? island.unsupported : null;
  island.walls.forEach((loops, k) => {
    if (loops.length) entries.push(entry(cfg, 'wall', true, loops, w, wallsOverAir, k));
  });
  if (island.wallGaps.length) {
    entries.push(entry(cfg, 'wall-gap', true, island.wallGaps.map((g) => g.loop), island.wallGaps.map((g) => g.widthUm / UM_PER_MM), null));
  }
  entries.push(...infillEntries(island, ctx));
  // skin resting on support right below it (no Z gap) is not a bridge; over a Z gap it is, as over air
  const bridgeArea = island.bridge.length && ctx.supportBelow.length ? difference(island.bridge, ctx.supportBelow) : island.bridge;
  entries.push(...skinEntries(island, ctx, bridgeArea));
  const boundary = island.walls[0] && island.walls[0].length ? island.walls[0] : undefined;
  const group: PathGroup = { kind: 'island', object: island.object, area: island.outline, entries };
  if (boundary) group.boundary = boundary;
  return group;
}
