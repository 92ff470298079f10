/**
 * The objects of a plate as the layer stages see them: which mesh holds each object's parts and which its
 * negative volumes, modifiers, support blockers and enforcers, and which config each of its regions reads
 * (made by pipeline/print-setup.ts). Plain data: it crosses to the workers as it is.
 */
import type { Config } from '../settings/resolve.js';

/** One object as the layer stages see it: indices into the setup's meshes and configs. */
export interface ObjectSetup {
  name: string;
  /** The parts' mesh. */
  parts: number;
  negatives: number[];
  modifiers: number[];
  blockers: number[];
  enforcers: number[];
  /** The object's config (its settings over the print's). */
  config: number;
  /** Layer ranges in the order given (a later one wins where they overlap), mm from the bed. */
  ranges: Array<{ fromZ: number; toZ: number }>;
  /**
   * `regions[r][m]`: the config of layer range r (0: none, k: ranges[k − 1]) inside modifier m (0: none,
   * k: modifiers[k − 1]).
   */
  regions: number[][];
}

export interface PrintSetup {
  /** Deduplicated configs; configs[0] is the print's. */
  configs: Config[];
  objects: ObjectSetup[];
  /** Pairs of objects whose bounds overlap and whose settings differ: refused if their sections do. */
  overlapPairs: Array<[number, number]>;
}

/** The index of the layer range (0: none) of a layer cut at `sliceZ` (a later range wins). */
export function rangeAt(object: ObjectSetup, sliceZ: number): number {
  for (let r = object.ranges.length - 1; r >= 0; r--) {
    const { fromZ, toZ } = object.ranges[r];
    if (sliceZ >= fromZ && sliceZ < toZ) return r + 1;
  }
  return 0;
}

/** The setup of a plate of objects with no settings or volumes of their own (object k sliced from mesh k). */
export function plainSetup(cfg: Config, objectCount = 1): PrintSetup {
  const objects = Array.from(
    { length: objectCount },
    (_, k): ObjectSetup => ({
      name: `object ${k + 1}`,
      parts: k,
      negatives: [],
      modifiers: [],
      blockers: [],
      enforcers: [],
      config: 0,
      ranges: [],
      regions: [[0]],
    }),
  );
  return { configs: [cfg], objects, overlapPairs: [] };
}
