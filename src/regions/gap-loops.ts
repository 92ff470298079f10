/**
 * Gap fill for thin strips (between walls, or skin the lines miss): loops a quarter of the strip's width in from
 * its edge and half its width wide, so that going round the strip their two passes cover it side by side; where
 * a piece widens (a wedge), further loops fill what the first leaves towards its wide end.
 */
import { area, difference, offset, opening, ringArea, strokeArea } from '../geometry/clip.js';
import { UM_PER_MM, type ExPolygon, type Polygon } from '../geometry/types.js';
import { stripWidthUm } from './strip-width.js';

export interface GapLoop {
  loop: Polygon;
  widthUm: number;
}

/** Each gap loop's width, mm, at every one of its points (the per-point widths a path entry carries). */
export function gapLoopWidthsMm(gaps: readonly GapLoop[]): Float64Array[] {
  return gaps.map((g) => new Float64Array(g.loop.length).fill(g.widthUm / UM_PER_MM));
}

/** Strips narrower than this fraction of a line width are left empty (nothing prints that thin). */
export const MIN_GAP_FRACTION = 0.3;
/** Pieces wider than this many line widths are not gaps (a loop of half their width would not cover them). */
const MAX_GAP_WIDTHS = 2;
/** At most this many rounds of loops inside loops. */
const MAX_ROUNDS = 3;
/**
 * Smallest area a gap loop's ring may enclose, µm²: a 25 µm square. A smaller one is a speck the nozzle
 * cannot draw; gap loops are thinner than walls, so theirs is smaller than walls' (MIN_WALL_LOOP_AREA_UM2).
 */
const MIN_GAP_LOOP_AREA_UM2 = 25 * 25;

/**
 * Loops filling thin strips. Parts of the strips thinner than a printable bead are dropped first: besides
 * printing nothing, they would join real gaps into long pieces whose width reads far too small. What a piece's
 * loop leaves bare where the piece is wider than its width estimate (the wide end of a wedge) is filled again
 * the same way, a few times over.
 */
export function gapLoops(gaps: readonly ExPolygon[], lineWidthUm: number): GapLoop[] {
  const out: GapLoop[] = [];
  fillGaps(gaps, lineWidthUm, MAX_ROUNDS, out);
  return out;
}

function fillGaps(gaps: readonly ExPolygon[], w: number, rounds: number, out: GapLoop[]): void {
  const minWidth = MIN_GAP_FRACTION * w;
  const pieces = gaps.filter((g) => area([g]) >= minWidth * minWidth);
  if (pieces.length === 0) return;
  for (const g of opening(pieces, minWidth / 2)) {
    const d = stripWidthUm(g);
    if (d < minWidth || d > MAX_GAP_WIDTHS * w) continue;
    const bead = d / 2;
    const loops = offset([g], -bead / 2)
      .filter((p) => Math.abs(ringArea(p.outer)) >= MIN_GAP_LOOP_AREA_UM2)
      .map((p) => p.outer);
    for (const loop of loops) out.push({ loop, widthUm: Math.round(bead) });
    if (loops.length && rounds > 1) fillGaps(difference([g], loopBeads(loops, bead)), w, rounds - 1, out);
  }
}

/**
 * The beads `width` wide along closed loops (counter-clockwise, as offsets' outer rings are): per loop the band
 * between its mitred offsets out and in by half the width, as strokeArea's mitred loops give it; the mitre
 * offsets usually need no union. A loop whose offsets do not nest as one band each (never seen) is stroked.
 */
export function loopBeads(loops: readonly Polygon[], width: number): ExPolygon[] {
  const out: ExPolygon[] = [];
  const odd: Polygon[] = [];
  for (const loop of loops) {
    const island = [{ outer: loop, holes: [] }];
    const grown = offset(island, width / 2);
    const shrunk = offset(island, -width / 2);
    if (grown.length !== 1 || shrunk.some((s) => s.holes.length > 0)) {
      odd.push(loop);
      continue;
    }
    out.push({ outer: grown[0].outer, holes: [...grown[0].holes, ...shrunk.map((s) => s.outer.slice().reverse())] });
  }
  if (odd.length) out.push(...strokeArea([], odd, width, 'miter'));
  return out;
}
