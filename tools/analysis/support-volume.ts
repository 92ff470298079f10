/** Extruded volumes by kind of material (from E and the filament's cross-section), and the mesh's own volume. */
import type { Mesh } from '#strata/mesh/types.js';
import type { GcodeLayer } from './gcode-types.js';
import type { LayerFrame } from './model-z.js';
import type { SupportSummary } from './report-types.js';
import { Material, materialOf } from './support-raster.js';

/** Volume enclosed by a closed mesh (mm³): the divergence theorem over its triangles, sign dropped. */
export function meshVolume(mesh: Mesh): number {
  const p = mesh.positions;
  const idx = mesh.indices;
  let six = 0;
  for (let t = 0; t < idx.length; t += 3) {
    const a = 3 * idx[t]!,
      b = 3 * idx[t + 1]!,
      c = 3 * idx[t + 2]!;
    const ax = p[a]!,
      ay = p[a + 1]!,
      az = p[a + 2]!;
    const bx = p[b]!,
      by = p[b + 1]!,
      bz = p[b + 2]!;
    const cx = p[c]!,
      cy = p[c + 1]!,
      cz = p[c + 2]!;
    six += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  }
  return Math.abs(six) / 6;
}

/** Filament volume of every layer's support body, interface, raft and part material. */
export function supportVolumes(
  layers: readonly GcodeLayer[],
  frames: readonly LayerFrame[],
  filamentArea: number,
  modelMm3: number,
): SupportSummary['volume'] {
  const sums = new Float64Array(5);
  for (const layer of layers) {
    const t = layer.extrusions;
    const frame = frames[layer.index]!;
    for (let i = 0; i < t.count; i++) {
      const k = materialOf(t.feature[i]!, frame);
      sums[k] = sums[k]! + t.e[i]!;
    }
  }
  const mm3 = (k: number) => sums[k]! * filamentArea;
  const support = mm3(Material.Support);
  const iface = mm3(Material.Interface);
  const raft = mm3(Material.Raft);
  return {
    supportMm3: support,
    interfaceMm3: iface,
    raftMm3: raft,
    partMm3: mm3(Material.Part),
    modelMm3,
    supportShare: modelMm3 > 0 ? (support + iface) / modelMm3 : null,
    raftShare: modelMm3 > 0 ? raft / modelMm3 : null,
  };
}
