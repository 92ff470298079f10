/**
 * Mesh preparation before slicing: weld coincident vertices, drop triangles that repeat a vertex,
 * and report open / non-manifold edges, volume and bounds.
 *
 * Only triangles with a repeated (welded) vertex are removed. Zero-area triangles whose three
 * corners are distinct but collinear are kept: they fill T-junctions, and removing them opens holes
 * (3DBenchy has 11 such slivers; dropping them would leave 29 open edges).
 */
import { StrataError } from '../errors.js';
import type { Mesh, MeshReport } from './types.js';
import { isWelded, weld } from './weld.js';

export interface PreparedMesh {
  mesh: Mesh;
  report: MeshReport;
}

export function prepareMesh(mesh: Mesh): PreparedMesh {
  const welded = isWelded(mesh) ? mesh : weld(mesh.positions, mesh.indices, 'mesh');
  const { mesh: clean, removed } = dropRepeatedCorners(welded);
  const edges = countEdges(clean.indices, clean.positions.length / 3);
  const { min, max } = positionBounds(clean.positions);
  const volume = signedVolume(clean, min, max);
  const triangles = clean.indices.length / 3;
  const report: MeshReport = {
    triangles,
    vertices: clean.positions.length / 3,
    degenerateRemoved: removed,
    openEdges: edges.open,
    nonManifoldEdges: edges.nonManifold,
    volume,
    min,
    max,
    warnings: [],
  };
  const w = report.warnings;
  if (triangles === 0) w.push('the mesh has no triangles');
  if (removed > 0) {
    w.push(`removed ${plural(removed, 'degenerate triangle')} (two corners at the same point)`);
  }
  if (edges.open > 0) {
    w.push(`${plural(edges.open, 'open edge')}: the mesh has holes; slicing closes them as well as it can`);
  }
  if (edges.nonManifold > 0) {
    w.push(
      `${plural(edges.nonManifold, 'non-manifold edge')} (shared by more than two triangles): ` +
        'the surface touches or crosses itself there; slicing may show artefacts',
    );
  }
  if (edges.flipped > 0) {
    w.push(`${plural(edges.flipped, 'edge')} join triangles that face opposite ways: some triangles are flipped`);
  }
  if (triangles > 0 && volume < 0) {
    w.push('the mesh is inside out (negative volume): its triangles face inwards');
  }
  return { mesh: clean, report };
}

function plural(n: number, word: string): string {
  return `${n} ${word}${n === 1 ? '' : 's'}`;
}

/** Remove triangles with a repeated vertex index, then drop vertices no triangle uses. */
function dropRepeatedCorners(mesh: Mesh): { mesh: Mesh; removed: number } {
  const idx = mesh.indices;
  const n = idx.length;
  let removed = 0;
  for (let i = 0; i < n; i += 3) {
    const a = idx[i],
      b = idx[i + 1],
      c = idx[i + 2];
    if (a === b || b === c || a === c) removed++;
  }
  if (removed === 0) return { mesh, removed };

  const kept = new Uint32Array(n - removed * 3);
  const nVerts = mesh.positions.length / 3;
  const remap = new Int32Array(nVerts).fill(-1);
  let k = 0;
  let used = 0;
  for (let i = 0; i < n; i += 3) {
    const a = idx[i],
      b = idx[i + 1],
      c = idx[i + 2];
    if (a === b || b === c || a === c) continue;
    kept[k++] = a;
    kept[k++] = b;
    kept[k++] = c;
  }
  for (let i = 0; i < kept.length; i++) {
    const v = kept[i];
    if (remap[v] < 0) remap[v] = used++;
    kept[i] = remap[v];
  }
  const src = mesh.positions;
  const positions = new Float32Array(used * 3);
  for (let v = 0; v < nVerts; v++) {
    const r = remap[v];
    if (r < 0) continue;
    positions[r * 3] = src[v * 3];
    positions[r * 3 + 1] = src[v * 3 + 1];
    positions[r * 3 + 2] = src[v * 3 + 2];
  }
  return { mesh: { positions, indices: kept }, removed };
}

interface EdgeCounts {
  open: number;
  nonManifold: number;
  /** Edges used by exactly two triangles that traverse it in the same direction. */
  flipped: number;
}

/** Buckets larger than this are sorted instead of compared pairwise. */
const SMALL_BUCKET = 24;

/**
 * Count undirected edges by how many triangles use them. Edges are bucketed by their lower vertex
 * (counting sort, cache-friendly), then equal upper vertices are found inside each small bucket.
 * Each entry stores upper·2 + direction bit (1 when the triangle runs upper → lower).
 */
function countEdges(indices: Uint32Array, nVerts: number): EdgeCounts {
  if (nVerts > 0x3fffffff)
    throw new StrataError('LIMIT_EXCEEDED', `the mesh has ${nVerts} vertices; the limit is ${0x3fffffff}`);
  const n = indices.length;
  const start = new Int32Array(nVerts + 1);
  for (let t = 0; t < n; t += 3) {
    const a = indices[t],
      b = indices[t + 1],
      c = indices[t + 2];
    start[(a < b ? a : b) + 1]++;
    start[(b < c ? b : c) + 1]++;
    start[(c < a ? c : a) + 1]++;
  }
  for (let v = 0; v < nVerts; v++) start[v + 1] += start[v];
  const fill = start.slice(0, nVerts);
  const other = new Int32Array(n);
  for (let t = 0; t < n; t += 3) {
    for (let e = 0; e < 3; e++) {
      const a = indices[t + e];
      const b = indices[e === 2 ? t : t + e + 1];
      if (a < b) other[fill[a]++] = b * 2;
      else other[fill[b]++] = a * 2 + 1;
    }
  }
  let open = 0;
  let nonManifold = 0;
  let flipped = 0;
  const tally = (uses: number, dir: number): void => {
    if (uses === 1) open++;
    else if (uses > 2) nonManifold++;
    else if (dir !== 0) flipped++;
  };
  for (let v = 0; v < nVerts; v++) {
    const s = start[v];
    const e = start[v + 1];
    if (e - s > SMALL_BUCKET) {
      const bucket = other.subarray(s, e).sort();
      for (let i = 0; i < bucket.length; ) {
        const hi = bucket[i] >> 1;
        let uses = 0;
        let dir = 0;
        while (i < bucket.length && bucket[i] >> 1 === hi) {
          uses++;
          dir += bucket[i] & 1 ? -1 : 1;
          i++;
        }
        tally(uses, dir);
      }
      continue;
    }
    for (let i = s; i < e; i++) {
      const hi = other[i] >> 1;
      if (hi < 0) continue; // already counted
      let uses = 1;
      let dir = other[i] & 1 ? -1 : 1;
      for (let j = i + 1; j < e; j++) {
        if (other[j] >> 1 === hi) {
          uses++;
          dir += other[j] & 1 ? -1 : 1;
          other[j] = -2;
        }
      }
      tally(uses, dir);
    }
  }
  return { open, nonManifold, flipped };
}

/** A bounding box, mm. */
interface Box3 {
  min: [number, number, number];
  max: [number, number, number];
}

/**
 * Bounding box of the vertices the triangles use, mm (all Infinity / -Infinity when they use none): the box of the
 * triangles' corners, found by marking the vertices used and then reading those in memory order (on 3DBenchy about
 * half the time of reading the corners in triangle order, which jumps about the positions). Every index must be below
 * the vertex count.
 */
export function usedVertexBounds(p: Float32Array, indices: Uint32Array): Box3 {
  const used = new Uint8Array(Math.ceil(p.length / 3));
  for (let i = 0; i < indices.length; i++) used[indices[i]] = 1;
  return vertexBounds(p, used);
}

/** Bounding box of a position array (x,y,z per vertex), mm. */
export function positionBounds(p: Float32Array): Box3 {
  if (p.length === 0) return { min: [0, 0, 0], max: [0, 0, 0] };
  return vertexBounds(p, null);
}

/**
 * The box of the vertices `used` marks (of every vertex without it). A last vertex cut short is still read: its
 * missing coordinates compare false.
 */
function vertexBounds(p: Float32Array, used: Uint8Array | null): Box3 {
  const n = Math.ceil(p.length / 3);
  let x0 = Infinity,
    y0 = Infinity,
    z0 = Infinity;
  let x1 = -Infinity,
    y1 = -Infinity,
    z1 = -Infinity;
  for (let v = 0, i = 0; v < n; v++, i += 3) {
    if (used !== null && used[v] === 0) continue;
    const x = p[i],
      y = p[i + 1],
      z = p[i + 2];
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
    if (z < z0) z0 = z;
    if (z > z1) z1 = z;
  }
  return { min: [x0, y0, z0], max: [x1, y1, z1] };
}

/** Signed volume (sum of tetrahedra to the bounding-box centre, which keeps the sum precise). */
function signedVolume(mesh: Mesh, min: number[], max: number[]): number {
  const cx = (min[0] + max[0]) / 2,
    cy = (min[1] + max[1]) / 2,
    cz = (min[2] + max[2]) / 2;
  const p = mesh.positions;
  const idx = mesh.indices;
  let sum = 0;
  for (let i = 0; i < idx.length; i += 3) {
    const a = idx[i] * 3,
      b = idx[i + 1] * 3,
      c = idx[i + 2] * 3;
    const ax = p[a] - cx,
      ay = p[a + 1] - cy,
      az = p[a + 2] - cz;
    const bx = p[b] - cx,
      by = p[b + 1] - cy,
      bz = p[b + 2] - cz;
    const qx = p[c] - cx,
      qy = p[c + 1] - cy,
      qz = p[c + 2] - cz;
    sum += ax * (by * qz - bz * qy) + ay * (bz * qx - bx * qz) + az * (bx * qy - by * qx);
  }
  return sum / 6;
}
