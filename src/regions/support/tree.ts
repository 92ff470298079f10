/** Tree support (placeholder until the tree generator lands): normal columns. */
import type { SupportAreas } from '../types.js';
import type { ModelLayers } from './model-layers.js';
import { normalSupport } from './normal.js';

export function* treeSupport(model: ModelLayers): Generator<void, SupportAreas[]> {
  return yield* normalSupport(model);
}
