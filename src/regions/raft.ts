/**
 * The raft: layers printed under the model — a thick base of wide lines on the bed, interface layers across
 * it, and solid surface layers the print stands on — covering the first layer of the print and its support,
 * grown by the raft margin (holes filled). The model is raised by the raft's thickness and an air gap.
 */
import { offset, union } from '../geometry/clip.js';
import { UM_PER_MM, type ExPolygon } from '../geometry/types.js';
import type { Config } from '../settings/resolve.js';
import type { LayerOutlines, LayerRegions, RaftArea } from './types.js';

export interface Raft {
  /** The raft's layers, bottom up (Z in print coordinates). */
  layers: LayerRegions[];
  /** How far the model is raised: raft thickness plus the air gap, mm. */
  zOffset: number;
}

/** The raft under a model whose first layer has these regions ([] layers when adhesion is not a raft). */
export function raftUnder(first: LayerOutlines | undefined, cfg: Config): Raft {
  if (cfg.adhesionType !== 'raft' || !first) return { layers: [], zOffset: 0 };
  const footprint: ExPolygon[] = first.islands.map((i) => ({ outer: i.outline.outer, holes: [] }));
  if (first.support)
    for (const a of [...first.support.body, ...first.support.roof, ...first.support.floor])
      footprint.push({ outer: a.outer, holes: [] });
  if (footprint.length === 0) return { layers: [], zOffset: 0 };
  const grown = offset(union(footprint), cfg.raftMargin * UM_PER_MM, 'round').map((a) => ({
    outer: a.outer,
    holes: [],
  }));
  const area = union(grown);
  const kinds: { kind: RaftArea['kind']; height: number }[] = [{ kind: 'base', height: cfg.raftBaseThickness }];
  for (let k = 0; k < cfg.raftInterfaceLayers; k++) kinds.push({ kind: 'interface', height: cfg.layerHeight });
  for (let k = 0; k < cfg.raftSurfaceLayers; k++) kinds.push({ kind: 'surface', height: cfg.layerHeight });
  const layers: LayerRegions[] = [];
  let zUm = 0;
  kinds.forEach((k, index) => {
    const hUm = Math.round(k.height * UM_PER_MM);
    zUm += hUm;
    layers.push({
      index,
      z: zUm / UM_PER_MM,
      height: hUm / UM_PER_MM,
      sliceZ: NaN,
      islands: [],
      overhang: [],
      support: null,
      raft: { kind: k.kind, area },
    });
  });
  return { layers, zOffset: (zUm + Math.round(cfg.raftAirGap * UM_PER_MM)) / UM_PER_MM };
}
