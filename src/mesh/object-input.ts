/**
 * An object as a library caller describes it: a mesh (any model input: bytes, text, three.js, arrays, a
 * Mesh) with settings of its own, volumes and layer ranges:
 *
 *   { mesh, name?, settings?: { infillDensity: 40 },
 *     volumes?: [{ type: 'modifier', mesh, settings: { infillDensity: 80 } }, { type: 'negative', mesh }],
 *     layerRanges?: [{ fromZ: 10, toZ: 12, settings: { infillDensity: 100 } }] }
 *
 * Volumes are in the same coordinates as the mesh and move with it; a volume of type 'part' is one more
 * printed part (overlapping parts print once).
 */
import { StrataError } from '../errors.js';
import { mergeObjects } from './place.js';
import type { LayerRangeSettings, MeshObject, MeshVolume, SettingsSource, VolumeKind } from './types.js';

const KINDS: readonly (VolumeKind | 'part')[] = ['part', 'modifier', 'negative', 'support-blocker', 'support-enforcer'];

/** Most volumes and layer ranges one object may have. */
const MAX_VOLUMES = 1000;

/** Whether a value is an object description (a `mesh` with settings, volumes, layer ranges or a layer height profile). */
export function isObjectInput(v: unknown): boolean {
  if (typeof v !== 'object' || v === null || Array.isArray(v) || !('mesh' in v)) return false;
  const o = v as Record<string, unknown>;
  return 'settings' in o || 'volumes' in o || 'layerRanges' in o || 'layerHeightProfile' in o;
}

const FORMATS: readonly SettingsSource['format'][] = ['strata', 'prusaslicer', 'orcaslicer', 'cura'];

/** Settings as given: Strata keys, or a `SettingsSource` (`{ format, values }`, as a project file's objects carry them). */
function settingsOf(v: unknown, what: string): MeshObject['settings'] {
  if (v === undefined) return undefined;
  if (typeof v !== 'object' || v === null || Array.isArray(v))
    throw new StrataError('BAD_SETTING', `${what}: settings must be an object of settings`);
  const o = v as Record<string, unknown>;
  if (
    Object.keys(o).length === 2 &&
    FORMATS.includes(o.format as never) &&
    typeof o.values === 'object' &&
    o.values !== null
  ) {
    return { format: o.format as SettingsSource['format'], values: { ...(o.values as Record<string, unknown>) } };
  }
  return { format: 'strata', values: { ...o } };
}

function list(v: unknown, what: string): unknown[] {
  if (v === undefined) return [];
  if (!Array.isArray(v)) throw new StrataError('UNSUPPORTED_FORMAT', `${what} must be a list`);
  if (v.length > MAX_VOLUMES) throw new StrataError('LIMIT_EXCEEDED', `${what}: more than ${MAX_VOLUMES}`);
  return v;
}

/** One object from its description; `toObjects` reads any model input into objects. */
export function objectFromInput(
  input: Record<string, unknown>,
  toObjects: (mesh: unknown) => MeshObject[],
  index: number,
): MeshObject {
  const name = typeof input.name === 'string' && input.name !== '' ? input.name : undefined;
  const label = name ?? `object ${index + 1}`;
  const parts = toObjects(input.mesh);
  const volumes: MeshVolume[] = [];
  list(input.volumes, `${label}: volumes`).forEach((raw, k) => {
    if (typeof raw !== 'object' || raw === null)
      throw new StrataError(
        'UNSUPPORTED_FORMAT',
        `${label}: volume ${k + 1} must be an object { type, mesh, settings? }`,
      );
    const v = raw as Record<string, unknown>;
    const kind = (v.type ?? v.kind) as VolumeKind | 'part';
    if (!KINDS.includes(kind)) {
      throw new StrataError(
        'UNSUPPORTED_FORMAT',
        `${label}: volume ${k + 1} has type ${JSON.stringify(kind)}; expected one of ${KINDS.join(', ')}`,
      );
    }
    const vname = typeof v.name === 'string' && v.name !== '' ? v.name : `${kind} ${k + 1}`;
    const meshes = toObjects(v.mesh);
    const mesh = meshes.length === 1 ? meshes[0].mesh : mergeObjects(meshes);
    const settings = settingsOf(v.settings, `${label}: ${vname}`);
    if (kind === 'part') {
      parts.push({ name: vname, mesh });
      // a part with settings of its own is a part and a modifier over it
      if (settings) volumes.push({ kind: 'modifier', name: vname, mesh, settings });
      return;
    }
    if (settings && kind !== 'modifier')
      throw new StrataError(
        'BAD_SETTING',
        `${label}: ${vname} is a ${kind}, which takes no settings (a modifier does)`,
      );
    volumes.push(settings ? { kind, name: vname, mesh, settings } : { kind, name: vname, mesh });
  });
  const layerRanges: LayerRangeSettings[] = list(input.layerRanges, `${label}: layerRanges`).map((raw, k) => {
    const r = raw as Record<string, unknown>;
    const fromZ = r?.fromZ,
      toZ = r?.toZ;
    if (
      typeof fromZ !== 'number' ||
      typeof toZ !== 'number' ||
      !Number.isFinite(fromZ) ||
      !Number.isFinite(toZ) ||
      !(toZ > fromZ) ||
      fromZ < 0
    ) {
      throw new StrataError(
        'BAD_SETTING',
        `${label}: layer range ${k + 1} needs numbers 0 ≤ fromZ < toZ (mm from the bed), got ${JSON.stringify({ fromZ, toZ })}`,
      );
    }
    return { fromZ, toZ, settings: settingsOf(r.settings ?? {}, `${label}: layer range ${fromZ}–${toZ} mm`)! };
  });
  const profile = input.layerHeightProfile;
  if (profile !== undefined && !isHeightProfile(profile)) {
    throw new StrataError(
      'BAD_SETTING',
      `${label}: layerHeightProfile needs numbers z0, h0, z1, h1, … (mm, at least two points, Z from 0 rising, heights above 0)`,
    );
  }
  const out: MeshObject = {
    name: name ?? (parts.length === 1 ? parts[0].name : label),
    mesh: parts.length === 1 ? parts[0].mesh : mergeObjects(parts),
  };
  if (profile !== undefined) out.layerHeightProfile = [...(profile as number[])];
  const settings = settingsOf(input.settings, label);
  if (settings) out.settings = settings;
  if (volumes.length) out.volumes = volumes;
  if (layerRanges.length) out.layerRanges = layerRanges;
  return out;
}

/** Whether `v` is a layer height profile: z0, h0, z1, h1, … with Z from 0 rising and heights above 0. */
function isHeightProfile(v: unknown): boolean {
  return (
    Array.isArray(v) &&
    v.length >= 4 &&
    v.length % 2 === 0 &&
    v.every(
      (x, i) =>
        typeof x === 'number' && Number.isFinite(x) && (i % 2 === 0 ? x >= 0 && (i === 0 || x > v[i - 2]) : x > 0),
    )
  );
}
