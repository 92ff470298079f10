/**
 * Turning one expanded build item into a MeshObject once a project reader has said what each run of its
 * triangles is: printed part, modifier, negative volume, support blocker or enforcer. Parts become the
 * object's mesh; every other piece a volume, in the same (build) coordinates. A part with settings of its
 * own prints with the others and is also a modifier volume carrying those settings.
 */
import { StrataError } from '../errors.js';
import type { ExpandedItem } from './threemf.js';
import type { LayerRangeSettings, Mesh, MeshObject, MeshVolume, SettingsSource, VolumeKind } from './types.js';
import { weld } from './weld.js';

/** Most volumes one object may have. */
export const MAX_VOLUMES = 10_000;

/** Triangles of an expanded item: `start` and `count` in triangles. */
export interface TriangleRun {
  start: number;
  count: number;
}

export interface PieceSpec {
  kind: 'part' | VolumeKind;
  name: string;
  runs: TriangleRun[];
  settings?: SettingsSource;
}

export interface ObjectSpec {
  name: string;
  /** The object's id in the project's config, when it has one there. */
  id?: number;
  pieces: PieceSpec[];
  settings?: SettingsSource;
  layerRanges?: LayerRangeSettings[];
  layerHeightProfile?: number[];
}

/** An assembled item: an object, or (when it has no printed part) only volumes for another object to take. */
export interface Assembled {
  object: MeshObject | null;
  volumes: MeshVolume[];
}

export function assemble(e: ExpandedItem, spec: ObjectSpec): Assembled {
  const total = e.indices.length / 3;
  const cutter = new MeshCutter(e);
  const parts = spec.pieces.filter((p) => p.kind === 'part');
  const volumes: MeshVolume[] = [];
  for (const p of spec.pieces) {
    if (p.kind === 'part' && p.settings === undefined) continue;
    if (volumes.length >= MAX_VOLUMES)
      throw new StrataError('LIMIT_EXCEEDED', `3MF: object "${spec.name}" has more than ${MAX_VOLUMES} volumes`);
    const v: MeshVolume = { kind: p.kind === 'part' ? 'modifier' : p.kind, name: p.name, mesh: cutter.mesh(p.runs) };
    if (p.settings !== undefined) v.settings = p.settings;
    volumes.push(v);
  }
  const partRuns = parts.flatMap((p) => p.runs);
  if (countOf(partRuns) === 0) return { object: null, volumes };
  const mesh = countOf(partRuns) === total ? weld(e.positions, e.indices, '3MF') : cutter.mesh(partRuns);
  const object: MeshObject = { name: spec.name, mesh };
  if (volumes.length > 0) object.volumes = volumes;
  if (spec.settings !== undefined) object.settings = spec.settings;
  if (spec.layerRanges !== undefined && spec.layerRanges.length > 0) object.layerRanges = spec.layerRanges;
  if (spec.layerHeightProfile !== undefined) object.layerHeightProfile = spec.layerHeightProfile;
  return { object, volumes: [] };
}

function countOf(runs: readonly TriangleRun[]): number {
  let n = 0;
  for (const r of runs) n += r.count;
  return n;
}

/**
 * Copies runs of an item's triangles into meshes of their own: only the vertices the triangles use are
 * copied (a stamp per vertex marks which, so a piece costs its own size, not the item's), then welded.
 */
class MeshCutter {
  readonly #e: ExpandedItem;
  #stamp: Int32Array | null = null;
  #remap: Uint32Array | null = null;
  #gen = 0;

  constructor(e: ExpandedItem) {
    this.#e = e;
  }

  mesh(runs: readonly TriangleRun[]): Mesh {
    const { positions, indices } = this.#e;
    const nv = positions.length / 3;
    this.#stamp ??= new Int32Array(nv).fill(-1);
    this.#remap ??= new Uint32Array(nv);
    const stamp = this.#stamp;
    const remap = this.#remap;
    const gen = ++this.#gen;
    const corners = countOf(runs) * 3;
    const outIdx = new Uint32Array(corners);
    let used = 0;
    let c = 0;
    for (const r of runs) {
      for (let i = r.start * 3, end = (r.start + r.count) * 3; i < end; i++) {
        const v = indices[i];
        if (stamp[v] !== gen) {
          stamp[v] = gen;
          remap[v] = used++;
        }
        outIdx[c++] = remap[v];
      }
    }
    const outPos = new Float32Array(used * 3);
    for (const r of runs) {
      for (let i = r.start * 3, end = (r.start + r.count) * 3; i < end; i++) {
        const v = indices[i];
        const o = remap[v] * 3;
        outPos[o] = positions[v * 3];
        outPos[o + 1] = positions[v * 3 + 1];
        outPos[o + 2] = positions[v * 3 + 2];
      }
    }
    return weld(outPos, outIdx, '3MF');
  }
}
