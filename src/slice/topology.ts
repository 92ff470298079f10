/**
 * Mesh topology for slicing: undirected edge ids per triangle side (so a plane crossing is
 * identified by its edge, not by its coordinates), and shells (connected components) with the
 * orientation fix for shells whose normals point inwards.
 */

/**
 * Edge ids of a mesh: `triEdge[3t + j]` is the edge from corner j to corner j+1 (mod 3) of triangle t
 * (-1 for triangles left out as invalid).
 */
export interface EdgeTable {
  triEdge: Int32Array;
  /** Lower vertex id of each edge. */
  edgeA: Uint32Array;
  /** Higher vertex id of each edge. */
  edgeB: Uint32Array;
  edgeCount: number;
}

/** Above this many sides in one vertex bucket, the bucket is indexed with a map (no quadratic scan). */
const LARGE_FAN = 48;

/**
 * Give every undirected vertex pair used by a triangle side one id. Linear time: sides are bucketed
 * by their lower vertex (counting sort), and each bucket — a vertex's few neighbours — is scanned.
 * Only triangles with `valid[t]` set are indexed; their vertex ids must be below `vertexCount`.
 */
export function buildEdgeTable(indices: Uint32Array, vertexCount: number, valid: Uint8Array): EdgeTable {
  const sides = indices.length - (indices.length % 3);
  const bucketStart = new Int32Array(vertexCount + 1);
  const other = new Uint32Array(sides);
  for (let tri = 0, t = 0; t < sides; tri++, t += 3) {
    if (!valid[tri]) continue;
    for (let j = 0; j < 3; j++) {
      const u = indices[t + j];
      const v = indices[t + (j === 2 ? 0 : j + 1)];
      bucketStart[(u < v ? u : v) + 1]++;
      other[t + j] = u < v ? v : u;
    }
  }
  for (let v = 0; v < vertexCount; v++) bucketStart[v + 1] += bucketStart[v];
  const bucket = new Int32Array(sides);
  const fill = bucketStart.slice(0, vertexCount);
  for (let tri = 0, t = 0; t < sides; tri++, t += 3) {
    if (!valid[tri]) continue;
    for (let j = 0; j < 3; j++) {
      const u = indices[t + j];
      const v = indices[t + (j === 2 ? 0 : j + 1)];
      bucket[fill[u < v ? u : v]++] = t + j;
    }
  }
  const edgeA = new Uint32Array(Math.max(1, sides));
  const edgeB = new Uint32Array(Math.max(1, sides));
  const triEdge = new Int32Array(sides).fill(-1);
  let edgeCount = 0;
  for (let a = 0; a < vertexCount; a++) {
    const first = bucketStart[a],
      end = bucketStart[a + 1];
    if (end - first > LARGE_FAN) {
      // A fan centre with very many neighbours: look them up in a map instead of scanning.
      const seen = new Map<number, number>();
      for (let i = first; i < end; i++) {
        const side = bucket[i];
        const b = other[side];
        let id = seen.get(b);
        if (id === undefined) {
          id = edgeCount++;
          edgeA[id] = a;
          edgeB[id] = b;
          seen.set(b, id);
        }
        triEdge[side] = id;
      }
      continue;
    }
    for (let i = first; i < end; i++) {
      const side = bucket[i];
      const b = other[side];
      let id = -1;
      for (let k = first; k < i; k++) {
        if (other[bucket[k]] === b) {
          id = triEdge[bucket[k]];
          break;
        }
      }
      if (id === -1) {
        id = edgeCount++;
        edgeA[id] = a;
        edgeB[id] = b;
      }
      triEdge[side] = id;
    }
  }
  return { triEdge, edgeA, edgeB, edgeCount };
}

/** Connected components of triangles (sharing a vertex) and their orientation. */
export interface Shells {
  /** Shell id of each triangle. */
  triShell: Int32Array;
  shellCount: number;
  /** 1 where the shell's triangles must be read with reversed winding. */
  shellFlip: Uint8Array;
}

function find(parent: Int32Array, v: number): number {
  let r = v;
  while (parent[r] !== r) r = parent[r];
  while (parent[v] !== r) {
    const n = parent[v];
    parent[v] = r;
    v = n;
  }
  return r;
}

function growBox(box: Float64Array, o: number, x: number, y: number, z: number): void {
  if (x < box[o]) box[o] = x;
  if (y < box[o + 1]) box[o + 1] = y;
  if (z < box[o + 2]) box[o + 2] = z;
  if (x > box[o + 3]) box[o + 3] = x;
  if (y > box[o + 4]) box[o + 4] = y;
  if (z > box[o + 5]) box[o + 5] = z;
}

/** Shells with fewer triangles than this never get flipped (no closed surface has fewer than 4). */
const MIN_SHELL_TRIANGLES = 4;
/** Above this many shells the nesting search (quadratic in shells) is skipped. */
const MAX_NESTING_SHELLS = 2048;

/**
 * Find the shells and decide which to flip. Rule: an outermost shell (its bounding box inside no
 * other shell's) with negative signed volume has inverted normals and is flipped. A shell nested in
 * another one's bounding box inherits its container's decision: a correctly oriented cavity
 * (negative volume inside a positive shell) stays a cavity, an embedded positive body stays a body,
 * and a wholly inverted model (outer and cavity both inverted) is flipped as a whole.
 * `valid[t]` = 0 excludes triangle t (degenerate indices, non-finite coordinates).
 */
export function findShells(positions: Float32Array, indices: Uint32Array, valid: Uint8Array): Shells {
  const vertexCount = Math.floor(positions.length / 3);
  const triCount = Math.floor(indices.length / 3);
  const parent = new Int32Array(vertexCount);
  for (let i = 0; i < vertexCount; i++) parent[i] = i;
  for (let t = 0; t < triCount; t++) {
    if (!valid[t]) continue;
    const a = find(parent, indices[3 * t]);
    const b = find(parent, indices[3 * t + 1]);
    const c = find(parent, indices[3 * t + 2]);
    if (a !== b) parent[a] = b;
    const b2 = find(parent, b);
    if (c !== b2) parent[c] = b2;
  }
  const rootShell = new Int32Array(vertexCount).fill(-1);
  const triShell = new Int32Array(triCount).fill(-1);
  let shellCount = 0;
  for (let t = 0; t < triCount; t++) {
    if (!valid[t]) continue;
    const r = find(parent, indices[3 * t]);
    if (rootShell[r] === -1) rootShell[r] = shellCount++;
    triShell[t] = rootShell[r];
  }
  const shellFlip = new Uint8Array(shellCount);
  if (shellCount === 0) return { triShell, shellCount, shellFlip };

  // Signed volume (about the mesh centre, to keep open shells' volumes meaningful), boxes, counts.
  let cx = 0,
    cy = 0,
    cz = 0;
  {
    let minX = Infinity,
      minY = Infinity,
      minZ = Infinity,
      maxX = -Infinity,
      maxY = -Infinity,
      maxZ = -Infinity;
    for (let v = 0; v < vertexCount; v++) {
      const x = positions[3 * v],
        y = positions[3 * v + 1],
        z = positions[3 * v + 2];
      if (!(x > -Infinity && x < Infinity && y > -Infinity && y < Infinity && z > -Infinity && z < Infinity)) continue;
      if (x < minX) minX = x;
      if (x > maxX) maxX = x;
      if (y < minY) minY = y;
      if (y > maxY) maxY = y;
      if (z < minZ) minZ = z;
      if (z > maxZ) maxZ = z;
    }
    if (minX <= maxX) {
      cx = (minX + maxX) / 2;
      cy = (minY + maxY) / 2;
      cz = (minZ + maxZ) / 2;
    }
  }
  const volume = new Float64Array(shellCount);
  const count = new Int32Array(shellCount);
  const box = new Float64Array(shellCount * 6);
  for (let s = 0; s < shellCount; s++) {
    box[6 * s] = box[6 * s + 1] = box[6 * s + 2] = Infinity;
    box[6 * s + 3] = box[6 * s + 4] = box[6 * s + 5] = -Infinity;
  }
  for (let t = 0; t < triCount; t++) {
    const s = triShell[t];
    if (s < 0) continue;
    const i0 = 3 * indices[3 * t],
      i1 = 3 * indices[3 * t + 1],
      i2 = 3 * indices[3 * t + 2];
    const ax = positions[i0] - cx,
      ay = positions[i0 + 1] - cy,
      az = positions[i0 + 2] - cz;
    const bx = positions[i1] - cx,
      by = positions[i1 + 1] - cy,
      bz = positions[i1 + 2] - cz;
    const qx = positions[i2] - cx,
      qy = positions[i2 + 1] - cy,
      qz = positions[i2 + 2] - cz;
    volume[s] += (ax * (by * qz - bz * qy) + ay * (bz * qx - bx * qz) + az * (bx * qy - by * qx)) / 6;
    count[s]++;
    growBox(box, 6 * s, ax, ay, az);
    growBox(box, 6 * s, bx, by, bz);
    growBox(box, 6 * s, qx, qy, qz);
  }

  const big: number[] = [];
  for (let s = 0; s < shellCount; s++) if (count[s] >= MIN_SHELL_TRIANGLES) big.push(s);
  if (big.length > MAX_NESTING_SHELLS) {
    for (const s of big) shellFlip[s] = volume[s] < 0 ? 1 : 0;
    return { triShell, shellCount, shellFlip };
  }
  const boxVolume = (s: number): number =>
    (box[6 * s + 3] - box[6 * s]) * (box[6 * s + 4] - box[6 * s + 1]) * (box[6 * s + 5] - box[6 * s + 2]);
  const contains = (p: number, c: number): boolean =>
    box[6 * p] <= box[6 * c] &&
    box[6 * p + 1] <= box[6 * c + 1] &&
    box[6 * p + 2] <= box[6 * c + 2] &&
    box[6 * p + 3] >= box[6 * c + 3] &&
    box[6 * p + 4] >= box[6 * c + 4] &&
    box[6 * p + 5] >= box[6 * c + 5];
  // Largest boxes first, so a container is decided before what it contains.
  big.sort((p, q) => boxVolume(q) - boxVolume(p) || Math.abs(volume[q]) - Math.abs(volume[p]));
  for (let i = 0; i < big.length; i++) {
    const c = big[i];
    let container = -1;
    for (let j = 0; j < i; j++) {
      const p = big[j];
      if (contains(p, c) && (container === -1 || boxVolume(p) <= boxVolume(container))) container = p;
    }
    shellFlip[c] = container === -1 ? (volume[c] < 0 ? 1 : 0) : shellFlip[container];
  }
  return { triShell, shellCount, shellFlip };
}
