/**
 * sliceMesh: mesh + layer plan → one cross-section (islands in integer µm) per layer.
 *
 * Pipeline per call: prepare (edge ids, shell orientation; linear), one bottom-to-top sweep that
 * yields each layer's directed segments, chaining through edge topology, closing open chains
 * across small gaps, then simplify + non-zero union into islands.
 *
 * Fill rule: loops carry the orientation of the triangles that made them (outer CCW, holes CW for
 * an outward-facing mesh) and are merged with the NON-ZERO rule, so overlapping shells union and
 * self-intersecting shells stay solid. Orientation is repaired before that, not guessed per layer:
 * a shell (connected component) with negative signed volume that is not nested in another shell's
 * bounding box is read with reversed winding (an inverted shell still slices solid, even where it
 * overlaps a correct one), nested shells follow their container (so real cavities stay holes), and
 * each chain's direction is a length-weighted vote of its segments (a few flipped triangles do
 * not reverse a loop).
 */
import type { Mesh } from '../mesh/types.js';
import { chainSegments } from './chain.js';
import { closeOpenChains } from './gaps.js';
import { PlaneSweep, prepareMesh, sweepLayers } from './intersect.js';
import type { LayerSegments } from './intersect.js';
import type { PreparedMesh } from './intersect.js';
import { ringsToIslands } from './islands.js';
import { toHalfUm } from './layers.js';
import { simplifySlotRings } from './simplify.js';
import type { LayerSection, LayerZ } from './types.js';

export interface SliceOptions {
  /** Open chain ends farther apart than this are not joined to each other (mm). Default 2. */
  maxGapMm?: number;
  /** Islands and holes smaller than this are dropped (µm²). Default (50 µm)² = 0.0025 mm². */
  minAreaUm2?: number;
}

export const DEFAULT_MAX_GAP_MM = 2;
export const DEFAULT_MIN_AREA_UM2 = 50 * 50;

/** Slice an already prepared mesh (prepare once, slice layer ranges in several calls or workers). */
export function slicePrepared(
  prep: PreparedMesh,
  layers: readonly LayerZ[],
  toleranceUm: number,
  options: SliceOptions = {},
): LayerSection[] {
  const maxGapUm = (options.maxGapMm ?? DEFAULT_MAX_GAP_MM) * 1000;
  const minArea = options.minAreaUm2 ?? DEFAULT_MIN_AREA_UM2;
  const tolerance = Number.isFinite(toleranceUm) && toleranceUm > 0 ? toleranceUm : 0;
  // Sweep planes in ascending order; report in the caller's order.
  const order = layers.map((_, i) => i);
  const planeOf = layers.map((l) => (Number.isFinite(l.sliceZ) ? toHalfUm(l.sliceZ) : Infinity)); // ∞ cuts nothing
  order.sort((a, b) => planeOf[a] - planeOf[b]);
  const planes = Float64Array.from(order, (i) => planeOf[i]);
  const out: LayerSection[] = layers.map((l) => ({
    index: l.index,
    z: l.z,
    height: l.height,
    sliceZ: l.sliceZ,
    islands: [],
  }));
  sweepLayers(prep, planes, (k, seg) => {
    out[order[k]].islands = segmentsToIslands(seg, maxGapUm, tolerance, minArea);
  });
  return out;
}

function segmentsToIslands(seg: LayerSegments, maxGapUm: number, toleranceUm: number, minAreaUm2: number) {
  const chains = chainSegments(seg);
  const loops = chains.open.length
    ? chains.closed.concat(closeOpenChains(chains.open, seg.slotX, seg.slotY, maxGapUm))
    : chains.closed;
  const rings = simplifySlotRings(loops, seg.slotX, seg.slotY, toleranceUm);
  return ringsToIslands(rings, minAreaUm2);
}

/**
 * Sections of a run of consecutive layers (ascending), sliced on demand: `at(k)` slices forward as far as
 * layer `first + k`, so a caller can work layer by layer (and pause) and only what it reaches is cut.
 * Layers further back than `keep` behind the furthest one asked for are dropped.
 */
export class SectionStream {
  readonly #sweep: PlaneSweep;
  readonly #layers: readonly LayerZ[];
  readonly #maxGapUm: number;
  readonly #toleranceUm: number;
  readonly #minArea: number;
  readonly #sections = new Map<number, LayerSection>();
  #sliced = 0;

  /**
   * @param layers consecutive layers, ascending (a range of the layer plan)
   */
  constructor(prep: PreparedMesh, layers: readonly LayerZ[], toleranceUm: number, options: SliceOptions = {}) {
    this.#layers = layers;
    this.#maxGapUm = (options.maxGapMm ?? DEFAULT_MAX_GAP_MM) * 1000;
    this.#minArea = options.minAreaUm2 ?? DEFAULT_MIN_AREA_UM2;
    this.#toleranceUm = Number.isFinite(toleranceUm) && toleranceUm > 0 ? toleranceUm : 0;
    this.#sweep = new PlaneSweep(
      prep,
      Float64Array.from(layers, (l) => (Number.isFinite(l.sliceZ) ? toHalfUm(l.sliceZ) : Infinity)),
    );
  }

  /** The section of the k-th layer of the run. */
  at(k: number): LayerSection {
    while (this.#sliced <= k) {
      const seg = this.#sweep.next();
      const l = this.#layers[this.#sliced];
      const islands = seg ? segmentsToIslands(seg, this.#maxGapUm, this.#toleranceUm, this.#minArea) : [];
      this.#sections.set(this.#sliced, { index: l.index, z: l.z, height: l.height, sliceZ: l.sliceZ, islands });
      this.#sliced++;
    }
    const s = this.#sections.get(k);
    if (!s) throw new Error(`section ${k} was already released`);
    return s;
  }

  /** Forget the sections before the k-th layer of the run. */
  release(k: number): void {
    for (const key of this.#sections.keys()) if (key < k) this.#sections.delete(key);
  }
}

/**
 * Cut a mesh (mm) at each layer's sliceZ. Never throws on broken geometry: open, non-manifold and
 * flipped meshes are sliced as well as their loops allow.
 */
export function sliceMesh(
  mesh: Mesh,
  layers: readonly LayerZ[],
  toleranceUm: number,
  options: SliceOptions = {},
): LayerSection[] {
  return slicePrepared(prepareMesh(mesh), layers, toleranceUm, options);
}
