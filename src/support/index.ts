/**
 * The support pass: a whole-model pass over the layers' outlines (their sections and overhangs) that finds
 * each layer's support areas, normal or tree (the pipeline runs it: pipeline/passes.ts). With several
 * objects each object's support is its own, made with the object's settings, so that it prints (and is
 * cancelled) with the object.
 */
import type { Config } from '../settings/resolve.js';
import type { LayerOutlines, SupportAreas } from '../regions/types.js';
import { ModelLayers } from './model-layers.js';
import { normalSupport } from './normal.js';
import { treeSupport } from './tree.js';

/** Compute every layer's support (written to `layers[j].support`); yields between layers. */
export function* supportPass(layers: LayerOutlines[], cfg: Config): Generator<void, void> {
  if (!cfg.supportEnabled) return;
  const areas = yield* supportAreas(layers, cfg);
  if (areas) for (let j = 0; j < layers.length; j++) layers[j].support = areas[j];
}

/** The support of the layers' overhangs with one config (null when nothing overhangs). */
function* supportAreas(layers: readonly LayerOutlines[], cfg: Config): Generator<void, (SupportAreas | null)[] | null> {
  if (layers.length === 0 || !layers.some((l) => l.overhang.length > 0)) return null;
  const model = new ModelLayers(layers, cfg);
  const areas: SupportAreas[] = yield* cfg.supportType === 'tree' ? treeSupport(model) : normalSupport(model);
  return layers.map((_, j) => {
    const a = areas[j];
    return a && (a.body.length || a.roof.length || a.floor.length) ? a : null;
  });
}

/** What the support pass gives one layer: its support areas, and with several objects each one's. */
export interface LayerSupport {
  /** The layer's support (with several objects, all of theirs together), or null: none. */
  support: SupportAreas | null;
  /** With several objects: per object, its own support (which prints, and is cancelled, with it). */
  supports?: (SupportAreas | null)[];
}

/**
 * The support of every object, each with its own config (`objectConfigs[o]` indexes `configs`), per layer
 * (null: the layer keeps what it has). An object has overhangs only where its support is on or enforced (the
 * regions stage), so this holds up exactly those. One object: `support`. Several: `supports[o]` per object
 * and `support` all of them together.
 */
export function* objectsSupport(
  layers: readonly LayerOutlines[],
  configs: readonly Config[],
  objectConfigs: readonly number[],
): Generator<void, (LayerSupport | null)[]> {
  if (!layers.some((l) => l.overhangs)) {
    const areas = yield* supportAreas(layers, configs[objectConfigs[0] ?? 0]);
    return layers.map((_, j) => (areas ? { support: areas[j] } : null));
  }
  const perObject: ((SupportAreas | null)[] | null)[] = [];
  for (let o = 0; o < objectConfigs.length; o++) {
    // the object's overhangs, with every object's sections (support keeps clear of all of them)
    const view = layers.map((l) => ({ ...l, overhang: l.overhangs?.[o] ?? [] }));
    perObject.push(yield* supportAreas(view, configs[objectConfigs[o]]));
  }
  return layers.map((_, j) => {
    const own = perObject.map((p) => p?.[j] ?? null);
    return own.every((a) => a === null) ? null : { support: mergeAreas(own), supports: own };
  });
}

/** Write what the support pass gave each layer onto it, where the raft, the skirt and the paths read it. */
export function attachSupport(layers: readonly LayerOutlines[], support: readonly (LayerSupport | null)[]): void {
  for (let j = 0; j < layers.length; j++) {
    const s = support[j];
    if (!s) continue;
    layers[j].support = s.support;
    if (s.supports) layers[j].supports = s.supports;
  }
}

/** Several objects' support areas as one (for the raft, the skirt and skin resting on support). */
function mergeAreas(list: readonly (SupportAreas | null)[]): SupportAreas {
  const out: SupportAreas = { body: [], roof: [], floor: [] };
  for (const a of list) {
    if (!a) continue;
    out.body.push(...a.body);
    out.roof.push(...a.roof);
    out.floor.push(...a.floor);
  }
  return out;
}
