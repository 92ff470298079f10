import { test } from 'node:test';
import assert from 'node:assert/strict';
import { generateInfill } from '#strata/infill/generate.js';
import { indexRegion, nearestBoundary, regionGeom } from '#strata/infill/region-index.js';
import { TEST_SHAPES, testParams } from '../test-shapes.js';

test('concentric: loops keep at least ~0.4 spacings from the boundary and are linked into few paths', () => {
  for (const region of Object.values(TEST_SHAPES).map((f) => f())) {
    const params = testParams(0.3);
    const s = params.lineWidthUm / params.density;
    const r = generateInfill('concentric', { layerIndex: 0, zMm: 0.2, layerHeightMm: 0.2, region }, params);
    const ix = indexRegion(regionGeom(region));
    for (const p of [...r.lines.flat(), ...r.loops.flat()]) {
      const nb = nearestBoundary(ix, p.x, p.y, 0.3 * s);
      assert.equal(nb, null, `(${p.x}, ${p.y}) is ${nb?.dist} µm from the boundary`);
    }
    const unlinked = generateInfill(
      'concentric',
      { layerIndex: 0, zMm: 0.2, layerHeightMm: 0.2, region },
      testParams(0.3, { connect: false }),
    );
    assert.ok(r.lines.length + r.loops.length < unlinked.lines.length + unlinked.loops.length);
  }
});
