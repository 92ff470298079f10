import type { ExPolygon } from '../geometry/types.js';

/** The Z plan of the print: one entry per layer. */
export interface LayerZ {
  /** Layer index, 0 = first layer on the bed. */
  index: number;
  /** Nozzle height when printing this layer (top of the layer), mm. */
  z: number;
  /** Layer thickness, mm. */
  height: number;
  /** Height at which the mesh is cut for this layer (mid-height of the layer), mm. */
  sliceZ: number;
}

/** One layer's cross-section: islands (outer ring + holes) in integer µm. */
export interface LayerSection extends LayerZ {
  islands: ExPolygon[];
}
