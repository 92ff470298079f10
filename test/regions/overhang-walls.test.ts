import { test } from 'node:test';
import assert from 'node:assert/strict';
import { area, difference, pointInArea } from '#strata/geometry/clip.js';
import { rect } from '../geometry/test-shapes.js';
import type { Pt } from '#strata/geometry/types.js';
import { overhangWalls } from '#strata/regions/overhang-walls.js';

const W = 400;
const maxX = (lines: readonly Pt[][]) => Math.max(...lines.flat().map((p) => p.x));

test('a cantilever held on one side: rings parallel to its free edges, ending in the anchor, printed from the anchor outwards', () => {
  // the island's inside, 20 × 4 mm; the layer below holds its first 8 mm
  const inner = [rect(0, 0, 20_000, 4_000)];
  const below = [rect(-1_000, -1_000, 8_000, 5_000)];
  const made = overhangWalls(inner, below, W, 2)!;
  assert.ok(made && made.rings.length >= 4, `rings: ${made?.rings.length}`);
  // each ring reaches further out than the one printed before it
  const reach = made.rings.map((r) => maxX(r.paths));
  for (let k = 1; k < reach.length; k++)
    assert.ok(reach[k] >= reach[k - 1] - 1, `ring ${k} reaches ${reach[k]} after ${reach[k - 1]}`);
  // the last ring runs along the free end, half a line in
  assert.ok(
    reach[reach.length - 1] > 20_000 - W && reach[reach.length - 1] <= 20_000 - W / 2,
    `${reach[reach.length - 1]}`,
  );
  // the rings' lines (not the gap fill's loops) start and end over the anchor: U shapes, never a dangling end
  for (const ring of made.rings.filter((r) => r.widths === null)) {
    for (const line of ring.paths) {
      for (const end of [line[0], line[line.length - 1]]) assert.ok(end.x < 8_000, `a line ends at x ${end.x}`);
    }
  }
  // they fill the overhang: skin and infill keep out of it
  const overhang = difference(inner, below);
  assert.ok(area(difference(overhang, made.covered)) < 0.02 * area(overhang));
  // the anchor beyond the band round the overhang (a line more than the walls: 1.2 mm) is left to the infill
  assert.ok(!made.covered.some((a) => pointInArea({ x: 4_000, y: 2_000 }, a)));
});

test('an overhang held on two sides bridges (no extra walls); nothing over air, nothing to do', () => {
  const inner = [rect(0, 0, 20_000, 4_000)];
  assert.equal(
    overhangWalls(inner, [rect(-1_000, -1_000, 4_000, 5_000), rect(16_000, -1_000, 21_000, 5_000)], W, 2),
    null,
  );
  assert.equal(overhangWalls(inner, [rect(-1_000, -1_000, 21_000, 5_000)], W, 2), null);
  // a sliver over air along a side (thinner than half a line) rests on the wall beside it
  assert.equal(overhangWalls(inner, [rect(-1_000, 150, 21_000, 5_000)], W, 2), null);
});
