/**
 * Plain-data meshes. Positions are millimetres, Z up; a mesh crosses a worker boundary as typed arrays.
 */

/** An indexed triangle mesh in mm. `positions` holds x,y,z per vertex; `indices` three vertex ids per triangle. */
export interface Mesh {
  positions: Float32Array;
  indices: Uint32Array;
}

/** Raw typed arrays as a caller (or the Doodle3D worker protocol) hands them over. Unindexed when `indices` is absent. */
export interface RawMeshArrays {
  positions: Float32Array | Float64Array | number[];
  indices?: Uint32Array | Uint16Array | number[];
}

/** One named object of a loaded model (a 3MF object/build item, an OBJ group, a three.js mesh). */
export interface MeshObject {
  name: string;
  mesh: Mesh;
}

/** What mesh preparation found: counts and human-readable warnings. */
export interface MeshReport {
  triangles: number;
  vertices: number;
  degenerateRemoved: number;
  openEdges: number;
  nonManifoldEdges: number;
  /** Signed volume in mm³ (positive for outward-facing closed meshes). */
  volume: number;
  min: [number, number, number];
  max: [number, number, number];
  warnings: string[];
}
