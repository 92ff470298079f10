/**
 * Adhesion paths: the skirt or brim round the first layer, and the lines of each raft layer (a thick base of
 * wide lines, interface lines across it, a solid surface the print stands on).
 */
import { union } from '../geometry/clip.js';
import { UM_PER_MM, type ExPolygon, type Pt } from '../geometry/types.js';
import { solidFill } from '../infill/index.js';
import { adhesionLoops } from '../regions/adhesion.js';
import type { RaftArea } from '../regions/types.js';
import type { Config } from '../settings/resolve.js';
import type { LayerZ } from '../slice/types.js';
import { makeEntry } from './entry.js';
import type { PathGroup } from './types.js';

/**
 * Skirt (round the print and its support) or brim (attached to the part) on the first layer.
 * @param islands the first layer's islands, µm
 * @param support the first layer's support areas, µm
 */
export function skirtOrBrim(
  islands: readonly ExPolygon[],
  support: readonly ExPolygon[],
  cfg: Config,
  widthUm: number,
): PathGroup[] {
  const around = cfg.adhesionType === 'skirt' && support.length ? union([...islands, ...support]) : islands;
  const loops = adhesionLoops(around, cfg, widthUm);
  if (loops.length === 0) return [];
  const role = cfg.adhesionType === 'brim' ? 'brim' : 'skirt';
  return [{ kind: 'adhesion', entries: [makeEntry(cfg, role, true, loops, widthUm / UM_PER_MM)] }];
}

/** The paths of one raft layer. */
export function raftGroups(raft: RaftArea, cfg: Config, layer: LayerZ, origin: Pt): PathGroup[] {
  if (raft.area.length === 0) return [];
  const w = cfg.lineWidthMm;
  let width: number, spacing: number, angle: number, role: 'raft-base' | 'raft-interface' | 'raft-surface';
  switch (raft.kind) {
    case 'base':
      role = 'raft-base';
      width = cfg.raftBaseLineWidthMm;
      spacing = cfg.raftBaseLineSpacingMm;
      angle = 0;
      break;
    case 'interface':
      role = 'raft-interface';
      width = w;
      spacing = cfg.raftInterfaceLineSpacingMm;
      angle = 90 + (layer.index % 2) * 90;
      break;
    case 'surface':
      role = 'raft-surface';
      width = w;
      spacing = w;
      angle = 45 + (layer.index % 2) * 90;
      break;
  }
  // one group per raft piece (travel within a piece combs, between pieces retracts)
  const groups: PathGroup[] = [];
  for (const area of raft.area) {
    const lines = solidFill([area], angle, Math.round(spacing * UM_PER_MM), origin);
    if (lines.length) groups.push({ kind: 'adhesion', area, entries: [makeEntry(cfg, role, false, lines, width)] });
  }
  return groups;
}
