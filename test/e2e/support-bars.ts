/** Test-only: the bars every end-to-end support print is held to, judged by the analyser's report. */
import assert from 'node:assert/strict';
import type { PrintReport } from '../../tools/analysis/checks.js';

/**
 * Every overhang held (≥ 95 %), the part over nothing ≤ 0.3 %, support inside the part ≤ 1 mm², a one- or
 * two-layer top Z gap, and the part itself whole (walls ≥ 97 % of the outline, nothing outside the model).
 * Returns the support's volume (support and interface), mm³.
 */
export function assertSupportBars(report: PrintReport): number {
  const s = report.summary;
  const sup = s.support!;
  assert.ok(sup, 'support checks ran');
  assert.ok(
    sup.overhangSupported !== null && sup.overhangSupported >= 0.95,
    `overhang supported ${sup.overhangSupported}`,
  );
  assert.ok(sup.overNothing !== null && sup.overNothing <= 0.003, `model over nothing ${sup.overNothing}`);
  assert.ok(
    sup.insideAreaMm2 <= 1,
    `support inside the part ${sup.insideAreaMm2} mm² (worst layer ${sup.insideWorstLayer})`,
  );
  assert.ok(
    sup.topGap.medianLayers === 1 || sup.topGap.medianLayers === 2,
    `top gap ${sup.topGap.medianLayers} layers`,
  );
  assert.ok(s.walls.coverage !== null && s.walls.coverage >= 0.97, `outline coverage ${s.walls.coverage}`);
  assert.ok(s.outside.p99Mm <= 0.1, `material outside the model: p99 ${s.outside.p99Mm} mm`);
  return sup.volume.supportMm3 + sup.volume.interfaceMm3;
}
