/**
 * Support, raft and bridges end to end, judged by the independent analyser: every overhang held, nothing of
 * the part printed over air, no support inside the part, the top Z gap as set; the quality bars of the part
 * itself hold with support on.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { skipWithoutModels, sliceAndAnalyze } from './models.js';
import { assertSupportBars } from './support-bars.js';

const skip = skipWithoutModels();
const MODELS = ['SupportTest.stl', 'Overhang.stl', 'spot.stl'] as const;

const volumes = new Map<string, number>();

for (const name of MODELS) {
  for (const supportType of ['normal', 'tree'] as const) {
    test(`${name}, ${supportType} support: overhangs held, nothing over air, none inside the part, one-layer Z gap`, {
      skip,
      timeout: 600_000,
    }, async () => {
      const { report, gcode } = await sliceAndAnalyze(name, { supportEnabled: true, supportType });
      assert.match(gcode, /;TYPE:SUPPORT\n/);
      assert.match(gcode, /;TYPE:SUPPORT-INTERFACE\n/);
      volumes.set(`${name} ${supportType}`, assertSupportBars(report));
      // E balanced
      assert.equal(report.summary.e.balance.unbalanced, 0);
    });
  }
}

// Tests in a file run one after another: the six above have filled `volumes`.
test('tree support uses clearly less material than normal support for the same overhangs (≤ 0.75 ×)', { skip }, () => {
  for (const name of MODELS) {
    const tree = volumes.get(`${name} tree`);
    const normal = volumes.get(`${name} normal`);
    assert.ok(tree !== undefined && normal !== undefined, `${name}: both support runs passed`);
    assert.ok(
      tree > 0.1 * normal && tree <= 0.75 * normal,
      `${name}: tree ${tree.toFixed(0)} mm³, normal ${normal.toFixed(0)} mm³`,
    );
  }
});

test('the Stanford bunny (an open scan): support holds its overhangs and stays out of the part, trees with less material', {
  skip,
  timeout: 600_000,
}, async () => {
  // its first layer has support and no part (the base is open): the analyser is told there is no raft
  const volume: Record<string, number> = {};
  for (const supportType of ['normal', 'tree'] as const) {
    const { report } = await sliceAndAnalyze(
      'stanford-bunny.stl',
      { supportEnabled: true, supportType },
      { modelZOffset: 0 },
    );
    volume[supportType] = assertSupportBars(report);
  }
  assert.ok(
    volume.tree <= 0.75 * volume.normal,
    `tree ${volume.tree.toFixed(0)} mm³, normal ${volume.normal.toFixed(0)} mm³`,
  );
});

test('CalibrationCube: the tops of its engraved letters get from tree support what normal support gives them, not branches from the bed', {
  skip,
  timeout: 300_000,
}, async () => {
  // the recesses are 1 mm deep: a tip fits only at a recess's mouth and used to run 15 mm down to the bed
  // outside the face (24 mm³ against normal support's 1)
  const volume: Record<string, number> = {};
  for (const supportType of ['normal', 'tree'] as const) {
    const { report } = await sliceAndAnalyze('CalibrationCube.stl', { supportEnabled: true, supportType });
    volume[supportType] = assertSupportBars(report);
  }
  assert.ok(
    volume.tree <= volume.normal + 0.5,
    `tree ${volume.tree.toFixed(1)} mm³, normal ${volume.normal.toFixed(1)} mm³`,
  );
});

test('without support the overhangs of SupportTest are not held (the measure discriminates)', {
  skip,
  timeout: 300_000,
}, async () => {
  const { report } = await sliceAndAnalyze('SupportTest.stl', { supportEnabled: false });
  const sup = report.summary.support!;
  assert.ok(
    sup.overhangSupported !== null && sup.overhangSupported < 0.2,
    `overhang supported ${sup.overhangSupported}`,
  );
  assert.ok(sup.overNothing !== null && sup.overNothing > 0.01, `model over nothing ${sup.overNothing}`);
});

test('buildPlate placement: nothing stands on the part of SupportTest', { skip, timeout: 300_000 }, async () => {
  const { report } = await sliceAndAnalyze('SupportTest.stl', { supportEnabled: true, supportPlacement: 'buildPlate' });
  const sup = report.summary.support!;
  // about half of SupportTest's overhang lies over its own lower part: only the rest can reach the bed
  assert.ok(
    sup.overhangSupported !== null && sup.overhangSupported > 0.3 && sup.overhangSupported < 0.9,
    `overhang supported ${sup.overhangSupported}`,
  );
  assert.equal(sup.bottomGap.areaMm2, 0, 'no support starts on the part');
  assert.ok(sup.insideAreaMm2 <= 1);
});

test('buildPlate placement, tree support: the arc of Overhang over its own base is held by trees leaning out to the bed, none standing on the part', {
  skip,
  timeout: 300_000,
}, async () => {
  const tree = (
    await sliceAndAnalyze('Overhang.stl', { supportEnabled: true, supportType: 'tree', supportPlacement: 'buildPlate' })
  ).report.summary.support!;
  assert.ok(
    tree.overhangSupported !== null && tree.overhangSupported >= 0.95,
    `tree: overhang supported ${tree.overhangSupported}`,
  );
  assert.ok(tree.overNothing !== null && tree.overNothing <= 0.003, `tree: over nothing ${tree.overNothing}`);
  assert.equal(tree.bottomGap.areaMm2, 0, 'no support starts on the part');
  assert.ok(tree.insideAreaMm2 <= 1);
  // straight columns reach the bed only beside the base
  const normal = (await sliceAndAnalyze('Overhang.stl', { supportEnabled: true, supportPlacement: 'buildPlate' }))
    .report.summary.support!;
  assert.ok(
    normal.overhangSupported !== null && normal.overhangSupported < 0.5,
    `normal: overhang supported ${normal.overhangSupported}`,
  );
});

test('a raft under the calibration cube: the model raised by the raft and its gap, its walls and skin as without', {
  skip,
  timeout: 300_000,
}, async () => {
  const { report, layers } = await sliceAndAnalyze('CalibrationCube.stl', { adhesionType: 'raft' });
  const s = report.summary;
  assert.equal(layers, 104, 'four raft layers under the 100 of the cube');
  assert.equal(s.modelZ.source, 'detected');
  assert.ok(Math.abs(s.modelZ.offsetMm - 1.1) < 0.01, `model raised by ${s.modelZ.offsetMm} mm`);
  assert.equal(s.modelZ.raftLayerCount, 4);
  assert.ok(s.support!.volume.raftMm3 > 100, `raft volume ${s.support!.volume.raftMm3} mm³`);
  assert.ok(s.walls.coverage !== null && s.walls.coverage >= 0.97, `walls ${s.walls.coverage}`);
  assert.ok(s.skin.bottom.coverage !== null && s.skin.bottom.coverage >= 0.99, `bottom skin ${s.skin.bottom.coverage}`);
  assert.equal(s.outside.emptySectionLayers.length, 0);
});
