/** Mesh input: file parsers, three.js and raw-array adapters, preparation and bed placement. */
export type { Mesh, MeshObject, MeshReport, RawMeshArrays } from './types.js';
export { parseStl } from './stl.js';
export { parseObj } from './obj.js';
export { parse3mf } from './threemf.js';
export { fromThree } from './three.js';
export { fromArrays } from './arrays.js';
export { prepareMesh, positionBounds, type PreparedMesh } from './prepare.js';
export { weld } from './weld.js';
export { mergeObjects, placeOnBed, type PlaceOptions } from './place.js';
export { detectFormat, loadModelBytes, toMeshObjects, type ModelFormat } from './load.js';
