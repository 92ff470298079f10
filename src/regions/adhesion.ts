/**
 * First-layer adhesion: skirt loops around the print at a distance, or brim loops attached to it.
 * Only the outer boundaries are used, so a brim never runs inside a hole.
 */
import { offset, union } from '../geometry/clip.js';
import type { ExPolygon, Polygon } from '../geometry/types.js';

export interface AdhesionSettings {
  adhesionType: 'skirt' | 'brim' | 'raft' | 'none';
  skirtLoops: number;
  /** mm */
  skirtDistance: number;
  /** mm */
  brimWidth: number;
}

function outerRings(areas: readonly ExPolygon[]): Polygon[] {
  return areas.map((a) => a.outer);
}

/**
 * Loops (µm) for the first layer, innermost first.
 * @param islands the first layer's islands, µm
 * @param lineWidthUm first-layer line width, µm
 */
export function adhesionLoops(islands: readonly ExPolygon[], s: AdhesionSettings, lineWidthUm: number): Polygon[] {
  if (s.adhesionType === 'none' || s.adhesionType === 'raft' || islands.length === 0) return [];
  const w = lineWidthUm;
  // fill the holes: only the outside matters
  const solid = union(islands.map((a) => ({ outer: a.outer, holes: [] })));
  const loops: Polygon[] = [];
  if (s.adhesionType === 'skirt') {
    const base = s.skirtDistance * 1000 + w / 2;
    // one merged outline around everything, so the skirt is a few clean loops
    const around = offset(offset(solid, base + w * 2, 'round'), -w * 2, 'round');
    for (let k = 0; k < s.skirtLoops; k++) loops.push(...outerRings(k === 0 ? around : offset(around, k * w, 'round')));
  } else {
    const count = Math.max(1, Math.round((s.brimWidth * 1000) / w));
    for (let k = 0; k < count; k++) loops.push(...outerRings(offset(solid, w / 2 + k * w, 'round')));
  }
  return loops;
}
