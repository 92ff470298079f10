/**
 * Whether a prepared mesh holds anything to print: a model whose triangles all have zero area, that
 * lies in one plane, or that is closed but encloses no volume, prints nothing, and saying why is
 * better than G-code that heats, homes and stops.
 */
import type { Mesh, MeshReport } from './types.js';

/** Triangles smaller than this (mm²) count as having no area. */
const ZERO_AREA_MM2 = 1e-9;
/** Vertices this close (mm) to one plane make a flat model. */
const FLAT_MM = 1e-4;
/** A closed mesh whose volume is below this share of its bounding-box diagonal cubed encloses nothing. */
const ZERO_VOLUME_SHARE = 1e-9;

/** Why the mesh gives nothing to print (a phrase after the model's name), or undefined when it may. */
export function nothingToPrint(mesh: Mesh, report: MeshReport): string | undefined {
  const p = mesh.positions;
  const idx = mesh.indices;
  const n = idx.length / 3;
  if (n === 0) return 'has no triangles';
  // the largest triangle fixes a plane to test flatness against
  let best = -1;
  let bestArea2 = 0;
  let nx = 0,
    ny = 0,
    nz = 0;
  for (let t = 0; t < idx.length; t += 3) {
    const a = idx[t] * 3,
      b = idx[t + 1] * 3,
      c = idx[t + 2] * 3;
    const ux = p[b] - p[a],
      uy = p[b + 1] - p[a + 1],
      uz = p[b + 2] - p[a + 2];
    const vx = p[c] - p[a],
      vy = p[c + 1] - p[a + 1],
      vz = p[c + 2] - p[a + 2];
    const cx = uy * vz - uz * vy,
      cy = uz * vx - ux * vz,
      cz = ux * vy - uy * vx;
    const area2 = cx * cx + cy * cy + cz * cz;
    if (area2 > bestArea2) {
      bestArea2 = area2;
      best = t;
      nx = cx;
      ny = cy;
      nz = cz;
    }
  }
  if (best < 0 || Math.sqrt(bestArea2) / 2 < ZERO_AREA_MM2) {
    return `has only triangles of zero area (the corners of all ${plural(n, 'triangle')} lie on a line)`;
  }
  const len = Math.sqrt(bestArea2);
  nx /= len;
  ny /= len;
  nz /= len;
  const o = idx[best] * 3;
  const d0 = nx * p[o] + ny * p[o + 1] + nz * p[o + 2];
  let flat = true;
  for (let t = 0; t < idx.length && flat; t++) {
    const v = idx[t] * 3;
    if (Math.abs(nx * p[v] + ny * p[v + 1] + nz * p[v + 2] - d0) > FLAT_MM) flat = false;
  }
  if (flat) return `is flat: its ${plural(n, 'triangle')} lie in one plane, so it has no volume to fill`;
  const diag = Math.hypot(report.max[0] - report.min[0], report.max[1] - report.min[1], report.max[2] - report.min[2]);
  if (report.openEdges === 0 && Math.abs(report.volume) <= ZERO_VOLUME_SHARE * diag ** 3) {
    return `encloses no volume: its ${plural(n, 'triangle')} form a surface with both sides facing out, not a solid`;
  }
  return undefined;
}

function plural(n: number, word: string): string {
  return `${n} ${word}${n === 1 ? '' : 's'}`;
}
