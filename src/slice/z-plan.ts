/**
 * The plate's Z plan from the print's settings: even layers (planLayers), or varying ones (planVaryingLayers)
 * where adaptive layer height is on, an object has a layer height profile or a layer range sets its own
 * layerHeight.
 *
 * A layer whose bottom lies in a range [fromZ, toZ) that sets a height is that thick (a later range wins,
 * as for every range setting); elsewhere it is a layer height profile's height (PrusaSlicer's variable layer
 * height, within minLayerHeight and maxLayerHeight), adaptive's height, or layerHeight. A layer that would cross a
 * range's start or end is cut short there (when that leaves it 0.02 mm at least), so a range begins and
 * ends on a layer boundary.
 */
import type { Mesh } from '../mesh/types.js';
import { adaptiveHeights, cuspFor } from './adaptive.js';
import { planLayers, planVaryingLayers } from './layers.js';
import type { LayerZ } from './types.js';

/** Layers thinner than this (µm) are not made to end a layer on a range boundary. */
const MIN_CUT_UM = 20;

export interface ZPlanSettings {
  firstLayerHeight: number;
  layerHeight: number;
  adaptiveLayerHeight: boolean;
  minLayerHeightMm: number;
  maxLayerHeightMm: number;
  adaptiveLayerQuality: number;
  adaptiveLayerStep: number;
}

/** A Z range of the plate with its own layer height, mm. */
export interface HeightRange {
  fromZ: number;
  toZ: number;
  layerHeight: number;
}

/**
 * Plan the layers of a plate whose parts are these meshes (bed coordinates, bottom at z = 0) and whose top
 * is at `modelHeight`. With adaptive off and no ranges this is `planLayers`, layer for layer.
 */
export function planPlateLayers(
  modelHeight: number,
  cfg: ZPlanSettings,
  meshes: readonly Mesh[],
  ranges: readonly HeightRange[] = [],
  profile: readonly number[] | null = null,
): LayerZ[] {
  if (!cfg.adaptiveLayerHeight && ranges.length === 0 && !profile)
    return planLayers(modelHeight, cfg.firstLayerHeight, cfg.layerHeight);
  const um = (mm: number) => Math.round(mm * 1000);
  const stepUm = um(cfg.layerHeight);
  const minUm = um(cfg.minLayerHeightMm),
    maxUm = um(cfg.maxLayerHeightMm);
  // a profile is the layers' own heights (PrusaSlicer's variable layer height): it stands for adaptive
  const fromProfile = profile
    ? (bottomUm: number) => Math.min(maxUm, Math.max(minUm, Math.round(profileAt(profile, bottomUm / 1000) * 1000)))
    : null;
  const adaptive =
    fromProfile ??
    (cfg.adaptiveLayerHeight
      ? adaptiveHeights(meshes, {
          minUm,
          maxUm,
          cuspUm: cuspFor(cfg.minLayerHeightMm, cfg.maxLayerHeightMm, cfg.adaptiveLayerQuality) * 1000,
          stepUm: Math.max(1, um(cfg.adaptiveLayerStep)),
        })
      : null);
  const rs = ranges
    .map((r) => ({ from: um(r.fromZ), to: um(r.toZ), h: um(r.layerHeight) }))
    .filter((r) => r.to > r.from && r.h >= 1);
  const bounds = [...new Set(rs.flatMap((r) => [r.from, r.to]))].sort((a, b) => a - b);
  return planVaryingLayers(modelHeight, cfg.firstLayerHeight, (bottom, prev) => {
    let h = -1;
    for (let k = rs.length - 1; k >= 0 && h < 0; k--) if (bottom >= rs[k].from && bottom < rs[k].to) h = rs[k].h;
    if (h < 0) h = adaptive ? adaptive(bottom, prev) : stepUm;
    for (const b of bounds) {
      if (b <= bottom) continue;
      if (b < bottom + h && b - bottom >= MIN_CUT_UM) h = b - bottom;
      break;
    }
    return h;
  });
}

/** The height a profile (z0, h0, z1, h1, …) gives at z: linear between its points, its ends' beyond them. */
export function profileAt(profile: readonly number[], z: number): number {
  const n = profile.length / 2;
  if (z <= profile[0]) return profile[1];
  for (let k = 1; k < n; k++) {
    const z1 = profile[2 * k];
    if (z < z1) {
      const z0 = profile[2 * k - 2],
        h0 = profile[2 * k - 1],
        h1 = profile[2 * k + 1];
      return h0 + ((h1 - h0) * (z - z0)) / (z1 - z0);
    }
  }
  return profile[2 * n - 1];
}
