/**
 * The paths stage for one layer: its regions become path groups — raft lines on raft layers; otherwise the
 * skirt or brim (first layer), the support, and every island's walls, skin and infill.
 */
import type { ExPolygon } from '../geometry/types.js';
import type { InfillParams } from '../infill/types.js';
import { lineWidthUm } from '../regions/layer-regions.js';
import type { LayerRegions } from '../regions/types.js';
import type { Config } from '../settings/resolve.js';
import type { CustomInfillGenerator } from '../shader/index.js';
import { raftGroups, skirtOrBrim } from './adhesion-paths.js';
import { islandGroup } from './island-paths.js';
import { supportGroups } from './support-paths.js';
import type { LayerPaths, PathGroup } from './types.js';

export interface LayerPathsContext {
  cfg: Config;
  /** Infill parameters of each object (its pattern origin), by object index. */
  params: readonly InfillParams[];
  /** The pattern's whole-model data for this layer (lightning). */
  prepared?: unknown;
  custom?: CustomInfillGenerator;
  /** Support areas of the layer below (skin resting on them is no bridge), µm. */
  supportBelow: readonly ExPolygon[];
  /** Added to the layer's Z (the raft under the model), mm. */
  zOffset: number;
  /** Skirt or brim go round this layer (the print's first layer on the bed). */
  adhesion: boolean;
}

export function layerPaths(regions: LayerRegions, ctx: LayerPathsContext): LayerPaths {
  const { cfg } = ctx;
  const w = regions.raft ? Math.round(cfg.lineWidthMm * 1000) : lineWidthUm(cfg, regions.index);
  const origin = ctx.params[0].origin;
  const groups: PathGroup[] = [];
  if (regions.raft) {
    groups.push(...raftGroups(regions.raft, cfg, regions, origin));
  } else {
    if (ctx.adhesion) {
      const support = regions.support ? [...regions.support.body, ...regions.support.roof, ...regions.support.floor] : [];
      groups.push(...skirtOrBrim(regions.islands.map((i) => i.outline), support, cfg, w));
    }
    groups.push(...supportGroups(regions.support, cfg, regions, origin));
    for (const island of regions.islands) {
      groups.push(
        islandGroup(island, {
          cfg,
          layer: regions,
          widthUm: w,
          params: ctx.params[island.object] ?? ctx.params[0],
          prepared: ctx.prepared,
          custom: ctx.custom,
          supportBelow: ctx.supportBelow,
        }),
      );
    }
  }
  return {
    index: regions.index,
    z: regions.z + ctx.zOffset,
    height: regions.height,
    sliceZ: regions.sliceZ,
    lineWidth: w / 1000,
    groups,
  };
}
