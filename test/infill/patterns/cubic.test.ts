import { test } from 'node:test';
import assert from 'node:assert/strict';
import { cubic, cubicSpacing } from '#strata/infill/patterns/cubic.js';
import { TEST_SHAPES, testParams } from '../test-shapes.js';

test('cubic: three families 120° apart, shifted along their normals by z/√2', () => {
  const params = testParams(0.2);
  const at = (z: number) =>
    cubic.generate({ layerIndex: 0, zMm: z, layerHeightMm: 0.2, region: TEST_SHAPES.square() }, params).sweeps!;
  const a = at(1.0),
    b = at(2.0);
  assert.deepEqual(
    a.map((s) => s.angle - a[0].angle),
    [0, 120, 240],
  );
  for (let k = 0; k < 3; k++) {
    assert.equal(a[k].spacingUm, cubicSpacing(params));
    assert.ok(Math.abs(b[k].offsetUm - a[k].offsetUm - 1000 / Math.SQRT2) < 1e-6);
  }
  // one Z period later the pattern repeats exactly (three shifts add up to one spacing)
  const period = cubic.zPeriodMm!(params);
  const c = at(1.0 + period);
  const s = a[0].spacingUm;
  for (let k = 0; k < 3; k++) {
    const d = ((c[k].offsetUm - a[k].offsetUm) * 3) / s;
    assert.ok(Math.abs(d - Math.round(d)) < 1e-6);
  }
});
