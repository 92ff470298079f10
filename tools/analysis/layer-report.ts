/** The per-layer part of the report: grid Z, feature and travel lengths, and the raster measures. */
import type { FeatureName } from './feature-names.js';
import { FEATURE_NAMES } from './feature-names.js';
import type { GcodeLayer } from './gcode-types.js';
import type { LayerMeasure, ResolvedOptions } from './layer-analysis.js';
import type { LayerFrame } from './model-z.js';
import { segmentLength } from './raster.js';
import type { LayerReport } from './report-types.js';

/** The nearest Z of the layer grid (firstLayerHeight, then every layerHeight) and its grid index. */
export function gridZ(z: number, o: ResolvedOptions): [number, number] {
  const k = Math.max(0, Math.round((z - o.firstLayerHeight) / o.layerHeight));
  return [o.firstLayerHeight + k * o.layerHeight, k];
}

/** Layers whose mid-height lies below the model top: the first at firstLayerHeight/2, then every layerHeight. */
export function expectedLayerCount(zTop: number, o: ResolvedOptions): number {
  if (!(zTop > o.firstLayerHeight / 2)) return 0;
  const x = (zTop - o.firstLayerHeight) / o.layerHeight + 0.5;
  return 1 + Math.max(0, Math.ceil(x - 1e-9) - 1);
}

export function featureLengths(layer: GcodeLayer): Partial<Record<FeatureName, number>> {
  const sums = new Float64Array(FEATURE_NAMES.length);
  const t = layer.extrusions;
  for (let i = 0; i < t.count; i++) sums[t.feature[i]!] = sums[t.feature[i]!]! + segmentLength(t, i);
  const out: Partial<Record<FeatureName, number>> = {};
  sums.forEach((v, k) => {
    if (v > 0) out[FEATURE_NAMES[k]!] = v;
  });
  return out;
}

export function travelLength(layer: GcodeLayer): number {
  const t = layer.travels;
  let sum = 0;
  for (let i = 0; i < t.count; i++) {
    sum += Math.hypot(t.x1[i]! - t.x0[i]!, t.y1[i]! - t.y0[i]!, t.z1[i]! - t.z0[i]!);
  }
  return sum;
}

export const orNull = (v: number) => (Number.isFinite(v) ? v : null);

/**
 * With variable layers: whether a part layer's thickness (from the last part layer; the first layer's from
 * the bed, which must be firstLayerHeight) is within the range.
 */
export function thicknessOk(frame: LayerFrame, [min, max]: readonly [number, number], o: ResolvedOptions): boolean {
  const t = frame.partThickness;
  if (!Number.isFinite(t)) return true;
  if (Math.abs(frame.modelZ - t) <= o.zTolerance) return Math.abs(t - o.firstLayerHeight) <= o.zTolerance;
  return t >= min - o.zTolerance && t <= max + o.zTolerance;
}

/** Whether a layer's Z is judged against the layer grid: layers with part material, but not the first over a raft. */
export function onZGrid(frame: LayerFrame): boolean {
  return frame.hasPart && !frame.firstOverRaft;
}

/** What a printed layer holds: part material (perhaps with support), support alone, or raft. */
export function layerRole(frame: LayerFrame): LayerReport['role'] {
  return frame.hasPart ? 'part' : frame.raft ? 'raft' : 'support';
}

export function layerReport(
  layer: GcodeLayer,
  m: LayerMeasure,
  o: ResolvedOptions,
  retractions: number,
  frame: LayerFrame,
): LayerReport {
  // with variable layers a layer's Z is its own; its thickness is judged instead
  const [ez] = o.layerHeightRange ? [frame.modelZ] : gridZ(frame.modelZ, o);
  const zOk =
    !onZGrid(frame) ||
    (o.layerHeightRange ? thicknessOk(frame, o.layerHeightRange, o) : Math.abs(frame.modelZ - ez) <= o.zTolerance);
  const shiftMm = m.shift ? Math.hypot(m.shift.dx, m.shift.dy) : null;
  return {
    index: layer.index,
    z: layer.z,
    modelZ: frame.modelZ,
    role: layerRole(frame),
    thickness: layer.thickness,
    expectedZ: ez,
    zOk,
    marker: layer.marker,
    sectionZ: m.sectionZ,
    sectionAreaMm2: m.sectionAreaMm2,
    sectionEmpty: m.section.segments.count === 0,
    materialAreaMm2: m.materialAreaMm2,
    outlineLengthMm: m.outlineLengthMm,
    thinOutlineMm: m.thinOutlineMm,
    outlineCoverage: orNull(m.outlineCoverage),
    shift: m.shift,
    shiftMm,
    outsideMaxMm: m.outsideMaxMm,
    outsideP99Mm: m.outsideP99Mm,
    outsideAreaMm2: m.outsideAreaMm2,
    topSkin: { areaMm2: m.topAreaMm2, coverage: orNull(m.topCoverage) },
    bottomSkin: { areaMm2: m.bottomAreaMm2, coverage: orNull(m.bottomCoverage) },
    infillRegionAreaMm2: m.infillRegionAreaMm2,
    infillDensity: orNull(m.infillDensity),
    widthMedianMm: orNull(m.widthMedianMm),
    featureLengthMm: featureLengths(layer),
    travelLengthMm: travelLength(layer),
    retractions,
    support: null,
  };
}
