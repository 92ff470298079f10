/**
 * Strata's own project data, `Metadata/Strata_project.json`, written beside PrusaSlicer's layout by
 * threemf-write.ts: the print's settings and every object's settings, volumes and layer ranges in Strata's
 * keys, lossless where PrusaSlicer's keys are not. The geometry (which triangles are which volume) is read
 * from PrusaSlicer's model config; this file then replaces names, kinds and settings. A file that does not
 * match the geometry (edited by hand, or by another program) is reported and PrusaSlicer's data kept.
 */
import type { ObjectSpec, PieceSpec } from './threemf-assemble.js';
import type { LayerRangeSettings, SettingsSource, VolumeKind } from './types.js';

export const STRATA_PROJECT_VERSION = 1;

export interface StrataProjectVolume {
  kind: VolumeKind;
  name: string;
  settings: Record<string, unknown>;
}

export interface StrataProjectObject {
  /** The object's id in the 3MF model (and in PrusaSlicer's model config). */
  id: number;
  name: string;
  settings: Record<string, unknown>;
  volumes: StrataProjectVolume[];
  layerRanges: Array<{ fromZ: number; toZ: number; settings: Record<string, unknown> }>;
}

export interface StrataProject {
  version: number;
  printSettings: Record<string, unknown>;
  objects: StrataProjectObject[];
}

const KINDS: readonly VolumeKind[] = ['modifier', 'negative', 'support-blocker', 'support-enforcer'];

const isRecord = (v: unknown): v is Record<string, unknown> => typeof v === 'object' && v !== null && !Array.isArray(v);

/** The file's data, checked; a string saying what is wrong when it cannot be used. */
export function readStrataProject(text: string): StrataProject | string {
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch {
    return 'it is not valid JSON';
  }
  if (!isRecord(json)) return 'it is not a JSON object';
  if (json.version !== STRATA_PROJECT_VERSION)
    return `its version is ${JSON.stringify(json.version)}, not ${STRATA_PROJECT_VERSION}`;
  const printSettings = json.printSettings ?? {};
  if (!isRecord(printSettings)) return 'printSettings is not an object';
  if (!Array.isArray(json.objects)) return 'objects is not a list';
  const objects: StrataProjectObject[] = [];
  for (const [i, o] of json.objects.entries()) {
    const where = `object ${i + 1}`;
    if (!isRecord(o) || !Number.isInteger(o.id) || typeof o.name !== 'string') return `${where} needs an id and a name`;
    const settings = o.settings ?? {};
    const volumes = o.volumes ?? [];
    const ranges = o.layerRanges ?? [];
    if (!isRecord(settings) || !Array.isArray(volumes) || !Array.isArray(ranges))
      return `${where}: settings, volumes or layerRanges is malformed`;
    const vs: StrataProjectVolume[] = [];
    for (const v of volumes) {
      if (
        !isRecord(v) ||
        !KINDS.includes(v.kind as VolumeKind) ||
        typeof v.name !== 'string' ||
        !isRecord(v.settings ?? {})
      ) {
        return `${where}: a volume needs a kind (${KINDS.join(', ')}), a name and settings`;
      }
      vs.push({ kind: v.kind as VolumeKind, name: v.name, settings: (v.settings ?? {}) as Record<string, unknown> });
    }
    const rs: StrataProjectObject['layerRanges'] = [];
    for (const r of ranges) {
      if (
        !isRecord(r) ||
        typeof r.fromZ !== 'number' ||
        typeof r.toZ !== 'number' ||
        !(r.fromZ < r.toZ) ||
        !isRecord(r.settings ?? {})
      ) {
        return `${where}: a layer range needs fromZ below toZ and settings`;
      }
      rs.push({ fromZ: r.fromZ, toZ: r.toZ, settings: (r.settings ?? {}) as Record<string, unknown> });
    }
    rs.sort((a, b) => a.fromZ - b.fromZ);
    if (rs.some((r, k) => k > 0 && r.fromZ < rs[k - 1].toZ)) return `${where}: its layer ranges overlap`;
    objects.push({
      id: o.id as number,
      name: o.name,
      settings: settings as Record<string, unknown>,
      volumes: vs,
      layerRanges: rs,
    });
  }
  return { version: STRATA_PROJECT_VERSION, printSettings: printSettings as Record<string, unknown>, objects };
}

/** Strata settings of their own (instances of one object must not share them), or undefined when empty. */
const strata = (values: Record<string, unknown>): SettingsSource | undefined =>
  Object.keys(values).length > 0 ? { format: 'strata', values: { ...values } } : undefined;

/** Replace what PrusaSlicer's data says of an object (`spec`) with Strata's copy, found by the object's id. */
export function overlayStrata(
  spec: ObjectSpec,
  objects: ReadonlyMap<number, StrataProjectObject>,
  warnings: string[],
): ObjectSpec {
  const o = spec.id === undefined ? undefined : objects.get(spec.id);
  if (o === undefined) return spec;
  const volumePieces = spec.pieces.filter((p) => p.kind !== 'part');
  if (volumePieces.length !== o.volumes.length || volumePieces.some((p, i) => p.kind !== o.volumes[i].kind)) {
    warnings.push(
      `3MF: Strata's project data of object "${o.name}" does not match its volumes; PrusaSlicer's settings are used`,
    );
    return spec;
  }
  let k = 0;
  const pieces = spec.pieces.map((p): PieceSpec => {
    const out: PieceSpec = { kind: p.kind, name: p.name, runs: p.runs };
    if (p.kind === 'part') return out;
    const v = o.volumes[k++];
    out.name = v.name;
    const settings = strata(v.settings);
    if (settings !== undefined) out.settings = settings;
    return out;
  });
  const out: ObjectSpec = { name: o.name, pieces };
  const settings = strata(o.settings);
  if (settings !== undefined) out.settings = settings;
  const ranges: LayerRangeSettings[] = o.layerRanges.map((r) => ({
    fromZ: r.fromZ,
    toZ: r.toZ,
    settings: { format: 'strata', values: { ...r.settings } },
  }));
  if (ranges.length > 0) out.layerRanges = ranges;
  return out;
}
