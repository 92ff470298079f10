/**
 * Plane–mesh intersection: one sweep over the layers, triangles bucketed by the first plane they
 * cross, producing per layer one directed segment per crossing triangle, each segment linking two
 * edge crossings ("slots"). No triangle is ever tested against a plane it does not cross.
 *
 * Symbolic perturbation: vertex heights and slice planes are compared on the half-µm grid and a
 * vertex with z ≥ plane counts as above. No vertex is ever on a plane, so a crossing triangle has
 * exactly one lone vertex, crosses exactly two of its edges, and every crossing is on an edge
 * interior (interpolated with t clamped to [0, 1]).
 *
 * Orientation: the segment runs so that the triangle's outward side (by its winding) is on the
 * right, so a closed outward-facing mesh yields counter-clockwise outer contours and clockwise holes.
 */
import type { Mesh } from '../mesh/types.js';
import { HALF_UM_PER_MM } from './layers.js';
import { buildEdgeTable, findShells } from './topology.js';
import type { EdgeTable } from './topology.js';

/** A mesh made ready for slicing (plain typed arrays; reusable for any set of layers). */
export interface PreparedMesh {
  positions: Float32Array;
  indices: Uint32Array;
  /** Vertex heights on the half-µm grid. */
  zq: Float64Array;
  edges: EdgeTable;
  /** Per triangle: 0 = skipped (repeated vertex, bad index, non-finite), 1 = as wound, 2 = reversed. */
  triMode: Uint8Array;
}

/** The segments of one layer. Slot = one edge crossing; coordinates are integer µm. */
export interface LayerSegments {
  segCount: number;
  /** Slot the segment starts at. */
  segStart: Int32Array;
  /** Slot the segment ends at. */
  segEnd: Int32Array;
  slotCount: number;
  slotX: Float64Array;
  slotY: Float64Array;
}

/** Build edge ids, shell orientation and quantized heights. Linear in the mesh size. */
export function prepareMesh(mesh: Mesh): PreparedMesh {
  const { positions, indices } = mesh;
  const vertexCount = Math.floor(positions.length / 3);
  const triCount = Math.floor(indices.length / 3);
  const zq = new Float64Array(vertexCount);
  const finite = new Uint8Array(vertexCount);
  for (let v = 0; v < vertexCount; v++) {
    const x = positions[3 * v],
      y = positions[3 * v + 1],
      z = positions[3 * v + 2];
    finite[v] = Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z) ? 1 : 0;
    zq[v] = finite[v] ? Math.round(z * HALF_UM_PER_MM) : 0;
  }
  const valid = new Uint8Array(triCount);
  for (let t = 0; t < triCount; t++) {
    const a = indices[3 * t],
      b = indices[3 * t + 1],
      c = indices[3 * t + 2];
    valid[t] =
      a < vertexCount &&
      b < vertexCount &&
      c < vertexCount &&
      a !== b &&
      b !== c &&
      a !== c &&
      finite[a] &&
      finite[b] &&
      finite[c]
        ? 1
        : 0;
  }
  const edges = buildEdgeTable(indices, vertexCount, valid);
  const shells = findShells(positions, indices, valid);
  const triMode = new Uint8Array(triCount);
  for (let t = 0; t < triCount; t++) {
    if (valid[t]) triMode[t] = shells.shellFlip[shells.triShell[t]] ? 2 : 1;
  }
  return { positions, indices, zq, edges, triMode };
}

/** Number of planes ≤ x in an ascending array. */
function countAtOrBelow(planes: Float64Array, x: number): number {
  let lo = 0,
    hi = planes.length;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if (planes[mid] <= x) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/**
 * Sweep ascending planes (half-µm grid) bottom to top, one plane per `next()` call, so a caller can slice
 * layers as it needs them (and pause between them). The segments object and its arrays are reused between
 * calls: consume them before the next.
 */
export class PlaneSweep {
  readonly #prep: PreparedMesh;
  readonly #planes: Float64Array;
  readonly #lastOf: Int32Array;
  readonly #bucketStart: Int32Array;
  readonly #order: Int32Array;
  readonly #active: Int32Array;
  #activeCount = 0;
  readonly #edgeStamp: Int32Array;
  readonly #edgeSlot: Int32Array;
  readonly #seg: LayerSegments;
  #k = 0;

  constructor(prep: PreparedMesh, planes: Float64Array) {
    this.#prep = prep;
    this.#planes = planes;
    const { indices, zq, triMode } = prep;
    const triCount = triMode.length;
    const L = planes.length;
    // Bucket triangles by the first plane they cross (counting sort); remember the last one.
    const firstOf = new Int32Array(triCount).fill(-1);
    const lastOf = new Int32Array(triCount);
    const bucketStart = new Int32Array(L + 1);
    if (L > 0) {
      for (let t = 0; t < triCount; t++) {
        if (!triMode[t]) continue;
        const z0 = zq[indices[3 * t]],
          z1 = zq[indices[3 * t + 1]],
          z2 = zq[indices[3 * t + 2]];
        const lo = z0 < z1 ? (z0 < z2 ? z0 : z2) : z1 < z2 ? z1 : z2;
        const hi = z0 > z1 ? (z0 > z2 ? z0 : z2) : z1 > z2 ? z1 : z2;
        // Crosses plane p iff lo < p ≤ hi.
        const first = countAtOrBelow(planes, lo);
        // Most triangles span few planes: walk up rather than search again.
        let last = first - 1;
        while (last + 1 < L && planes[last + 1] <= hi) last++;
        if (first > last) continue;
        firstOf[t] = first;
        lastOf[t] = last;
        bucketStart[first + 1]++;
      }
    }
    for (let k = 0; k < L; k++) bucketStart[k + 1] += bucketStart[k];
    const order = new Int32Array(bucketStart[L]);
    {
      const fill = bucketStart.slice(0, L);
      for (let t = 0; t < triCount; t++) if (firstOf[t] >= 0) order[fill[firstOf[t]]++] = t;
    }
    this.#lastOf = lastOf;
    this.#bucketStart = bucketStart;
    this.#order = order;
    this.#active = new Int32Array(order.length);
    this.#edgeStamp = new Int32Array(prep.edges.edgeCount);
    this.#edgeSlot = new Int32Array(prep.edges.edgeCount);
    this.#seg = {
      segCount: 0,
      segStart: new Int32Array(64),
      segEnd: new Int32Array(64),
      slotCount: 0,
      slotX: new Float64Array(128),
      slotY: new Float64Array(128),
    };
  }

  /** Planes not yet swept. */
  get remaining(): number {
    return this.#planes.length - this.#k;
  }

  /** The segments of the next plane, or null when every plane has been swept. */
  next(): LayerSegments | null {
    const k = this.#k;
    const planes = this.#planes;
    if (k >= planes.length) return null;
    this.#k = k + 1;
    const { positions, indices, zq, triMode } = this.#prep;
    const { triEdge, edgeA, edgeB } = this.#prep.edges;
    const lastOf = this.#lastOf,
      bucketStart = this.#bucketStart,
      order = this.#order,
      active = this.#active;
    const edgeStamp = this.#edgeStamp,
      edgeSlot = this.#edgeSlot,
      seg = this.#seg;

    // Drop triangles that ended below this plane, add those starting here.
    let n = 0;
    for (let i = 0; i < this.#activeCount; i++) {
      const t = active[i];
      if (lastOf[t] >= k) active[n++] = t;
    }
    for (let i = bucketStart[k]; i < bucketStart[k + 1]; i++) active[n++] = order[i];
    this.#activeCount = n;

    if (seg.segStart.length < n) {
      const cap = Math.max(n, seg.segStart.length * 2);
      seg.segStart = new Int32Array(cap);
      seg.segEnd = new Int32Array(cap);
      seg.slotX = new Float64Array(2 * cap);
      seg.slotY = new Float64Array(2 * cap);
    }
    const p = planes[k];
    const pMm = p / HALF_UM_PER_MM;
    const stamp = k + 1;
    const { segStart, segEnd, slotX, slotY } = seg;
    let slots = 0;

    for (let i = 0; i < n; i++) {
      const t = active[i];
      const b = 3 * t;
      const above0 = zq[indices[b]] >= p,
        above1 = zq[indices[b + 1]] >= p,
        above2 = zq[indices[b + 2]] >= p;
      // The lone vertex j (on its own side); edge j runs j→j+1, edge prev runs j−1→j.
      const j = above0 === above1 ? 2 : above0 === above2 ? 1 : 0;
      const eOut = triEdge[b + j];
      const eIn = triEdge[b + (j === 0 ? 2 : j - 1)];
      const loneAbove = j === 0 ? above0 : j === 1 ? above1 : above2;
      // Lone vertex above: the segment runs from edge (L, next) to edge (prev, L); reversed when below.
      let from = loneAbove ? eOut : eIn;
      let to = loneAbove ? eIn : eOut;
      if (triMode[t] === 2) {
        const tmp = from;
        from = to;
        to = tmp;
      }
      for (let side = 0; side < 2; side++) {
        const e = side === 0 ? from : to;
        let s: number;
        if (edgeStamp[e] === stamp) {
          s = edgeSlot[e];
        } else {
          s = slots++;
          edgeStamp[e] = stamp;
          edgeSlot[e] = s;
          let va = edgeA[e],
            vb = edgeB[e];
          if (zq[va] > zq[vb]) {
            const tmp = va;
            va = vb;
            vb = tmp;
          }
          const za = positions[3 * va + 2],
            zb = positions[3 * vb + 2];
          let u = zb > za ? (pMm - za) / (zb - za) : 0.5;
          if (!(u >= 0)) u = 0;
          else if (u > 1) u = 1;
          const xa = positions[3 * va],
            ya = positions[3 * va + 1];
          slotX[s] = Math.round((xa + (positions[3 * vb] - xa) * u) * 1000);
          slotY[s] = Math.round((ya + (positions[3 * vb + 1] - ya) * u) * 1000);
        }
        if (side === 0) segStart[i] = s;
        else segEnd[i] = s;
      }
    }
    seg.segCount = n;
    seg.slotCount = slots;
    return seg;
  }
}

/**
 * Sweep ascending planes (half-µm grid) bottom to top; call `onLayer(k, segments)` for each plane k.
 * The segments object and its arrays are reused between calls: consume them before returning.
 */
export function sweepLayers(
  prep: PreparedMesh,
  planes: Float64Array,
  onLayer: (k: number, segments: LayerSegments) => void,
): void {
  const sweep = new PlaneSweep(prep, planes);
  for (let k = 0; ; k++) {
    const seg = sweep.next();
    if (!seg) return;
    onLayer(k, seg);
  }
}
