/**
 * The support pass: a whole-model pass over the layers' regions (their sections and overhangs) that fills
 * in each layer's support areas, normal or tree.
 */
import type { Config } from '../../settings/resolve.js';
import type { LayerRegions, SupportAreas } from '../types.js';
import { ModelLayers } from './model-layers.js';
import { normalSupport } from './normal.js';
import { treeSupport } from './tree.js';

/** Compute every layer's support (written to `layers[j].support`); yields between layers. */
export function* supportPass(layers: LayerRegions[], cfg: Config): Generator<void, void> {
  if (!cfg.supportEnabled || layers.length === 0) return;
  if (!layers.some((l) => l.overhang.length > 0)) return;
  const model = new ModelLayers(layers, cfg);
  const areas: SupportAreas[] = yield* cfg.supportType === 'tree' ? treeSupport(model) : normalSupport(model);
  for (let j = 0; j < layers.length; j++) {
    const a = areas[j];
    layers[j].support = a && (a.body.length || a.roof.length || a.floor.length) ? a : null;
  }
}
