/**
 * The walls of a layer's islands, by the `wallGenerator` setting: variable-width walls (variable-walls.ts)
 * or classic fixed-width loops (walls.ts).
 */
import type { MedialScratch } from '../geometry/medial-axis.js';
import type { ExPolygon } from '../geometry/types.js';
import type { Config } from '../settings/resolve.js';
import { variableWalls } from './variable-walls.js';
import { classicWalls, type IslandWalls } from './walls.js';

export type { IslandWalls } from './walls.js';

/** @param scratch the medial axis's working memory, reused by the caller over its layers (optional) */
export function computeWalls(
  islands: readonly ExPolygon[],
  cfg: Config,
  lineWidthUm: number,
  scratch?: MedialScratch,
): IslandWalls[] {
  return cfg.wallGenerator === 'classic' || cfg.wallCount === 0
    ? classicWalls(islands, cfg.wallCount, lineWidthUm)
    : variableWalls(islands, cfg, lineWidthUm, scratch);
}
