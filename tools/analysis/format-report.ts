/** A human-readable summary of a PrintReport. */
import type { GapStats, PrintReport, SupportSummary } from './report-types.js';

const pct = (v: number | null) => (v === null ? 'n/a' : `${(v * 100).toFixed(1)} %`);
const mm = (v: number | null, digits = 3) => (v === null ? 'n/a' : `${v.toFixed(digits)} mm`);
const list = (xs: number[]) => (xs.length === 0 ? 'none' : xs.join(', '));

export function formatReport(report: PrintReport): string {
  const s = report.summary;
  const lines: string[] = [];
  lines.push(
    `layers: ${s.layerCount} printed, ${s.expectedLayerCount} expected; first at ${mm(s.firstLayerZ)}; ` +
      `off-grid Z: ${s.zMismatchCount}${s.zMismatchCount > 0 ? ` (layers ${list(s.zMismatchLayers)})` : ''}; ` +
      `missing: ${s.missingLayerCount}` +
      (s.missingLayerCount > 0 ? ` (Z ${s.missingLayerZ.map((z) => z.toFixed(2)).join(', ')})` : ''),
  );
  lines.push(`analysed layers: ${s.analysedLayers} (cell ${s.cellSizeMm.toFixed(3)} mm)`);
  lines.push(
    `walls: outline coverage ${pct(s.walls.coverage)}, worst ${pct(s.walls.minCoverage)}` +
      (s.walls.worstLayer !== null ? ` (layer ${s.walls.worstLayer})` : '') +
      `; layers below threshold: ${list(s.walls.layersBelowThreshold)}`,
  );
  lines.push(
    `outside: max ${mm(s.outside.maxMm)}, p99 ${mm(s.outside.p99Mm)}, area ${s.outside.areaMm2.toFixed(2)} mm²` +
      (s.outside.worstLayer !== null && s.outside.maxMm > 0 ? ` (worst layer ${s.outside.worstLayer})` : '') +
      (s.outside.emptySectionLayers.length > 0
        ? `; material on ${s.outside.emptySectionLayers.length} layers without model ` +
          `(${s.outside.materialOnEmptySectionMm.toFixed(1)} mm)`
        : ''),
  );
  const skin = (name: string, k: typeof s.skin.top) =>
    `${name} ${pct(k.coverage)} of ${k.areaMm2.toFixed(1)} mm², worst ${pct(k.minCoverage)}` +
    (k.worstLayer !== null ? ` (layer ${k.worstLayer})` : '');
  lines.push(`skin: ${skin('top', s.skin.top)}; ${skin('bottom', s.skin.bottom)}`);
  lines.push(
    `infill: density ${pct(s.infill.density)} (range ${pct(s.infill.minDensity)}–${pct(s.infill.maxDensity)}) ` +
      `over ${s.infill.layersMeasured} layers, ${s.infill.regionAreaMm2.toFixed(0)} mm²`,
  );
  lines.push(
    `shift: max ${mm(s.shift.maxMm)}` +
      (s.shift.worstLayer !== null ? ` (layer ${s.shift.worstLayer})` : '') +
      `; shifted layers: ${list(s.shift.shiftedLayers)}`,
  );
  const e = s.e;
  lines.push(
    `E (${e.mode}): extruded ${e.extruded.toFixed(2)} mm, retracted ${e.retracted.toFixed(2)}, primed ` +
      `${e.primed.toFixed(2)}, net ${e.net.toFixed(2)}; retractions ${s.retractionCount}, unbalanced ` +
      `${e.balance.unbalanced}${e.balance.unbalanced > 0 ? ` (lines ${list(e.balance.unbalancedLines)})` : ''}, ` +
      `trailing ${e.balance.trailingMm.toFixed(2)} mm`,
  );
  const ratio = e.flowRatio === null ? 'n/a' : e.flowRatio.toFixed(2);
  lines.push(`bead width: median ${mm(e.widthMedianMm)}, ${ratio}× nominal`);
  const features = Object.entries(s.featureLengthMm)
    .map(([k, v]) => `${k} ${(v / 1000).toFixed(2)} m`)
    .join(', ');
  lines.push(
    `lengths: ${features || 'none'}; travel ${(s.travelLengthMm / 1000).toFixed(2)} m` +
      (s.preambleExtrusionMm > 0 ? `; preamble extrusion ${s.preambleExtrusionMm.toFixed(1)} mm` : ''),
  );
  const z = s.modelZ;
  if (z.source !== 'none' || z.raftLayerCount > 0) {
    lines.push(
      `model Z offset: ${mm(z.offsetMm)} (${z.source}); raft layers ${z.raftLayerCount}` +
        (z.raftGapMm !== null ? `, air gap ${mm(z.raftGapMm)}` : '') +
        (z.firstModelLayer !== null ? `; first model layer ${z.firstModelLayer}` : ''),
    );
  }
  if (s.support) lines.push(...formatSupport(s.support));
  lines.push(`time: parse ${s.timingMs.parse.toFixed(0)} ms, analyse ${s.timingMs.analyse.toFixed(0)} ms`);
  for (const w of report.warnings) lines.push(`warning: ${w}`);
  return lines.join('\n');
}

const mm2 = (v: number) => `${v.toFixed(1)} mm²`;

function gap(g: GapStats): string {
  if (g.medianMm === null) return 'not measured';
  const shares = g.byLayers
    .map((v, k) => (v >= 0.005 ? `${k === g.byLayers.length - 1 ? `${k}+` : k}: ${(v * 100).toFixed(0)} %` : ''))
    .filter((x) => x !== '')
    .join(', ');
  const layers = (n: number | null) => `${n} layer${n === 1 ? '' : 's'}`;
  return (
    `median ${mm(g.medianMm, 2)} (${layers(g.medianLayers)}), low ${mm(g.minMm, 2)} (${layers(g.minLayers)}) ` +
    `over ${mm2(g.areaMm2)}; by layers ${shares}`
  );
}

/** The support section of the report. */
export function formatSupport(u: SupportSummary): string[] {
  const worstOverhang = u.overhangWorstLayers
    .map((w) => `${w.layer} (${w.unsupportedMm2.toFixed(1)} of ${w.areaMm2.toFixed(1)})`)
    .join(', ');
  const worstNothing = u.overNothingWorstLayers
    .map((w) => `${w.layer} (${w.areaMm2.toFixed(1)}, ${pct(w.fraction)})`)
    .join(', ');
  const v = u.volume;
  return [
    `support: overhang (${u.overhangAngleDeg}° from vertical) ${mm2(u.overhangAreaMm2)}, supported ` +
      `${pct(u.overhangSupported)}` +
      (worstOverhang ? `; most unsupported at layers ${worstOverhang}` : ''),
    `  model over nothing: ${pct(u.overNothing)} of ${mm2(u.partAreaMm2)} part extrusion (${mm2(u.overNothingMm2)})` +
      (worstNothing ? `; worst layers ${worstNothing}` : ''),
    `  support inside the part: ${mm2(u.insideAreaMm2)}` +
      (u.insideWorstLayer !== null ? ` (worst layer ${u.insideWorstLayer}: ${mm2(u.insideWorstMm2)})` : '') +
      ` of ${mm2(u.supportAreaMm2)} support on ${u.supportLayers} layers`,
    `  top Z gap: ${gap(u.topGap)}`,
    ...(u.topGapOverFirstLayer.areaMm2 > 0
      ? [`  top Z gap under the second layer (no room for one over the first): ${gap(u.topGapOverFirstLayer)}`]
      : []),
    `  bottom Z gap: ${gap(u.bottomGap)}`,
    `  volume: support ${v.supportMm3.toFixed(0)} mm³ + interface ${v.interfaceMm3.toFixed(0)} mm³ = ` +
      `${pct(v.supportShare)} of the model's ${v.modelMm3.toFixed(0)} mm³; raft ${v.raftMm3.toFixed(0)} mm³` +
      (v.raftMm3 > 0 ? ` (${pct(v.raftShare)})` : '') +
      `; part extruded ${v.partMm3.toFixed(0)} mm³`,
  ];
}

/** One line per analysed layer with support measures (areas in mm²). */
export function formatLayerSupport(report: PrintReport): string {
  const lines = ['layer z role: overhang supported | part over-nothing | support inside'];
  for (const l of report.layers) {
    const u = l.support;
    if (!u) continue;
    if (u.overhangAreaMm2 === 0 && u.overNothingMm2 === 0 && u.supportAreaMm2 === 0) continue;
    lines.push(
      `${l.index} ${l.z.toFixed(3)} ${l.role}: ` +
        `${u.overhangAreaMm2.toFixed(2)} ${u.overhangSupportedMm2.toFixed(2)} | ` +
        `${u.partAreaMm2.toFixed(1)} ${u.overNothingMm2.toFixed(2)} | ${u.supportAreaMm2.toFixed(1)} ` +
        `${u.insideMm2.toFixed(2)}`,
    );
  }
  return lines.join('\n');
}
