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

/**
 * Settings as a file or a caller gave them, before they are checked against the schema: Strata's own keys
 * and values, or another slicer's (PrusaSlicer/OrcaSlicer config keys, Cura setting keys, values as text),
 * which profiles/ maps onto ours.
 */
export interface SettingsSource {
  format: 'strata' | 'prusaslicer' | 'orcaslicer' | 'cura';
  values: Readonly<Record<string, unknown>>;
}

/**
 * What a volume of an object does: a modifier changes the settings inside it (and is not printed), a
 * negative volume is cut out of the parts, support blockers and enforcers keep support out of, or put it
 * under, the overhangs inside them.
 */
export type VolumeKind = 'modifier' | 'negative' | 'support-blocker' | 'support-enforcer';

/** A volume of an object other than its printed parts, in the same coordinates as the object's mesh. */
export interface MeshVolume {
  kind: VolumeKind;
  name: string;
  mesh: Mesh;
  /** A modifier's settings (region-scoped ones only). */
  settings?: SettingsSource;
}

/** Settings for the layers of one object whose Z (from the bed, mm) lies in [fromZ, toZ). */
export interface LayerRangeSettings {
  fromZ: number;
  toZ: number;
  settings: SettingsSource;
}

/**
 * One named object of a loaded model (a 3MF object/build item, an OBJ group, a three.js mesh). Its mesh is
 * every printed part of it together (overlapping parts print once); a project file or the caller may add
 * volumes, settings of its own and settings for ranges of its layers.
 */
export interface MeshObject {
  name: string;
  mesh: Mesh;
  /** Modifiers, negative volumes, support blockers and enforcers, in the order they apply. */
  volumes?: MeshVolume[];
  /** The object's own settings (object- and region-scoped ones), over the print's. */
  settings?: SettingsSource;
  layerRanges?: LayerRangeSettings[];
  /**
   * Variable layer height (PrusaSlicer's and OrcaSlicer's per-object profile): z0, h0, z1, h1, … in mm from
   * the object's bottom, Z rising; a layer's height is the profile's at its bottom (linear between points).
   */
  layerHeightProfile?: number[];
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
