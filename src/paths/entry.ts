/**
 * Making a path entry: its style resolved from the role table, and, where an area over air is given and the
 * role prints such runs differently, each path split where it crosses into that area and its edges flagged
 * (per-point widths follow the split); walls graded by how much of the line hangs over nothing are split at
 * the edges of each level's area and flagged with the level.
 */
import type { ExPolygon, Pt } from '../geometry/types.js';
import type { Config } from '../settings/resolve.js';
import { flagLevels, flagOverAir, indexArea, type AreaIndex } from './over-air.js';
import { entryStyle, overAirMatters, type PathRole } from './roles.js';
import type { PathEntry } from './types.js';

export interface EntryOptions {
  /** Wall index (walls only). */
  wall?: number;
  /** Per-path per-point widths, mm (null entries: `width`). */
  widths?: (Float64Array | null)[];
  /** The area over nothing on the layer below. */
  overAir?: readonly ExPolygon[] | null;
  /**
   * With graded styles (EntryStyle.levels): where a quarter, half and three quarters of the line width or
   * more hangs over nothing (levels 1 to 3; `overAir` is level 4, all of it).
   */
  overhangLevels?: readonly (readonly ExPolygon[])[] | null;
}

/** An entry of closed or open paths of one role, `width` mm wide unless a path has widths of its own. */
export function makeEntry(
  cfg: Config,
  role: PathRole,
  closed: boolean,
  paths: Pt[][],
  width: number,
  opts: EntryOptions = {},
): PathEntry {
  const style = entryStyle(cfg, role, opts.wall);
  const e: PathEntry = { role, closed, paths, width, style };
  if (opts.wall !== undefined) e.wall = opts.wall;
  let widths = opts.widths && opts.widths.some((w) => w !== null) ? opts.widths : undefined;
  if (widths) e.widths = widths;
  const overAir = opts.overAir;
  const graded =
    style.levels && (opts.overhangLevels?.length || overAir?.length) ? gradedAreas(opts.overhangLevels, overAir) : null;
  if (graded ? graded.some((a) => a.areas.length) : overAir && overAir.length && overAirMatters(style)) {
    const idx = graded ? null : indexArea(overAir!);
    let flags: (Uint8Array | null)[] | null = null;
    for (let k = 0; k < paths.length; k++) {
      const f = graded
        ? flagLevels(paths[k], closed, graded, widths?.[k] ?? null)
        : flagOverAir(paths[k], closed, idx!, widths?.[k] ?? null);
      if (!f) continue;
      if (!flags) {
        flags = new Array(paths.length).fill(null);
        e.paths = paths = paths.slice(); // the regions' own arrays stay as they are
        if (widths) e.widths = widths = widths.slice();
      }
      paths[k] = f.points;
      if (widths) widths[k] = f.widths;
      flags[k] = f.flags;
    }
    if (flags) e.overAir = flags;
  }
  return e;
}

/**
 * Level areas indexed once for all the entries of an island that read them (its wall sets, its extra walls):
 * a memo keyed by the island's own area lists (no other slice holds them), held no longer than they are.
 */
const gridded = new WeakMap<readonly ExPolygon[], AreaIndex>();
const NONE = indexArea([]);

/** The areas of over-air levels 1 to 4, indexed for flagging (missing ones empty). */
function gradedAreas(levels: EntryOptions['overhangLevels'], overAir: EntryOptions['overAir']): AreaIndex[] {
  const index = (areas: readonly ExPolygon[] | null | undefined): AreaIndex => {
    if (!areas || areas.length === 0) return NONE;
    let idx = gridded.get(areas);
    if (!idx) gridded.set(areas, (idx = indexArea(areas, true)));
    return idx;
  };
  return [index(levels?.[0]), index(levels?.[1]), index(levels?.[2]), index(overAir)];
}
