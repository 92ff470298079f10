/**
 * The printed objects as the plan names them (for object labels): a unique name, the footprint's convex
 * hull and its centre, from each placed object's vertices.
 */
import type { Mesh } from '../mesh/types.js';
import type { PlanObject } from '../plan/types.js';
import { convexHull } from '../geometry/convex-hull.js';
import type { Pt } from '../geometry/types.js';

export interface PlacedObject {
  name: string;
  /** Placed in bed coordinates, mm. */
  mesh: Mesh;
}

/** Convex hull of the mesh's used vertices in XY (counter-clockwise, monotone chain), mm rounded to µm. */
export function footprintHull(mesh: Mesh): [number, number][] {
  const { positions, indices } = mesh;
  const n = positions.length / 3;
  const used = new Uint8Array(n);
  for (let i = 0; i < indices.length; i++) used[indices[i]] = 1;
  // Akl–Toussaint: the extreme points in eight directions span an octagon whose strict inside holds no hull
  // vertex; only the points outside it are sorted.
  // directions: +x, +x+y, +y, −x+y, −x, −x−y, −y, +x−y
  const ext = new Int32Array(8).fill(-1);
  const best = new Float64Array(8).fill(-Infinity);
  for (let v = 0; v < n; v++) {
    if (!used[v]) continue;
    const x = positions[3 * v],
      y = positions[3 * v + 1];
    const sc0 = x,
      sc1 = x + y,
      sc2 = y,
      sc3 = y - x;
    if (sc0 > best[0]) (best[0] = sc0), (ext[0] = v);
    if (sc1 > best[1]) (best[1] = sc1), (ext[1] = v);
    if (sc2 > best[2]) (best[2] = sc2), (ext[2] = v);
    if (sc3 > best[3]) (best[3] = sc3), (ext[3] = v);
    if (-sc0 > best[4]) (best[4] = -sc0), (ext[4] = v);
    if (-sc1 > best[5]) (best[5] = -sc1), (ext[5] = v);
    if (-sc2 > best[6]) (best[6] = -sc2), (ext[6] = v);
    if (-sc3 > best[7]) (best[7] = -sc3), (ext[7] = v);
  }
  if (ext[0] < 0) return [];
  const oct: [number, number][] = [];
  for (let d = 0; d < 8; d++) {
    const p: [number, number] = [positions[3 * ext[d]], positions[3 * ext[d] + 1]];
    if (!oct.length || oct[oct.length - 1][0] !== p[0] || oct[oct.length - 1][1] !== p[1]) oct.push(p);
  }
  const insideOctagon = (x: number, y: number): boolean => {
    if (oct.length < 3) return false;
    for (let k = 0; k < oct.length; k++) {
      const a = oct[k],
        b = oct[(k + 1) % oct.length];
      if ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]) <= 0) return false;
    }
    return true;
  };
  const pts: Pt[] = [];
  for (let v = 0; v < n; v++) {
    if (!used[v]) continue;
    const x = positions[3 * v],
      y = positions[3 * v + 1];
    if (!insideOctagon(x, y)) pts.push({ x: Math.round(x * 1000) / 1000, y: Math.round(y * 1000) / 1000 });
  }
  return convexHull(pts).map((p): [number, number] => [p.x, p.y]);
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
    let x0 = Infinity,
      y0 = Infinity,
      x1 = -Infinity,
      y1 = -Infinity;
    for (const [x, y] of polygon) {
      x0 = Math.min(x0, x);
      y0 = Math.min(y0, y);
      x1 = Math.max(x1, x);
      y1 = Math.max(y1, y);
    }
    // the centre of the footprint's bounds
    const center: [number, number] = polygon.length
      ? [Math.round(((x0 + x1) / 2) * 1000) / 1000, Math.round(((y0 + y1) / 2) * 1000) / 1000]
      : [0, 0];
    return { name, center, polygon };
  });
}
