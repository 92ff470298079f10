/**
 * Skin patterns: the one table from a skin pattern id (topSkinPattern, bottomSkinPattern) to the fill that
 * lays it. Each fills a skin region (the centreline area of its beads) with beads one spacing apart:
 * - lines: parallel lines zig-zag linked along the boundary, ordered nearest-first (solid-fill.ts);
 * - monotonic: the same lines, each laid beside lines already printed on one side only (monotonic.ts);
 * - concentric: loops inwards from the region's boundary, each a bead's spacing inside the one before.
 */
import { offset } from '../geometry/clip.js';
import type { ExPolygon, Polygon, Polyline, Pt } from '../geometry/types.js';
import { monotonicFill } from './monotonic.js';
import { solidFill } from './solid-fill.js';
import type { SkinPatternId } from './types.js';

export interface SkinFill {
  lines: Polyline[];
  loops: Polygon[];
  /** The paths print in the order given, lines from their first point; otherwise the planner orders them. */
  ordered: boolean;
}

export interface SkinPattern {
  readonly id: SkinPatternId;
  readonly description: string;
  /** Fill `region` with beads `spacingUm` apart (lines at `angleDeg`, their phase anchored at `origin`). */
  fill(region: readonly ExPolygon[], angleDeg: number, spacingUm: number, origin: Pt): SkinFill;
}

/**
 * Concentric loops of each piece of the region: its boundary, then the boundary of its inset by one
 * spacing, and so on while anything is left; a piece that splits as it shrinks is followed branch by
 * branch, so the nozzle finishes one branch before it moves to the next. Outer rings before their holes.
 * A piece thinner than a bead gets no loop (its two sides would print over each other): the skin's gap fill
 * covers it.
 */
export function concentricLoops(region: readonly ExPolygon[], spacingUm: number): Polygon[] {
  const loops: Polygon[] = [];
  const stack: ExPolygon[] = region.slice().reverse();
  while (stack.length) {
    const piece = stack.pop()!;
    const half = offset([piece], -spacingUm / 2);
    if (half.length === 0) continue;
    loops.push(piece.outer, ...piece.holes);
    const inner = offset(half, -spacingUm / 2);
    for (let k = inner.length - 1; k >= 0; k--) stack.push(inner[k]);
  }
  return loops;
}

export const SKIN_PATTERNS: Readonly<Record<SkinPatternId, SkinPattern>> = {
  lines: {
    id: 'lines',
    description: 'Parallel lines, joined where neighbouring ends meet along the boundary, nearest first.',
    fill: (region, angle, spacing, origin) => ({
      lines: solidFill(region, angle, spacing, origin),
      loops: [],
      ordered: false,
    }),
  },
  monotonic: {
    id: 'monotonic',
    description:
      'Parallel lines, each laid beside lines already printed on one side only, so no seam shows where fronts of lines meet.',
    fill: (region, angle, spacing, origin) => ({
      lines: monotonicFill(region, angle, spacing, origin),
      loops: [],
      ordered: true,
    }),
  },
  concentric: {
    id: 'concentric',
    description: 'Loops inwards from the boundary of the skin.',
    fill: (region, _angle, spacing) => ({ lines: [], loops: concentricLoops(region, spacing), ordered: true }),
  },
};
