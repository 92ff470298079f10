/**
 * Where a tree-support branch may be, layer by layer and per radius class (after CuraEngine's model volumes):
 * - collision(j): where no support may be (the part grown by the XY gap, from ModelLayers);
 * - grown(c, j): where the centre of a branch of class c may not be: collision(j) grown by the class radius;
 * - avoidance(c, j): where the centre of a branch of class c may not be if it is to reach the bed: grown(c, j)
 *   and every place from which no point outside avoidance(c, j-1) is within one layer's move. Built from the
 *   bed up: avoidance(c, 0) = grown(c, 0), avoidance(c, j) = grown(c, j) ∪ (avoidance(c, j-1) shrunk by the
 *   move between j and j-1). A centre outside avoidance(c, j) can always step to one outside avoidance(c, j-1),
 *   so a branch that keeps outside its avoidance reaches the bed, never touching the part on the way.
 * Radius classes keep the number of areas small: a branch is checked against the smallest class at least as
 * wide as it is.
 */
import { offset, union } from '../../geometry/clip.js';
import type { ExPolygon } from '../../geometry/types.js';
import { AreaIndex } from './area-index.js';
import type { ModelLayers } from './model-layers.js';

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

export class TreeVolumes {
  readonly radii: readonly number[];
  readonly #model: ModelLayers;
  /** Sideways move allowed between layer j and j-1, µm. */
  readonly #step: (j: number) => number;
  readonly #collision: ExPolygon[][] = [];
  /** [class][layer] */
  readonly #grown: ExPolygon[][][];
  readonly #avoid: ExPolygon[][][];
  readonly #index = new Map<string, AreaIndex>();
  #built = -1;
  #avoidTop = -1;

  constructor(model: ModelLayers, radii: readonly number[], step: (j: number) => number) {
    this.#model = model;
    this.radii = radii;
    this.#step = step;
    this.#grown = radii.map(() => []);
    this.#avoid = radii.map(() => []);
  }

  /** Compute collision up to layer `top` and avoidance up to `avoidTop`, from the bed up; yields per layer. */
  *build(top: number, avoidTop: number): Generator<void, void> {
    this.#avoidTop = avoidTop;
    for (let j = 0; j <= top; j++) {
      const col = this.#model.collision(j);
      this.#collision[j] = col;
      if (j <= avoidTop) {
        for (let c = 0; c < this.radii.length; c++) {
          const g = col.length ? offset(col, this.radii[c]) : [];
          this.#grown[c][j] = g;
          const below = j > 0 ? this.#avoid[c][j - 1] : [];
          const kept = below.length ? offset(below, -this.#step(j)) : [];
          this.#avoid[c][j] = kept.length && g.length ? union(g, kept) : kept.length ? kept : g;
        }
      }
      this.#built = j;
      yield;
    }
  }

  /** Where no support may be on layer j. */
  collision(j: number): ExPolygon[] {
    return j >= 0 && j <= this.#built ? this.#collision[j] : this.#model.collision(j);
  }

  /** The areas a centre of class c must stay out of on layer j: to reach the bed, or only to keep off the part. */
  blocked(keep: Keep, c: number, j: number): ExPolygon[] {
    if (keep === 'part') return this.collision(j);
    if (j < 0 || j > this.#avoidTop) return [];
    return keep === 'bed' ? this.#avoid[c][j] : this.#grown[c][j];
  }

  /** The same, as an index for point queries (built on first use). */
  index(keep: Keep, c: number, j: number): AreaIndex {
    const key = `${keep}:${keep === 'part' ? 0 : c}:${j}`;
    let ix = this.#index.get(key);
    if (!ix) this.#index.set(key, (ix = new AreaIndex(this.blocked(keep, c, j))));
    return ix;
  }

  /** Forget the avoidance of layer j + 1 (the branches have gone below it; collision stays for drawing). */
  release(j: number): void {
    const k = j + 1;
    if (k > this.#avoidTop) return;
    for (let c = 0; c < this.radii.length; c++) {
      this.#grown[c][k] = [];
      this.#avoid[c][k] = [];
      this.#index.delete(`bed:${c}:${k}`);
      this.#index.delete(`model:${c}:${k}`);
    }
    this.#index.delete(`part:0:${k}`);
  }
}
