/**
 * Making a path entry: its style resolved from the role table, and, where an area over air is given and the
 * role prints such runs differently, each path split where it crosses into that area and its edges flagged
 * (per-point widths follow the split).
 */
import type { ExPolygon, Pt } from '../geometry/types.js';
import type { Config } from '../settings/resolve.js';
import { flagOverAir, indexArea } from './over-air.js';
import { entryStyle, overAirMatters, type PathRole } from './roles.js';
import type { PathEntry } from './types.js';

export interface EntryOptions {
  /** Wall index (walls only). */
  wall?: number;
  /** Per-path per-point widths, mm (null entries: `width`). */
  widths?: (Float64Array | null)[];
  /** The area over nothing on the layer below. */
  overAir?: readonly ExPolygon[] | null;
}

/** An entry of closed or open paths of one role, `width` mm wide unless a path has widths of its own. */
export function makeEntry(cfg: Config, role: PathRole, closed: boolean, paths: Pt[][], width: number, opts: EntryOptions = {}): PathEntry {
  const style = entryStyle(cfg, role, opts.wall);
  const e: PathEntry = { role, closed, paths, width, style };
  if (opts.wall !== undefined) e.wall = opts.wall;
  let widths = opts.widths && opts.widths.some((w) => w !== null) ? opts.widths : undefined;
  if (widths) e.widths = widths;
  const overAir = opts.overAir;
  if (overAir && overAir.length && paths.length && overAirMatters(style)) {
    const idx = indexArea(overAir);
    let flags: (Uint8Array | null)[] | null = null;
    for (let k = 0; k < paths.length; k++) {
      const f = flagOverAir(paths[k], closed, idx, widths?.[k] ?? null);
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
