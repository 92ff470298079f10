/** Test helper: layer regions from hand-made sections (outline and overhang only, which support reads). */
import type { ExPolygon } from '#strata/geometry/types.js';
import type { Config } from '#strata/settings/resolve.js';
import { overhangOf } from '#strata/regions/overhang.js';
import type { IslandRegions, LayerRegions } from '#strata/regions/types.js';

const island = (outline: ExPolygon): IslandRegions => ({
  object: 0,
  region: 0,
  outline,
  walls: [],
  lostMm2: 0,
  topSkin: [],
  bottomSkin: [],
  skin: [],
  exposed: [],
  bridge: [],
  bridgeAngle: null,
  sparse: [],
  unsupported: [],
});

/** `sectionAt(j)` for layers 0..count-1, heights from the config, overhangs found as the regions stage does. */
export function layersOf(
  count: number,
  sectionAt: (j: number) => ExPolygon[],
  cfg: Config,
  heightOf?: (j: number) => number,
): LayerRegions[] {
  const out: LayerRegions[] = [];
  let zUm = 0;
  for (let j = 0; j < count; j++) {
    // (with `heightOf`, uneven layers: each its own height, Z their sum in whole µm)
    const h = heightOf ? heightOf(j) : j === 0 ? cfg.firstLayerHeight : cfg.layerHeight;
    zUm += Math.round(h * 1000);
    const z = heightOf ? zUm / 1000 : cfg.firstLayerHeight + j * cfg.layerHeight;
    const s = sectionAt(j);
    out.push({
      index: j,
      z,
      height: h,
      sliceZ: z - h / 2,
      islands: s.map(island),
      overhang: overhangOf(s, j > 0 ? sectionAt(j - 1) : [], h, cfg, j === 0),
      support: null,
    });
  }
  return out;
}

/** Run the support pass to its end. */
export function drain(steps: Generator<unknown, unknown>): void {
  while (!steps.next().done);
}
