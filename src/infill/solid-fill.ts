/**
 * Solid (skin) fill: one family of parallel lines, one line width apart, clipped exactly to the region by the
 * scanline engine and zig-zag linked along its boundary.
 */
import type { ExPolygon, Polyline, Pt } from '../geometry/types.js';
import { regionGeom } from './region-index.js';
import { clipSweep } from './sweep.js';
import { linkPieces } from './link.js';
import { cleanPaths } from './cleanup.js';
import { orderLines } from '../order/index.js';
import type { Piece } from './piece.js';
import { LINK_REACH } from './generate.js';

export interface SolidFillOptions {
  /** Join neighbouring line ends along the boundary (zig-zag). Default true. */
  connect?: boolean;
  /** Where the nozzle is before the fill; the first line starts nearest to it. */
  start?: Pt;
  /** Order the lines nearest-first (default true); off when the caller orders them itself. */
  order?: boolean;
}

/**
 * Solid (skin) fill: one family of lines `spacingUm` apart at `angleDeg`, phase anchored at `origin`,
 * clipped exactly by the scanline engine, zig-zag linked and ordered.
 */
export function solidFill(
  region: readonly ExPolygon[],
  angleDeg: number,
  spacingUm: number,
  origin: Pt,
  options: SolidFillOptions = {},
): Polyline[] {
  if (region.length === 0 || !(spacingUm > 0)) return [];
  const geom = regionGeom(region);
  const pieces: Piece[] = [];
  clipSweep(geom, { angle: angleDeg, spacingUm, offsetUm: 0 }, origin, pieces);
  const lines =
    options.connect === false ? pieces.map((p) => p.pts) : linkPieces(geom, pieces, LINK_REACH * spacingUm).lines;
  const clean = cleanPaths(lines, [], 0);
  if (options.order === false) return clean.lines;
  return orderLines(clean.lines, options.start ?? { x: geom.minX, y: geom.minY });
}
