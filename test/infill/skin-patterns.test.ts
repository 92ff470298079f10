import { test } from 'node:test';
import assert from 'node:assert/strict';
import { offset, pointInArea, ringArea } from '#strata/geometry/clip.js';
import { SKIN_PATTERNS, concentricLoops } from '#strata/infill/skin-patterns.js';
import { solidFill } from '#strata/infill/solid-fill.js';
import { measuredDensity } from '#strata/infill/measure.js';
import { SKIN_PATTERN_IDS } from '#strata/infill/types.js';
import { SHAPE_CENTRE, TEST_SHAPES, square } from './test-shapes.js';

const W = 450;

test('every skin pattern covers the region with beads one spacing apart and stays inside it', () => {
  assert.deepEqual(Object.keys(SKIN_PATTERNS).sort(), [...SKIN_PATTERN_IDS].sort());
  for (const id of SKIN_PATTERN_IDS) {
    for (const [name, make] of Object.entries(TEST_SHAPES)) {
      const region = make();
      const f = SKIN_PATTERNS[id].fill(region, 45, W, SHAPE_CENTRE);
      const d = measuredDensity({ lines: f.lines, loops: f.loops }, region, W);
      assert.ok(d > 0.9 && d < 1.1, `${id} on ${name}: covers ${d.toFixed(3)}`);
      // every point within the region (a micrometre of rounding aside)
      const grown = offset(region, 2);
      for (const p of [...f.lines, ...f.loops].flat())
        assert.ok(
          grown.some((a) => pointInArea(p, a)),
          `${id} on ${name}: (${p.x}, ${p.y}) outside`,
        );
    }
  }
});

test('lines is the solid fill as it always was; monotonic and concentric keep their order', () => {
  const region = TEST_SHAPES['disc with hole']();
  assert.deepEqual(SKIN_PATTERNS.lines.fill(region, 45, W, SHAPE_CENTRE), {
    lines: solidFill(region, 45, W, SHAPE_CENTRE),
    loops: [],
    ordered: false,
  });
  assert.equal(SKIN_PATTERNS.monotonic.fill(region, 45, W, SHAPE_CENTRE).ordered, true);
  assert.equal(SKIN_PATTERNS.concentric.fill(region, 45, W, SHAPE_CENTRE).ordered, true);
});

test('concentric skin is closed loops inwards from the boundary, each a spacing inside the one before', () => {
  const loops = concentricLoops(square(10_000), W);
  // a 10 mm square: loops at 0, 0.45, 0.9 … 4.5 mm in, while what is left is at least a bead wide
  assert.equal(loops.length, 11);
  for (const l of loops) {
    assert.ok(l.length >= 3, 'a ring');
    assert.notDeepEqual(l[0], l[l.length - 1], 'closed rings do not repeat their first point');
    assert.ok(ringArea(l) > 0, 'outer rings counter-clockwise');
  }
  // outside in: each loop's area smaller than the one before, its side W·2 shorter
  for (let k = 1; k < loops.length; k++) {
    const side = (l: (typeof loops)[number]) => Math.max(...l.map((p) => p.x)) - Math.min(...l.map((p) => p.x));
    assert.ok(
      Math.abs(side(loops[k - 1]) - side(loops[k]) - 2 * W) <= 2,
      `loop ${k}: ${side(loops[k - 1])} → ${side(loops[k])}`,
    );
  }
  // a region with a hole: the hole's ring is a loop too (clockwise), printed after its outer ring
  const disc = concentricLoops(TEST_SHAPES['disc with hole'](), W);
  assert.ok(ringArea(disc[0]) > 0 && ringArea(disc[1]) < 0);
});
