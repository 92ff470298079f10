/** Mesh input: file parsers, three.js and raw-array adapters, preparation and bed placement (writing a 3MF project with its settings is profiles/threemf-write.ts). */
export type {
  LayerRangeSettings,
  Mesh,
  MeshObject,
  MeshReport,
  MeshVolume,
  RawMeshArrays,
  SettingsSource,
  VolumeKind,
} from './types.js';
export { parseStl } from './stl.js';
export { parseObj } from './obj.js';
export { parse3mf } from './threemf.js';
export { parse3mfProject, type ThreeMfProject } from './threemf-project.js';
export { fromThree } from './three.js';
export { fromArrays } from './arrays.js';
export { prepareMesh, positionBounds, type PreparedMesh } from './prepare.js';
export { weld } from './weld.js';
export { mergeObjects, placeModels, type ModelInput, type PlaceOptions, type PlacedModels } from './place.js';
export { arrange, arrangeAll, findSpot, type Bed, type Footprint } from './arrange.js';
export {
  detectFormat,
  loadModelBytes,
  loadModelFile,
  toMeshObjects,
  toModels,
  type LoadOptions,
  type LoadedFile,
  type LoadedModels,
  type ModelFormat,
} from './load.js';
