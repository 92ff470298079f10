/**
 * The support pass: a whole-model pass over the layers' regions (their sections and overhangs) that fills
 * in each layer's support areas, normal or tree. With several objects each object's support is its own,
 * made with the object's settings, so that it prints (and is cancelled) with the object.
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

/**
 * The support of every object, each with its own config (`objectConfigs[o]` indexes `configs`). An object
 * has overhangs only where its support is on or enforced (the regions stage), so this holds up exactly those.
 * One object: `support` as before. Several: `supports[o]` per object and `support` all of them together.
 */
export function* objectsSupportPass(
  layers: LayerOutlines[],
  configs: readonly Config[],
  objectConfigs: readonly number[],
): Generator<void, void> {
  if (!layers.some((l) => l.overhangs)) {
    const areas = yield* supportAreas(layers, configs[objectConfigs[0] ?? 0]);
    if (areas) for (let j = 0; j < layers.length; j++) layers[j].support = areas[j];
    return;
  }
  const perObject: ((SupportAreas | null)[] | null)[] = [];
  for (let o = 0; o < objectConfigs.length; o++) {
    // the object's overhangs, with every object's sections (support keeps clear of all of them)
    const view = layers.map((l) => ({ ...l, overhang: l.overhangs?.[o] ?? [] }));
    perObject.push(yield* supportAreas(view, configs[objectConfigs[o]]));
  }
  if (perObject.every((p) => p === null)) return;
  for (let j = 0; j < layers.length; j++) {
    const own = perObject.map((p) => p?.[j] ?? null);
    if (own.every((a) => a === null)) continue;
    layers[j].supports = own;
    layers[j].support = mergeAreas(own);
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
