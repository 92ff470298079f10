import { test } from 'node:test';
import assert from 'node:assert/strict';
import { gyroid, gyroidPeriod } from '#strata/infill/patterns/gyroid.js';
import { TEST_SHAPES, testParams, SHAPE_CENTRE } from '../test-shapes.js';

test('gyroid: every vertex lies on the gyroid surface at the layer height (within 2 µm)', () => {
  const params = testParams(0.2);
  const L = gyroidPeriod(params);
  const k = (2 * Math.PI) / L;
  for (const z of [0.3, 1.1, 2.7]) {
    const out = gyroid.generate(
      { layerIndex: 0, zMm: z, layerHeightMm: 0.2, region: TEST_SHAPES['disc with hole']() },
      params,
    );
    const Z = k * (z - 0.1) * 1000;
    let n = 0;
    for (const line of out.lines) {
      for (const p of line) {
        const X = k * (p.x - SHAPE_CENTRE.x),
          Y = k * (p.y - SHAPE_CENTRE.y);
        const f = Math.sin(X) * Math.cos(Y) + Math.sin(Y) * Math.cos(Z) + Math.sin(Z) * Math.cos(X);
        const gx = k * (Math.cos(X) * Math.cos(Y) - Math.sin(Z) * Math.sin(X));
        const gy = k * (Math.cos(Y) * Math.cos(Z) - Math.sin(X) * Math.sin(Y));
        const g = Math.hypot(gx, gy);
        if (g > 0.2 * k) {
          assert.ok(Math.abs(f) / g < 2, `(${p.x}, ${p.y}) is ${Math.abs(f) / g} µm off the surface`);
          n++;
        }
      }
    }
    assert.ok(n > 100);
  }
});

test('gyroid: curves are smooth (no kinks sharper than the surface allows) and long', () => {
  const out = gyroid.generate(
    { layerIndex: 0, zMm: 0.5, layerHeightMm: 0.2, region: TEST_SHAPES.square() },
    testParams(0.2),
  );
  let maxTurn = 0;
  for (const l of out.lines) {
    assert.ok(l.length > 10);
    for (let i = 1; i + 1 < l.length; i++) {
      const a = Math.atan2(l[i].y - l[i - 1].y, l[i].x - l[i - 1].x),
        b = Math.atan2(l[i + 1].y - l[i].y, l[i + 1].x - l[i].x);
      let t = Math.abs(b - a);
      if (t > Math.PI) t = 2 * Math.PI - t;
      maxTurn = Math.max(maxTurn, t);
    }
  }
  assert.ok(maxTurn < Math.PI / 4, `max turn ${maxTurn}`);
});
