/**
 * End-to-end quality on every shared model, judged by the independent G-code analyser with the
 * profile of the quality bar: 0.2 mm layers, 2 walls, 0.8 mm top and bottom, 20 % grid.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { MODEL_FILES, skipWithoutModels, sliceAndAnalyze } from './models.js';

const skip = skipWithoutModels();

for (const name of MODEL_FILES) {
  test(`${name}: layers, walls, nothing outside, E balanced`, { skip, timeout: 300_000 }, async () => {
    const { report, layers } = await sliceAndAnalyze(name);
    const s = report.summary;
    assert.equal(layers, s.expectedLayerCount, 'layers planned');
    // the top layer may hold only a section narrower than one line, which no slicer prints
    assert.ok(
      s.layerCount === s.expectedLayerCount || s.layerCount === s.expectedLayerCount - 1,
      `layers printed ${s.layerCount}`,
    );
    assert.equal(s.firstLayerZ, 0.2, 'first layer printed at its own height');
    assert.equal(s.zMismatchCount, 0, 'every layer at firstLayerHeight + k·layerHeight');
    assert.ok(s.walls.coverage !== null && s.walls.coverage >= 0.97, `outline coverage ${s.walls.coverage}`);
    assert.ok(s.outside.p99Mm <= 0.1, `material outside the model: p99 ${s.outside.p99Mm} mm`);
    assert.equal(s.outside.emptySectionLayers.length, 0, 'no material where the model has no section');
    assert.equal(s.e.balance.unbalanced, 0, 'every retraction primed before extruding');
    assert.equal(s.shift.shiftedLayers.length, 0, 'no layer shifted');
    // the quality bar: top and bottom skin cover ≥ 99 % of exposed surfaces. The bunny scan is open at its
    // base, where the analyser closes the cut contours into solid that the slicer (like PrusaSlicer and
    // CuraEngine) reads as open; above its base it is held to the same bar in the test below
    if (name !== 'stanford-bunny.stl') {
      assert.ok(s.skin.top.coverage === null || s.skin.top.coverage >= 0.99, `top skin ${s.skin.top.coverage}`);
      assert.ok(
        s.skin.bottom.coverage === null || s.skin.bottom.coverage >= 0.99,
        `bottom skin ${s.skin.bottom.coverage}`,
      );
    }
    // density is judged where there is enough sparse region for it to mean something: 20 ± 1 %
    if (s.infill.regionAreaMm2 >= 500) {
      assert.ok(
        s.infill.density !== null && Math.abs(s.infill.density - 0.2) <= 0.01,
        `sparse density ${s.infill.density}`,
      );
    }
  });
}

test('calibration cube: bottom and top skin solid', { skip }, async () => {
  const { report } = await sliceAndAnalyze('CalibrationCube.stl');
  const { top, bottom } = report.summary.skin;
  assert.ok(bottom.coverage !== null && bottom.coverage >= 0.95, `bottom skin ${bottom.coverage}`);
  assert.ok(top.coverage !== null && top.coverage >= 0.95, `top skin ${top.coverage}`);
});

test('stanford bunny above its open base: top and bottom skin ≥ 99 %', { skip, timeout: 300_000 }, async () => {
  const { report } = await sliceAndAnalyze('stanford-bunny.stl');
  // the scan's open base reaches 3 mm up (layer 15): how to close it is a mesh-repair question
  const above = report.layers.filter((l) => l.z > 3.2);
  for (const side of ['topSkin', 'bottomSkin'] as const) {
    let area = 0,
      covered = 0;
    for (const l of above) {
      const m = l[side];
      if (m.coverage === null) continue;
      area += m.areaMm2;
      covered += m.areaMm2 * m.coverage;
    }
    assert.ok(area > 100, `${side}: exposed area ${area} mm²`);
    assert.ok(covered / area >= 0.99, `${side} coverage above the base ${covered / area}`);
  }
});
