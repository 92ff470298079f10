/**
 * The other way: Strata settings in PrusaSlicer's keys, for a project 3MF that PrusaSlicer opens with its
 * objects' and volumes' settings. Only the settings objects, modifiers and layer ranges commonly override,
 * each read back by slic3r-keys.ts as the value it came from; Strata's own copy in the project keeps
 * everything else.
 */
import type { PatternId } from '../infill/types.js';
import { LAYER_SHARE_EPS } from '../geometry/tolerances.js';

const PATTERNS: Readonly<Record<PatternId, string>> = {
  grid: 'grid',
  lines: 'rectilinear',
  triangles: 'triangles',
  hexagons: 'honeycomb',
  cubic: 'cubic',
  concentric: 'concentric',
  gyroid: 'gyroid',
  spiral: 'archimedeanchords',
  lightning: 'lightning',
};

const num = (v: unknown): number | undefined => (typeof v === 'number' && Number.isFinite(v) ? v : undefined);

/**
 * PrusaSlicer keys and values for the Strata settings in `settings` that have one. `layerHeight` (mm) turns
 * a skin thickness into PrusaSlicer's layer count (with the thickness as its minimum, so it is kept).
 */
export function toSlic3rKeys(settings: Readonly<Record<string, unknown>>, layerHeight: number): Record<string, string> {
  const out: Record<string, string> = {};
  const s = settings;
  if (num(s.layerHeight) !== undefined) out.layer_height = String(s.layerHeight);
  if (num(s.infillDensity) !== undefined) out.fill_density = `${s.infillDensity}%`;
  if (typeof s.infillPattern === 'string' && Object.hasOwn(PATTERNS, s.infillPattern))
    out.fill_pattern = PATTERNS[s.infillPattern as PatternId];
  if (num(s.infillAngle) !== undefined) out.fill_angle = String(s.infillAngle);
  if (num(s.wallCount) !== undefined) out.perimeters = String(s.wallCount);
  const lh = num(s.layerHeight) ?? layerHeight;
  for (const [setting, side] of [
    ['topSkinThickness', 'top'],
    ['bottomSkinThickness', 'bottom'],
  ] as const) {
    const t = num(s[setting]);
    if (t === undefined) continue;
    // whole layers that fit, the thickness as the minimum: slic3r-keys.ts reads back max(layers × height, minimum)
    out[`${side}_solid_layers`] = String(t > 0 ? Math.max(1, Math.floor(t / lh + LAYER_SHARE_EPS)) : 0);
    out[`${side}_solid_min_thickness`] = String(t);
  }
  // written only when on, so a project without the vase is written as before
  if (s.spiralVase === true) out.spiral_vase = '1';
  if (typeof s.supportEnabled === 'boolean') out.support_material = s.supportEnabled ? '1' : '0';
  return out;
}
