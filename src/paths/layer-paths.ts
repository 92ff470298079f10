/**
 * The paths stage for one layer: its regions become path groups — raft lines on raft layers; otherwise the
 * skirt or brim (first layer), the support, and every island's walls, skin and infill.
 */
import type { ExPolygon, Polyline } from '../geometry/types.js';
import type { InfillParams, InfillPattern } from '../infill/types.js';
import { lineWidthUm } from '../regions/layer-regions.js';
import type { LayerOutlines, LayerRegions } from '../regions/types.js';
import type { Config } from '../settings/resolve.js';
import { raftGroups, skirtOrBrim } from './adhesion-paths.js';
import { islandGroup } from './island-paths.js';
import { supportGroups } from './support-paths.js';
import type { LayerPaths, PathGroup } from './types.js';

export interface LayerPathsContext {
  /** The print's config. */
  cfg: Config;
  /** Every config of the print (configs[0] is `cfg`): islands and support read their object's or region's. */
  configs: readonly Config[];
  /** Per object, the index of its config. */
  objectConfigs: readonly number[];
  /** Infill parameters of each object (its pattern origin), by object index. */
  params: readonly InfillParams[];
  /** The pattern's whole-model data for this layer (lightning). */
  prepared?: Polyline[];
  /** The slice's custom infill, which fills every region in place of its pattern. */
  custom?: InfillPattern;
  /** Support areas of the layer below (skin resting on them is no bridge), µm. */
  supportBelow: readonly ExPolygon[];
  /** Added to the layer's Z (the raft under the model), mm. */
  zOffset: number;
  /** Skirt or brim go round this layer (the print's first layer on the bed). */
  adhesion: boolean;
}

export function layerPaths(regions: LayerRegions, ctx: LayerPathsContext): LayerPaths {
  return withSharedGroups(modelPaths(regions, ctx), regions, ctx);
}

/**
 * The layer's own part: raft lines on raft layers, else every island's walls, skin and infill. None of it
 * depends on the support pass (unless skin rests on support, `supportBelow`), so it may be made before it.
 */
export function modelPaths(regions: LayerRegions, ctx: LayerPathsContext): LayerPaths {
  const { cfg } = ctx;
  const w = layerLineWidthUm(regions, cfg);
  const groups: PathGroup[] = [];
  if (regions.raft) {
    groups.push(...raftGroups(regions.raft, cfg, regions, ctx.params[0].origin));
  } else {
    for (const island of regions.islands) {
      groups.push(
        islandGroup(island, {
          configs: ctx.configs,
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
  const out: LayerPaths = {
    index: regions.index,
    z: regions.z + ctx.zOffset,
    height: regions.height,
    sliceZ: regions.sliceZ,
    lineWidthMm: w / 1000,
    groups,
  };
  let lost = 0;
  for (const island of regions.islands) lost += island.lostMm2;
  if (lost > 0) out.lostMm2 = lost;
  if (regions.vase) out.vase = true;
  if (regions.firstLayerFilledMm2) out.firstLayerFilledMm2 = regions.firstLayerFilledMm2;
  if (regions.vaseDroppedMm2) out.vaseDroppedMm2 = regions.vaseDroppedMm2;
  return out;
}

/**
 * The model paths of a layer with what is shared by the layer's objects put first: the skirt or brim (on
 * the print's first layer, round the support too) and the support. `paths` is changed and returned.
 */
export function withSharedGroups(paths: LayerPaths, regions: LayerOutlines, ctx: LayerPathsContext): LayerPaths {
  if (regions.raft) return paths;
  const { cfg } = ctx;
  const shared: PathGroup[] = [];
  if (ctx.adhesion) {
    const support = regions.support ? [...regions.support.body, ...regions.support.roof, ...regions.support.floor] : [];
    shared.push(
      ...skirtOrBrim(
        regions.islands.map((i) => i.outline),
        support,
        cfg,
        layerLineWidthUm(regions, cfg),
      ),
    );
  }
  if (regions.supports) {
    // each object's support prints inside the object's label, so cancelling the object stops its support
    regions.supports.forEach((support, o) => {
      for (const g of supportGroups(support, ctx.configs[ctx.objectConfigs[o]], regions, ctx.params[0].origin))
        shared.push({ ...g, object: o });
    });
  } else
    shared.push(
      ...supportGroups(regions.support, ctx.configs[ctx.objectConfigs[0] ?? 0], regions, ctx.params[0].origin),
    );
  if (shared.length) paths.groups = [...shared, ...paths.groups];
  paths.z = regions.z + ctx.zOffset;
  return paths;
}

function layerLineWidthUm(regions: LayerOutlines, cfg: Config): number {
  return regions.raft ? Math.round(cfg.lineWidthMm * 1000) : lineWidthUm(cfg, regions.index);
}
