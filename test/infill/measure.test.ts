import { test } from 'node:test';
import assert from 'node:assert/strict';
import { extrudedAreaUm2 } from '#strata/infill/measure.js';
import { familyDensity, familySpacing } from '#strata/infill/density.js';
import { hexSide } from '#strata/infill/patterns/hexagons.js';

const W = 400;

test('one line: length × width plus two half-disc caps', () => {
  const a = extrudedAreaUm2(
    {
      lines: [
        [
          { x: 0, y: 0 },
          { x: 10_000, y: 0 },
        ],
      ],
      loops: [],
    },
    W,
  );
  const expected = 10_000 * W + Math.PI * (W / 2) ** 2;
  assert.ok(Math.abs(a - expected) / expected < 0.01, `${a} vs ${expected}`);
});

test('a crossing counts once', () => {
  const a = extrudedAreaUm2(
    {
      lines: [
        [
          { x: -5_000, y: 0 },
          { x: 5_000, y: 0 },
        ],
        [
          { x: 0, y: -5_000 },
          { x: 0, y: 5_000 },
        ],
      ],
      loops: [],
    },
    W,
  );
  const expected = 2 * (10_000 * W + Math.PI * (W / 2) ** 2) - W * W;
  assert.ok(Math.abs(a - expected) / expected < 0.01, `${a} vs ${expected}`);
});

test('inside a region only the inner part counts: a line on the boundary is half in', () => {
  const region = [
    {
      outer: [
        { x: 0, y: 0 },
        { x: 10_000, y: 0 },
        { x: 10_000, y: 10_000 },
        { x: 0, y: 10_000 },
      ],
      holes: [],
    },
  ];
  const a = extrudedAreaUm2(
    {
      lines: [
        [
          { x: 2_000, y: 0 },
          { x: 8_000, y: 0 },
        ],
      ],
      loops: [],
    },
    W,
    region,
  );
  const expected = 6_000 * (W / 2) + (Math.PI * (W / 2) ** 2) / 2; // the inner halves of the caps too
  assert.ok(Math.abs(a - expected) / expected < 0.02, `${a} vs ${expected}`);
});

test('spacing rules invert the density rules, and the seed grid rule gives its setting', () => {
  for (const F of [1, 2, 3]) {
    for (const d of [0.05, 0.1, 0.2, 0.4, 0.6]) {
      const s = familySpacing(d, W, F);
      assert.ok(Math.abs(familyDensity(s, W, F) - d) < 1e-9);
    }
  }
  // the seed: grid at 20 % with a 0.4 mm nozzle and line width has lines 4 mm apart in each direction
  assert.equal(familySpacing(0.2, W, 2), 4_000);
  assert.ok(hexSide(0.2, W) > hexSide(0.4, W));
});
