/**
 * Where a tree-support branch may be, layer by layer and per radius class (after CuraEngine's model volumes):
 * - collision(j): where no support may be (the part grown by the XY gap, from ModelLayers); a centre of a
 *   branch of class c must keep more than the class radius from it;
 * - avoidance(j): where the centre of a tip-sized branch may not be if it is to reach the bed, built from the
 *   bed up: avoidance(0) = collision(0) grown by the tip radius, avoidance(j) = collision(j) grown by the tip
 *   radius ∪ (avoidance(j - 1) shrunk by the move between j and j - 1, or in build-plate placement by
 *   BUILD_PLATE_AVOID_MOVE_SHARE of it), so that a centre outside it can
 *   always step to one outside avoidance(j - 1): a branch that keeps outside its avoidance reaches the bed,
 *   never touching the part on the way. A wider class keeps the difference in radius away from it. That
 *   holds the part clear exactly; only at sharp outer corners of the avoidance is it a little less than an
 *   avoidance built for the wider radius, and a branch that finds no way down there keeps just clear of the
 *   part like any other.
 * Both are asked as distances from two point indexes a layer, so no area is made per radius: a branch is
 * checked against the smallest class at least as wide as it is.
 */
import { offset, union } from '../geometry/clip.js';
import type { ExPolygon } from '../geometry/types.js';
import { AreaIndex, type Found } from '../geometry/area-index.js';
import type { ModelLayers } from './model-layers.js';

/**
 * In build-plate placement the avoidance is built for this share of the move: a branch at its edge then keeps
 * room to lean, merge and widen on its way down. Built for the whole move, a branch held to the edge had to
 * move the whole move every layer, failed at the first step that asked for more, and (with no part to stand
 * on) was dropped with every tip it carried: 3DBenchy's overhang 18.8 % held, Overhang's none. In 'everywhere'
 * placement such a branch stands on the part instead, and the whole move keeps more of them short.
 */
export const BUILD_PLATE_AVOID_MOVE_SHARE = 0.75;

/** Radius classes are at most this far apart, µm. */
export const CLASS_STEP_UM = 450;
/** At most this many radius classes between the tip and the branch radius. */
export const MAX_CLASSES = 4;

/** Radius classes from the tip radius to the branch radius, µm, ascending. */
export function radiusClasses(tipUm: number, branchUm: number): number[] {
  const span = Math.max(0, branchUm - tipUm);
  const steps = span > 0 ? Math.min(MAX_CLASSES - 1, Math.max(1, Math.ceil(span / CLASS_STEP_UM))) : 0;
  const out: number[] = [];
  for (let i = 0; i <= steps; i++) out.push(Math.round(tipUm + (steps ? (span * i) / steps : 0)));
  return out;
}

/** The smallest class at least `r` wide (the largest class for wider branches). */
export function classOf(radii: readonly number[], r: number): number {
  for (let c = 0; c < radii.length; c++) if (radii[c] >= r - 0.5) return c;
  return radii.length - 1;
}

/**
 * What a centre keeps out of: 'bed' its avoidance (so it reaches the bed), 'model' the collision grown by its
 * radius (it may end on the part), 'part' the collision itself (a branch ending on the part, or drawing).
 */
export type Keep = 'bed' | 'model' | 'part';

/** What a centre of some class must stay out of on one layer, asked point by point. */
export class Blocked {
  readonly #index: AreaIndex;
  /** How far outside the index's areas the centre must be, µm. */
  readonly #clearUm: number;

  constructor(index: AreaIndex, clearUm: number) {
    this.#index = index;
    this.#clearUm = clearUm;
  }

  /** Whether (x, y) is blocked. */
  contains(x: number, y: number): boolean {
    return this.#clearUm > 0 ? this.#index.meetsDisc(x, y, this.#clearUm) : this.#index.contains(x, y);
  }

  /**
   * The nearest unblocked point within `maxUm` of (x, y) ((x, y) itself when it is free), or null; `thorough`
   * off looks only just off the nearby edges, not round the point as well (cheaper, finds less).
   */
  nearestOutside(x: number, y: number, maxUm: number, thorough = true): Found | null {
    return this.#index.nearestClear(x, y, this.#clearUm, maxUm, thorough);
  }
}

export class TreeVolumes {
  readonly radii: readonly number[];
  readonly #model: ModelLayers;
  /** Sideways move allowed between layer j and j-1, µm. */
  readonly #step: (j: number) => number;
  readonly #collision: ExPolygon[][] = [];
  /** The tip class's avoidance per layer. */
  readonly #avoid: ExPolygon[][] = [];
  /** Per layer, made on first use: the avoidance and the collision as point indexes, and what each class keeps out of. */
  readonly #layer: (
    | { avoid: AreaIndex | null; part: AreaIndex | null; blocked: (Blocked | undefined)[] }
    | undefined
  )[] = [];
  #built = -1;
  #avoidTop = -1;
  /** The share of the move the avoidance is built for. */
  readonly #moveShare: number;

  constructor(model: ModelLayers, radii: readonly number[], step: (j: number) => number) {
    this.#model = model;
    this.#moveShare = model.cfg.supportPlacement === 'buildPlate' ? BUILD_PLATE_AVOID_MOVE_SHARE : 1;
    this.radii = radii;
    this.#step = step;
  }

  /** Compute collision up to layer `top` and the avoidance up to `avoidTop`, from the bed up; yields per layer. */
  *build(top: number, avoidTop: number): Generator<void, void> {
    this.#avoidTop = avoidTop;
    const r0 = this.radii[0];
    for (let j = 0; j <= top; j++) {
      const col = this.#model.collision(j);
      this.#collision[j] = col;
      if (j <= avoidTop) {
        const g = col.length ? offset(col, r0) : [];
        const below = j > 0 ? this.#avoid[j - 1] : [];
        const kept = below.length ? offset(below, -this.#step(j) * this.#moveShare) : [];
        this.#avoid[j] = kept.length && g.length ? union(g, kept) : kept.length ? kept : g;
      }
      this.#built = j;
      yield;
    }
  }

  /** Where no support may be on layer j. */
  collision(j: number): ExPolygon[] {
    return j >= 0 && j <= this.#built ? this.#collision[j] : this.#model.collision(j);
  }

  /** The tip class's avoidance on layer j ([] above the highest tip). */
  avoidance(j: number): ExPolygon[] {
    return j >= 0 && j <= this.#avoidTop ? this.#avoid[j] : [];
  }

  #layerOf(j: number) {
    return (this.#layer[j] ??= { avoid: null, part: null, blocked: [] });
  }

  #avoidIndex(j: number): AreaIndex {
    const l = this.#layerOf(j);
    return (l.avoid ??= new AreaIndex(this.avoidance(j)));
  }

  #partIndex(j: number): AreaIndex {
    const l = this.#layerOf(j);
    return (l.part ??= new AreaIndex(this.collision(j)));
  }

  /** What a centre of class c keeps out of on layer j: to reach the bed ('bed'), to keep off the part ('model'), or the collision itself ('part'). */
  index(keep: Keep, c: number, j: number): Blocked {
    const blocked = this.#layerOf(j).blocked;
    const slot = keep === 'bed' ? c : keep === 'model' ? this.radii.length + c : 2 * this.radii.length;
    let b = blocked[slot];
    if (!b) {
      if (keep === 'bed') b = new Blocked(this.#avoidIndex(j), this.radii[c] - this.radii[0]);
      else b = new Blocked(this.#partIndex(j), keep === 'model' ? this.radii[c] : 0);
      blocked[slot] = b;
    }
    return b;
  }

  /** The collision of layer j as a point index (segment tests between branches). */
  partIndex(j: number): AreaIndex {
    return this.#partIndex(j);
  }

  /** Forget what layer j + 1 needed (the branches have gone below it; collision stays for drawing). */
  release(j: number): void {
    const k = j + 1;
    if (k > this.#avoidTop) return;
    this.#avoid[k] = [];
    this.#layer[k] = undefined;
  }
}
