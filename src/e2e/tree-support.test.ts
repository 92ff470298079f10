/**
 * Tree support end to end on the shared support models, judged by the analyser: the overhang held, no part
 * material over nothing, no support in the part, a one- or two-layer top Z gap, and clearly less material than
 * normal support. (Thread-count identity of tree support is in determinism.test.ts.)
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { SupportSummary } from '../analysis/report-types.js';
import { skipWithoutModels, sliceAndAnalyze } from './models.js';

const skip = skipWithoutModels();

async function supportOf(name: string, supportType: 'tree' | 'normal'): Promise<{ s: SupportSummary; gcode: string }> {
  const { report, gcode } = await sliceAndAnalyze(name, { supportEnabled: true, supportType });
  assert.ok(report.summary.support, 'no support report');
  return { s: report.summary.support, gcode };
}

for (const name of ['SupportTest.stl', 'Overhang.stl', 'spot.stl']) {
  test(`${name} with tree support: overhang held, nothing in the part or over air, a 1-2 layer top gap, ≤ 0.75 × normal support's material`, { skip, timeout: 600_000 }, async () => {
    const { s: tree, gcode } = await supportOf(name, 'tree');
    assert.match(gcode, /;TYPE:SUPPORT\n/);
    assert.match(gcode, /;TYPE:SUPPORT-INTERFACE\n/);
    assert.ok((tree.overhangSupported ?? 0) >= 0.95, `overhang supported ${tree.overhangSupported}`);
    assert.ok((tree.overNothing ?? 1) <= 0.003, `part over nothing ${tree.overNothing}`);
    assert.ok(tree.insideAreaMm2 <= 1, `${tree.insideAreaMm2.toFixed(2)} mm² of support inside the part`);
    const gap = tree.topGap.medianLayers;
    assert.ok(gap !== null && gap >= 1 && gap <= 2, `top Z gap ${gap} layers`);
    const { s: normal } = await supportOf(name, 'normal');
    const vt = tree.volume.supportMm3 + tree.volume.interfaceMm3;
    const vn = normal.volume.supportMm3 + normal.volume.interfaceMm3;
    assert.ok(vt > 0.1 * vn && vt <= 0.75 * vn, `tree support ${vt.toFixed(0)} mm³, normal ${vn.toFixed(0)} mm³`);
  });
}
