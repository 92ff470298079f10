/**
 * Support under curved, sloping overhangs, end to end on meshes made for the test (curved-shapes.ts): a sphere
 * on the bed, a torus lying flat, a mushroom whose cap widens at 75° from vertical, fins leaning at 55-70° and
 * an arch. The independent
 * analyser holds normal and tree support to the same bars as on the shared models (support-bars.ts): every
 * overhang held, nothing of the part over air, no support inside the part, a one- or two-layer top Z gap.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { arch, leaningFins, mushroom, sphere, torus } from './curved-shapes.js';
import { sliceAndAnalyzeInput } from './models.js';
import { assertSupportBars } from './support-bars.js';
import type { Mesh } from '#strata/mesh/types.js';

/**
 * Each shape, and the most of its overhang the analyser may find held without support: the arch's crown is
 * held from both sides as a bridge within the analyser's span, the others' undersides only where their slope
 * nears the threshold.
 */
const SHAPES: [string, () => Mesh, number][] = [
  ['a sphere of radius 15 mm', () => sphere(15), 0.2],
  ['a torus lying flat (18 mm, tube 6 mm)', () => torus(18, 6), 0.2],
  ['a mushroom', mushroom, 0.2],
  ['fins leaning at 55-70°', leaningFins, 0.2],
  ['an arch 24 mm wide with a 10 mm opening', () => arch(), 0.5],
];

const volumes = new Map<string, number>();

for (const [name, make] of SHAPES) {
  for (const supportType of ['normal', 'tree'] as const) {
    test(`${name}, ${supportType} support: overhangs held, nothing over air, none inside the part, one-layer Z gap`, {
      timeout: 300_000,
    }, async () => {
      const { report, gcode, warnings } = await sliceAndAnalyzeInput(make(), { supportEnabled: true, supportType });
      assert.deepEqual(warnings, [], 'the mesh is closed and faces outwards');
      assert.match(gcode, /;TYPE:SUPPORT\n/);
      const area = report.summary.support?.overhangAreaMm2 ?? 0;
      assert.ok(area > 50, `an overhang to hold: ${area} mm²`);
      volumes.set(`${name} ${supportType}`, assertSupportBars(report));
    });
  }
}

test('without support the curved overhangs are not held (the measure discriminates)', {
  timeout: 300_000,
}, async () => {
  for (const [name, make, heldWithout] of SHAPES) {
    const { report } = await sliceAndAnalyzeInput(make(), { supportEnabled: false });
    const sup = report.summary.support!;
    assert.ok(
      sup.overhangSupported !== null && sup.overhangSupported < heldWithout,
      `${name}: overhang supported ${sup.overhangSupported}`,
    );
  }
});

// Tests in a file run one after another: the runs above have filled `volumes`.
test('under every shape (the mushroom tall under a wide cap, the sphere and the torus low and sloping, the leaning fins, the arch) tree support uses at most 0.75 × the material of normal', () => {
  for (const [name] of SHAPES) {
    const tree = volumes.get(`${name} tree`);
    const normal = volumes.get(`${name} normal`);
    assert.ok(tree !== undefined && normal !== undefined, `${name}: both support runs passed`);
    assert.ok(
      tree > 0.1 * normal && tree <= 0.75 * normal,
      `${name}: tree ${tree.toFixed(0)} mm³, normal ${normal.toFixed(0)} mm³`,
    );
  }
});

test("a torus whose only overhang is its second layer (23 mm, tube 5.7 mm, 24 sides round the tube, as PrusaSlicer's gallery torus): both kinds hold it from the first layer, with no Z gap, where there is no room for one", {
  timeout: 300_000,
}, async () => {
  const low = () => torus(11.44, 2.83, 64, 24);
  const without = (await sliceAndAnalyzeInput(low(), { supportEnabled: false })).report.summary.support!;
  assert.ok(
    without.overhangAreaMm2 > 20 && without.overhangSupported !== null && without.overhangSupported < 0.2,
    `without support: ${without.overhangSupported} of ${without.overhangAreaMm2} mm² held`,
  );
  for (const supportType of ['normal', 'tree'] as const) {
    const { report } = await sliceAndAnalyzeInput(low(), { supportEnabled: true, supportType });
    const sup = report.summary.support!;
    assert.ok(
      sup.overhangSupported !== null && sup.overhangSupported >= 0.95,
      `${supportType}: overhang supported ${sup.overhangSupported}`,
    );
    assert.ok(
      sup.overNothing !== null && sup.overNothing <= 0.003,
      `${supportType}: model over nothing ${sup.overNothing}`,
    );
    assert.ok(sup.insideAreaMm2 <= 1, `${supportType}: support inside the part ${sup.insideAreaMm2} mm²`);
    // every overhang is the second layer's: its support is on the first layer, right under it
    assert.equal(sup.topGap.areaMm2, 0, `${supportType}: no overhang above the second layer`);
    assert.equal(sup.topGapOverFirstLayer.medianLayers, 0, `${supportType}: support right under the second layer`);
  }
});
