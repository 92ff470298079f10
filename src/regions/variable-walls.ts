import type { ExPolygon } from '../geometry/types.js';
import type { Config } from '../settings/resolve.js';
import { classicWalls, type IslandWalls } from './walls.js';

export function variableWalls(islands: readonly ExPolygon[], cfg: Config, lineWidthUm: number): IslandWalls[] {
  return classicWalls(islands, cfg.walls, lineWidthUm);
}
