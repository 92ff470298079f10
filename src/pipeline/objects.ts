/**
 * The printed objects as the plan names them (for object labels): a unique name, the footprint's convex
 * hull and its centre, from each placed object's vertices.
 */
import type { Mesh } from '../mesh/types.js';
import type { PlanObject } from '../plan/types.js';

export interface PlacedObject {
  name: string;
  /** Placed in bed coordinates, mm. */
  mesh: Mesh;
}

function cross(o: [number, number], a: [number, number], b: [number, number]): number {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/** Convex hull of the mesh's used vertices in XY (counter-clockwise, monotone chain), mm rounded to µm. */
export function footprintHull(mesh: Mesh): [number, number][] {
  const { positions, indices } = mesh;
  const seen = new Set<number>();
  const pts: [number, number][] = [];
  for (let i = 0; i < indices.length; i++) {
    const v = indices[i];
    if (seen.has(v)) continue;
    seen.add(v);
    pts.push([Math.round(positions[3 * v] * 1000) / 1000, Math.round(positions[3 * v + 1] * 1000) / 1000]);
  }
  pts.sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  if (pts.length < 3) return pts;
  const lower: [number, number][] = [];
  for (const p of pts) {
    while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], p) <= 0) lower.pop();
    lower.push(p);
  }
  const upper: [number, number][] = [];
  for (let i = pts.length - 1; i >= 0; i--) {
    const p = pts[i];
    while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], p) <= 0) upper.pop();
    upper.push(p);
  }
  lower.pop();
  upper.pop();
  return lower.concat(upper);
}

/** The plan's objects, names made safe for G-code (letters, digits, `_.-`) and unique (`_2`, `_3`…). */
export function planObjects(objects: readonly PlacedObject[]): PlanObject[] {
  const used = new Set<string>();
  return objects.map((o) => {
    const base = (o.name || 'object').replace(/[^A-Za-z0-9_.-]+/g, '_').replace(/^_+|_+$/g, '') || 'object';
    let name = base;
    for (let k = 2; used.has(name); k++) name = `${base}_${k}`;
    used.add(name);
    const polygon = footprintHull(o.mesh);
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (const [x, y] of polygon) {
      x0 = Math.min(x0, x);
      y0 = Math.min(y0, y);
      x1 = Math.max(x1, x);
      y1 = Math.max(y1, y);
    }
    // the centre of the footprint's bounds
    const center: [number, number] = polygon.length ? [Math.round(((x0 + x1) / 2) * 1000) / 1000, Math.round(((y0 + y1) / 2) * 1000) / 1000] : [0, 0];
    return { name, center, polygon };
  });
}
