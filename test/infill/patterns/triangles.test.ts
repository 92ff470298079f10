import { test } from 'node:test';
import assert from 'node:assert/strict';
import { triangles } from '#strata/infill/patterns/triangles.js';
import { TEST_SHAPES, testParams, SHAPE_CENTRE } from '../test-shapes.js';

test('triangles: the three families pass through common points (true triangles)', () => {
  const out = triangles.generate(
    { layerIndex: 0, zMm: 0.2, layerHeightMm: 0.2, region: TEST_SHAPES.square() },
    testParams(0.2),
  );
  const sw = out.sweeps!;
  assert.equal(sw.length, 3);
  assert.deepEqual(
    sw.map((s) => s.angle - sw[0].angle),
    [0, 60, 120],
  );
  const n = (deg: number) => ({ x: -Math.sin((deg * Math.PI) / 180), y: Math.cos((deg * Math.PI) / 180) });
  const [n0, n1, n2] = sw.map((s) => n(s.angle));
  const s = sw[0].spacingUm;
  // every crossing of families 0 and 1 lies on a line of family 2
  for (let i = -3; i <= 3; i++) {
    for (let j = -3; j <= 3; j++) {
      const a = i * s + sw[0].offsetUm,
        b = j * s + sw[1].offsetUm;
      const det = n0.x * n1.y - n0.y * n1.x;
      const p = { x: (a * n1.y - b * n0.y) / det, y: (n0.x * b - n1.x * a) / det };
      const v = (n2.x * p.x + n2.y * p.y - sw[2].offsetUm) / s;
      assert.ok(Math.abs(v - Math.round(v)) < 1e-9, `${i},${j}: ${v}`);
    }
  }
  assert.ok(SHAPE_CENTRE.x > 0);
});
