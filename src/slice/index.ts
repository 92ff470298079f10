/** Slicing: the layer plan and mesh cross-sections. */
export type { LayerSection, LayerZ } from './types.js';
export { evenLayers, planLayers, planVaryingLayers, toHalfUm, HALF_UM_PER_MM, MAX_LAYERS } from './layers.js';
export { sliceMesh, slicePrepared, SectionStream, DEFAULT_MAX_GAP_MM, DEFAULT_MIN_AREA_UM2 } from './slice-mesh.js';
export type { SliceOptions } from './slice-mesh.js';
export { prepareMesh, sweepLayers, PlaneSweep } from './intersect.js';
export type { PreparedMesh, LayerSegments } from './intersect.js';
export { chainSegments } from './chain.js';
export type { Chains } from './chain.js';
export { closeOpenChains } from './gaps.js';
export { ringsToIslands } from './islands.js';
export { simplifySlotRings } from './simplify.js';
export { buildEdgeTable, findShells } from './topology.js';
export type { EdgeTable, Shells } from './topology.js';
