/**
 * PrusaSlicer and OrcaSlicer / Bambu Studio projects: what each build item's triangles are, from the model
 * config (threemf-configs.ts), as the slicers themselves read it (PrusaSlicer `src/libslic3r/Format/3mf.cpp`,
 * Orca `bbs_3mf.cpp`):
 * - PrusaSlicer keeps all volumes of an object in one mesh, already in the object's coordinates (the volume
 *   matrix is applied before saving); `<volume firstid lastid>` are inclusive triangle ranges of it, and
 *   `volume_type` (or the older `modifier` = 1) says what each is. Triangles in no range are dropped, as
 *   PrusaSlicer drops them. Instances are further objects whose one component is the first.
 * - Orca keeps each volume as an object of its own (often in `3D/Objects/*.model`), a component of the
 *   object with the volume's matrix as its transform; `<part id subtype>` names the component. Older
 *   Bambu files use PrusaSlicer's triangle ranges (`firstid`/`lastid`) instead.
 * - Layer ranges are listed by the object's place among the project's objects (1-based): PrusaSlicer
 *   counts the model's mesh objects in file order, Orca the objects in the order the build first places them.
 * Every other metadata key of an object or volume is a setting, kept raw with the slicer's format.
 */
import { StrataError } from '../errors.js';
import { MAX_VOLUMES, type ObjectSpec, type PieceSpec, type TriangleRun } from './threemf-assemble.js';
import type { ConfigObject, ConfigRange, ConfigVolume } from './threemf-configs.js';
import type { ModelObject } from './threemf-model.js';
import type { Build, BuildItem, ExpandedItem } from './threemf.js';
import type { LayerRangeSettings, SettingsSource, VolumeKind } from './types.js';

type Slic3rFormat = 'prusaslicer' | 'orcaslicer';

/** Metadata keys that describe an object or volume rather than set anything. */
const NOT_SETTINGS = new Set([
  'name',
  'volume_type',
  'modifier',
  'matrix',
  'extruder',
  'module',
  'mesh_shared',
  'part_type',
]);

const PRUSA_TYPES: Readonly<Record<string, 'part' | VolumeKind>> = {
  ModelPart: 'part',
  NegativeVolume: 'negative',
  ParameterModifier: 'modifier',
  SupportBlocker: 'support-blocker',
  SupportEnforcer: 'support-enforcer',
};
const ORCA_TYPES: Readonly<Record<string, 'part' | VolumeKind>> = {
  normal_part: 'part',
  negative_part: 'negative',
  modifier_part: 'modifier',
  support_blocker: 'support-blocker',
  support_enforcer: 'support-enforcer',
};

/** The settings among an object's or volume's metadata, or undefined when there are none. */
export function metadataSettings(
  metadata: ReadonlyMap<string, string>,
  format: SettingsSource['format'],
): SettingsSource | undefined {
  const values: Record<string, string> = {};
  let any = false;
  for (const [k, v] of metadata) {
    if (NOT_SETTINGS.has(k) || k.startsWith('source_')) continue;
    values[k] = v;
    any = true;
  }
  return any ? { format, values } : undefined;
}

/** Layer ranges of one object in our terms. */
export function layerRanges(
  list: readonly ConfigRange[] | undefined,
  format: SettingsSource['format'],
): LayerRangeSettings[] | undefined {
  if (list === undefined || list.length === 0) return undefined;
  return list.map((r) => ({ fromZ: r.minZ, toZ: r.maxZ, settings: { format, values: Object.fromEntries(r.options) } }));
}

export interface Slic3rProject {
  format: Slic3rFormat;
  config: ReadonlyMap<number, ConfigObject>;
  ranges?: ReadonlyMap<number, ConfigRange[]>;
  /** Variable layer height profiles by object number. */
  profiles?: ReadonlyMap<number, number[]>;
}

/** What each of an item's triangles is, for a PrusaSlicer project. */
export function prusaPlanner(
  build: Build,
  project: Slic3rProject,
  warnings: string[],
): (item: BuildItem, e: ExpandedItem) => ObjectSpec {
  // PrusaSlicer numbers its objects as the model's mesh objects come
  const objectNumber = new Map<ModelObject, number>();
  for (const o of build.root.objects.values())
    if (o.triangles !== null && o.triangles.length > 0) objectNumber.set(o, objectNumber.size + 1);
  return (item, e) => {
    const found = configObject(build, item, project.config);
    if (found === null) return wholeItem(item, e);
    const { object, cfg } = found;
    const name = cfg.metadata.get('name') || item.label;
    const seg = e.segments.find((s) => s.path[s.path.length - 1] === object);
    const pieces: PieceSpec[] = [];
    // triangles of other objects under the item (not PrusaSlicer's layout) print as they are
    const others = e.segments.filter((s) => s !== seg).map((s): TriangleRun => ({ start: s.start, count: s.count }));
    if (others.length > 0) pieces.push({ kind: 'part', name, runs: others });
    if (seg !== undefined) {
      if (cfg.volumes.length === 0) pieces.push({ kind: 'part', name, runs: [{ start: seg.start, count: seg.count }] });
      else pieces.push(...rangePieces(cfg, cfg.volumes, seg.start, seg.count, name, project.format, warnings));
    }
    const spec: ObjectSpec = { name, id: cfg.id, pieces };
    const settings = metadataSettings(cfg.metadata, project.format);
    if (settings !== undefined) spec.settings = settings;
    const n = objectNumber.get(object);
    const ranges = layerRanges(n === undefined ? undefined : project.ranges?.get(n), project.format);
    if (ranges !== undefined) spec.layerRanges = ranges;
    const profile = n === undefined ? undefined : project.profiles?.get(n);
    if (profile !== undefined) spec.layerHeightProfile = profile;
    return spec;
  };
}

/** What each of an item's triangles is, for an OrcaSlicer / Bambu Studio project. */
export function orcaPlanner(
  build: Build,
  project: Slic3rProject,
  warnings: string[],
): (item: BuildItem, e: ExpandedItem) => ObjectSpec {
  const objectNumber = new Map<ModelObject, number>();
  for (const item of build.items) {
    const o = build.lookup(item.key, item.ref.objectId);
    if (!objectNumber.has(o)) objectNumber.set(o, objectNumber.size + 1);
  }
  return (item, e) => {
    const object = build.lookup(item.key, item.ref.objectId);
    const cfg = item.key === build.rootKey ? project.config.get(object.id) : undefined;
    if (cfg === undefined) return wholeItem(item, e);
    const name = cfg.metadata.get('name') || item.label;
    const claimed = new Set<number>();
    const pieces: PieceSpec[] = [];
    if (cfg.volumes.length > MAX_VOLUMES) tooManyVolumes(name);
    // the older layout: triangle ranges of the object's own mesh
    const ranged = cfg.volumes.filter((v) => v.lastId !== null && v.lastId > 0);
    const isRanged = new Set(ranged);
    if (ranged.length > 0) {
      const own = e.segments.findIndex((s) => s.path.length === 1);
      if (own < 0)
        throw new StrataError('BAD_FILE', `3MF: object ${cfg.id} lists triangle ranges but has no mesh of its own`);
      claimed.add(own);
      pieces.push(
        ...rangePieces(cfg, ranged, e.segments[own].start, e.segments[own].count, name, project.format, warnings),
      );
    }
    // the item's triangles by the component (of the item's object) they come from
    const byComponent = new Map<number, number[]>();
    e.segments.forEach((s, k) => {
      if (s.path.length < 2) return;
      const list = byComponent.get(s.path[1].id);
      if (list) list.push(k);
      else byComponent.set(s.path[1].id, [k]);
    });
    cfg.volumes.forEach((v, i) => {
      if (isRanged.has(v)) return;
      const runs: TriangleRun[] = [];
      for (const k of (v.id === null ? undefined : byComponent.get(v.id)) ?? []) {
        if (claimed.has(k)) continue;
        runs.push({ start: e.segments[k].start, count: e.segments[k].count });
        claimed.add(k);
      }
      if (runs.length === 0) {
        warnings.push(
          `3MF: object "${name}" lists a part ${v.id ?? '(without id)'} that is not one of its components; skipped`,
        );
        return;
      }
      pieces.push(
        piece(v, ORCA_TYPES[v.subtype] ?? 'part', runs, v.metadata.get('name') || `${name} ${i + 1}`, project.format),
      );
    });
    const rest = e.segments
      .filter((_, k) => !claimed.has(k))
      .map((s): TriangleRun => ({ start: s.start, count: s.count }));
    if (rest.length > 0) {
      warnings.push(
        `3MF: ${rest.length} component${rest.length === 1 ? '' : 's'} of object "${name}" are not listed in its config; printed as parts`,
      );
      pieces.unshift({ kind: 'part', name, runs: rest });
    }
    const spec: ObjectSpec = { name, id: cfg.id, pieces };
    const settings = metadataSettings(cfg.metadata, project.format);
    if (settings !== undefined) spec.settings = settings;
    const ranges = layerRanges(project.ranges?.get(objectNumber.get(object) ?? 0), project.format);
    if (ranges !== undefined) spec.layerRanges = ranges;
    const profile = project.profiles?.get(objectNumber.get(object) ?? 0);
    if (profile !== undefined) spec.layerHeightProfile = profile;
    return spec;
  };
}

/** The whole item as one printed part (no project data for it). */
export function wholeItem(item: BuildItem, e: ExpandedItem): ObjectSpec {
  return {
    name: item.label,
    pieces: [{ kind: 'part', name: item.label, runs: [{ start: 0, count: e.indices.length / 3 }] }],
  };
}

/**
 * The object of the project config an item places: its own, or (an instance) the one its only component
 * refers to, followed down. Config ids are object ids of the root part.
 */
function configObject(
  build: Build,
  item: BuildItem,
  config: ReadonlyMap<number, ConfigObject>,
): { object: ModelObject; cfg: ConfigObject } | null {
  let key = item.key;
  let object = build.lookup(key, item.ref.objectId);
  for (let depth = 0; depth < 32; depth++) {
    const cfg = key === build.rootKey ? config.get(object.id) : undefined;
    if (cfg !== undefined) return { object, cfg };
    if (object.vertices !== null || object.components.length !== 1) return null;
    const c = object.components[0];
    key = c.path ?? key;
    object = build.lookup(key, c.objectId);
  }
  return null;
}

/** Pieces from PrusaSlicer's inclusive triangle ranges, checked against the object's `count` triangles. */
function rangePieces(
  cfg: ConfigObject,
  volumes: readonly ConfigVolume[],
  start: number,
  count: number,
  name: string,
  format: Slic3rFormat,
  warnings: string[],
): PieceSpec[] {
  if (volumes.length > MAX_VOLUMES) tooManyVolumes(name);
  const index = new Map(cfg.volumes.map((v, i) => [v, i]));
  const order = volumes.map((v) => ({ v, i: index.get(v)! }));
  for (const { v, i } of order) {
    if (v.firstId === null || v.lastId === null)
      throw new StrataError('BAD_FILE', `3MF: volume ${i + 1} of object ${cfg.id} has no firstid and lastid`);
    if (v.lastId < v.firstId)
      throw new StrataError(
        'BAD_FILE',
        `3MF: volume ${i + 1} of object ${cfg.id} ends (triangle ${v.lastId}) before it starts (${v.firstId})`,
      );
    if (v.lastId >= count) {
      throw new StrataError(
        'BAD_FILE',
        `3MF: volume ${i + 1} of object ${cfg.id} covers triangles ${v.firstId}–${v.lastId}, but the object has ${count}`,
      );
    }
  }
  const sorted = [...order].sort((a, b) => a.v.firstId! - b.v.firstId!);
  let covered = 0;
  for (let k = 0; k < sorted.length; k++) {
    const { v, i } = sorted[k];
    if (k > 0 && v.firstId! <= sorted[k - 1].v.lastId!) {
      throw new StrataError(
        'BAD_FILE',
        `3MF: volumes ${sorted[k - 1].i + 1} and ${i + 1} of object ${cfg.id} share triangles (from ${v.firstId})`,
      );
    }
    covered += v.lastId! - v.firstId! + 1;
  }
  if (covered < count) {
    warnings.push(
      `3MF: ${count - covered} triangles of object "${name}" belong to no volume; dropped, as the slicer that wrote it drops them`,
    );
  }
  return order.map(({ v, i }) => {
    const kind = format === 'prusaslicer' ? prusaKind(v) : (ORCA_TYPES[v.subtype] ?? 'part');
    return piece(
      v,
      kind,
      [{ start: start + v.firstId!, count: v.lastId! - v.firstId! + 1 }],
      v.metadata.get('name') || `${name} ${i + 1}`,
      format,
    );
  });
}

function prusaKind(v: ConfigVolume): 'part' | VolumeKind {
  const type = v.metadata.get('volume_type');
  if (type !== undefined) return PRUSA_TYPES[type] ?? (type === '1' ? 'modifier' : 'part');
  return v.metadata.get('modifier') === '1' ? 'modifier' : 'part';
}

function piece(
  v: ConfigVolume,
  kind: 'part' | VolumeKind,
  runs: TriangleRun[],
  name: string,
  format: Slic3rFormat,
): PieceSpec {
  const p: PieceSpec = { kind, name, runs };
  const settings = metadataSettings(v.metadata, format);
  if (settings !== undefined) p.settings = settings;
  return p;
}

function tooManyVolumes(name: string): never {
  throw new StrataError('LIMIT_EXCEEDED', `3MF: object "${name}" has more than ${MAX_VOLUMES} volumes`);
}
