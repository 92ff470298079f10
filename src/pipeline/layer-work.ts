/**
 * The per-layer middle of the pipeline for a range of layers: slice (with a window of neighbours
 * for exposure detection), walls, skin and infill regions, and their lines. Pure over plain data, so
 * it runs the same inline or in a worker, and gives the same result however layers are split up.
 */
import { difference, flatten, offset, union } from '../geometry/clip.js';
import { UM_PER_MM, type ExPolygon, type Polygon, type Pt } from '../geometry/types.js';
import { generateInfill, solidFill } from '../infill/index.js';
import type { InfillParams, PatternId } from '../infill/types.js';
import type { IslandPaths, LayerPaths } from '../paths/types.js';
import { allSkin, CoverWindows, skinAreas } from '../regions/skin-areas.js';
import { bridgeAngle } from '../regions/bridge-angle.js';
import { skinGapFill } from '../regions/skin-gaps.js';
import { computeWalls } from '../regions/walls.js';
import type { Config } from '../settings/resolve.js';
import { slicePrepared, type PreparedMesh } from '../slice/index.js';
import type { CustomInfillGenerator } from '../shader/index.js';
import type { LayerSection, LayerZ } from '../slice/types.js';

/** Per-layer regions, as a whole-model infill pass (lightning) needs them. */
export interface LayerRegions {
  index: number;
  /** Sparse-infill centreline area of the whole layer, µm. */
  infill: ExPolygon[];
  /** Top skin of the whole layer, µm. */
  topSkin: ExPolygon[];
}

export interface RangeResult {
  /** Empty for a regions-only job. */
  paths: LayerPaths[];
  /** Only for a regions-only job (nothing else needs them). */
  regions: LayerRegions[];
}

export interface RangeJob {
  layers: readonly LayerZ[];
  from: number;
  to: number;
  /** Only compute regions (for the whole-model infill pass), not lines. */
  regionsOnly: boolean;
  infillParams: InfillParams;
  /** Per-layer data from the pattern's whole-model pass, indexed by layer index. */
  prepared?: readonly unknown[];
}

export function lineWidthUm(cfg: Config, layerIndex: number): number {
  return Math.round((layerIndex === 0 ? cfg.firstLayerLineWidthMm : cfg.lineWidthMm) * UM_PER_MM);
}

/**
 * Compute paths (or only regions) for layers [job.from, job.to); `custom` replaces the built-in
 * pattern with a custom infiller.
 */
export function computeRange(mesh: PreparedMesh, cfg: Config, job: RangeJob, custom?: CustomInfillGenerator): RangeResult {
  const n = job.layers.length;
  const lo = Math.max(0, job.from - cfg.bottomLayers);
  const hi = Math.min(n, job.to + cfg.topLayers);
  const sections: LayerSection[] = slicePrepared(mesh, job.layers.slice(lo, hi) as LayerZ[], Math.round(cfg.meshTolerance * UM_PER_MM));
  const sectionAt = (i: number): ExPolygon[] => (i >= lo && i < hi ? sections[i - lo].islands : []);
  const paths: LayerPaths[] = [];
  const regions: LayerRegions[] = [];
  const topWindows = new CoverWindows(sectionAt, cfg.topLayers, n);
  const bottomWindows = cfg.bottomLayers === cfg.topLayers ? topWindows : new CoverWindows(sectionAt, cfg.bottomLayers, n);
  const infillOn = cfg.infillDensity > 0;
  for (let i = job.from; i < job.to; i++) {
    const section = sections[i - lo];
    const w = lineWidthUm(cfg, i);
    const walls = computeWalls(section.islands, cfg.walls, w);
    const anyInner = walls.some((iw) => iw.inner.length > 0);
    const coveredAbove = anyInner ? topWindows.window(i + 1) : [];
    const coveredBelow = anyInner ? bottomWindows.window(i - cfg.bottomLayers) : [];
    const overlapSkin = (cfg.skinOverlap / 100) * w;
    const overlapInfill = (cfg.infillOverlap / 100) * w;
    const islands: IslandPaths[] = [];
    const layerInfill: ExPolygon[] = [];
    const layerTop: ExPolygon[] = [];
    for (const iw of walls) {
      const skin = skinAreas(iw.inner, coveredAbove, coveredBelow, cfg.topLayers, cfg.bottomLayers, w);
      const skinAll = allSkin(skin);
      const sparse = infillOn ? offset(skinAll.length ? difference(iw.inner, skinAll) : iw.inner, -(w / 2 - overlapInfill)) : [];
      for (const a of sparse) layerInfill.push(a);
      for (const a of skin.top) layerTop.push(a);
      if (job.regionsOnly) continue;
      let skinWalls: Polygon[] = [];
      let skinFillArea: ExPolygon[];
      if (cfg.skinWall && skinAll.length) {
        const wallCentre = offset(skinAll, -w / 2);
        skinWalls = flatten(wallCentre);
        skinFillArea = offset(wallCentre, -(w - overlapSkin));
        // pieces too narrow for a skin-wall loop still get their lines
        if (skinAll.length > 1 || wallCentre.length === 0) {
          for (const piece of skinAll) {
            if (offset([piece], -w / 2).length === 0) skinFillArea.push(...offset([piece], -(w / 2 - overlapSkin)));
          }
        }
      } else {
        skinFillArea = offset(skinAll, -(w / 2 - overlapSkin));
      }
      const skinAngle = (i > 0 ? bridgeAngle(skin.bottom, sectionAt(i - 1), w) : null) ?? cfg.skinAngle + (i % 2 === 1 ? 90 : 0);
      const skinLines = skinFillArea.length ? solidFill(skinFillArea, skinAngle, w, job.infillParams.origin) : [];
      const skinGaps = skinGapFill(skin.exposed, skinWalls, skinLines, w).map((g) => ({ loop: g.loop, width: g.widthUm / UM_PER_MM }));
      let infillLines: Pt[][] = [];
      let infillLoops: Polygon[] = [];
      if (sparse.length) {
        const layerInput = { layerIndex: i, z: section.z, layerHeight: section.height, region: sparse };
        const layerParams = { ...job.infillParams, lineWidth: w };
        const res = custom
          ? custom(layerInput, layerParams)
          : generateInfill(cfg.infillPattern as PatternId, layerInput, layerParams, job.prepared ? job.prepared[i] : undefined);
        infillLines = res.lines;
        infillLoops = res.loops;
      }
      islands.push({ outline: iw.outline, walls: iw.wallLoops, gapFill: iw.gapFill.map((g) => ({ loop: g.loop, width: g.widthUm / UM_PER_MM })), skinWalls, skinLines, skinGaps, infillLines, infillLoops });
    }
    if (job.regionsOnly) regions.push({ index: i, infill: layerInfill.length > 1 ? union(layerInfill) : layerInfill, topSkin: layerTop });
    else {
      paths.push({
        index: section.index,
        z: section.z,
        height: section.height,
        sliceZ: section.sliceZ,
        lineWidth: w / UM_PER_MM,
        islands,
        adhesion: [],
        adhesionFeature: 'SKIRT',
      });
    }
  }
  return { paths, regions };
}
