import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pointInArea } from '#strata/geometry/clip.js';
import { rect } from '../geometry/test-shapes.js';
import type { ExPolygon, Pt } from '#strata/geometry/types.js';
import { BelowLevels, overhangLevels } from '#strata/regions/overhang-levels.js';

const W = 400;
const inAny = (p: Pt, areas: readonly ExPolygon[]) => areas.some((a) => pointInArea(p, a));
/** The level (0 to 3) the levels' areas give a point. */
const levelAt = (p: Pt, levels: readonly ExPolygon[][]) => levels.reduce((l, a, k) => (inAny(p, a) ? k + 1 : l), 0);

test('a side reaching out past the layer below: its outer wall (half a line in) is on the level of the share of its line over nothing', () => {
  const outline = rect(0, 0, 10_000, 10_000);
  // the layer below ends `out` µm inside the right side: the outer wall's centreline, 200 µm in, has
  // (out - 200 + 200) / 400 = out / 400 of its line over nothing
  for (const [out, level] of [
    [50, 0],
    [130, 1],
    [230, 2],
    [330, 3],
    [390, 3],
  ] as const) {
    const levels = overhangLevels(outline, new BelowLevels([rect(0, 0, 10_000 - out, 10_000)], W), W);
    const wall = { x: 10_000 - W / 2, y: 5_000 };
    assert.equal(levels === null ? 0 : levelAt(wall, levels), level, `${out} µm out`);
    // the sides over the layer below are on no level, the outer wall on them neither
    if (levels)
      for (const p of [
        { x: W / 2, y: 5_000 },
        { x: 5_000, y: W / 2 },
        { x: 5_000, y: 5_000 },
      ])
        assert.equal(levelAt(p, levels), 0);
  }
});

test('an outline no wider than the layer below has no levels, however its sides lie', () => {
  const outline = rect(0, 0, 10_000, 10_000);
  assert.equal(overhangLevels(outline, new BelowLevels([outline], W), W), null);
  assert.equal(overhangLevels(rect(100, 100, 9_000, 9_000), new BelowLevels([outline], W), W), null);
});
