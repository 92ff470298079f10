/** `strata info`: what is in a model file (triangles, size, volume, open and non-manifold edges), as text or JSON. */
import { basename } from 'node:path';
import { StrataError } from '../errors.js';
import { loadModelFile, prepareMesh } from '../mesh/index.js';
import type { MeshReport } from '../mesh/types.js';
import { SCHEMA } from '../settings/schema.js';
import type { ParsedArgs } from './args.js';
import { InputReader } from './inputs.js';

const MiB = 1024 * 1024;

export interface ModelInfo {
  file: string;
  /** Each object: its triangles, and what a project gives it (volumes by kind and name, settings, layer ranges). */
  objects: Array<{
    name: string;
    triangles: number;
    volumes?: Array<{ kind: string; name: string; triangles: number; settings?: Record<string, unknown> }>;
    settings?: Record<string, unknown>;
    layerRanges?: Array<{ fromZ: number; toZ: number; settings: Record<string, unknown> }>;
  }>;
  /** A project's print settings, as the file gives them (its slicer's keys). */
  projectSettings?: { format: string; count: number };
  triangles: number;
  vertices: number;
  degenerateRemoved: number;
  /** Size in X, Y and Z, mm. */
  size: [number, number, number];
  min: [number, number, number];
  max: [number, number, number];
  volumeMm3: number;
  openEdges: number;
  nonManifoldEdges: number;
  watertight: boolean;
  warnings: string[];
}

/** The report of one model file, over all its objects (each prepared on its own, as slicing does). */
export function modelInfo(file: string, bytes: Uint8Array, maxInflatedBytes: number): ModelInfo {
  const loaded = loadModelFile(bytes, file === '-' ? undefined : basename(file), { maxInflatedBytes });
  const objects = loaded.objects;
  const reports: MeshReport[] = objects.map((o) => prepareMesh(o.mesh).report);
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  const sum = (f: (r: MeshReport) => number) => reports.reduce((s, r) => s + f(r), 0);
  for (const r of reports) {
    if (r.triangles === 0) continue;
    for (let k = 0; k < 3; k++) {
      min[k] = Math.min(min[k], r.min[k]);
      max[k] = Math.max(max[k], r.max[k]);
    }
  }
  if (min[0] === Infinity) min.fill(0), max.fill(0);
  const openEdges = sum((r) => r.openEdges);
  const nonManifoldEdges = sum((r) => r.nonManifoldEdges);
  const several = objects.length > 1;
  return {
    file,
    objects: objects.map((o, i) => ({
      name: o.name,
      triangles: reports[i].triangles,
      ...(o.volumes?.length
        ? {
            volumes: o.volumes.map((v) => ({
              kind: v.kind,
              name: v.name,
              triangles: v.mesh.indices.length / 3,
              ...(v.settings ? { settings: { ...v.settings.values } } : {}),
            })),
          }
        : {}),
      ...(o.settings ? { settings: { ...o.settings.values } } : {}),
      ...(o.layerRanges?.length
        ? {
            layerRanges: o.layerRanges.map((r) => ({ fromZ: r.fromZ, toZ: r.toZ, settings: { ...r.settings.values } })),
          }
        : {}),
    })),
    ...(loaded.projectSettings
      ? {
          projectSettings: {
            format: loaded.projectSettings.format,
            count: Object.keys(loaded.projectSettings.values).length,
          },
        }
      : {}),
    triangles: sum((r) => r.triangles),
    vertices: sum((r) => r.vertices),
    degenerateRemoved: sum((r) => r.degenerateRemoved),
    size: [max[0] - min[0], max[1] - min[1], max[2] - min[2]],
    min,
    max,
    volumeMm3: Math.abs(sum((r) => r.volume)),
    openEdges,
    nonManifoldEdges,
    watertight: openEdges === 0 && nonManifoldEdges === 0,
    warnings: [
      ...loaded.warnings,
      ...reports.flatMap((r, i) => r.warnings.map((w) => (several ? `${objects[i].name}: ${w}` : w))),
    ],
  };
}

function text(info: ModelInfo): string {
  const f2 = (v: number) => v.toFixed(2);
  return [
    `${info.file}:`,
    `  objects:            ${info.objects.length}`,
    `  triangles:          ${info.triangles}${info.degenerateRemoved ? ` (${info.degenerateRemoved} degenerate removed)` : ''}`,
    `  size:               ${info.size.map(f2).join(' × ')} mm`,
    `  bounds:             (${info.min.map(f2).join(', ')}) – (${info.max.map(f2).join(', ')})`,
    `  volume:             ${(info.volumeMm3 / 1000).toFixed(2)} cm³`,
    `  open edges:         ${info.openEdges}`,
    `  non-manifold edges: ${info.nonManifoldEdges}`,
    `  watertight:         ${info.watertight ? 'yes' : 'no'}`,
    ...(info.projectSettings
      ? [`  project:            ${info.projectSettings.count} print settings (${info.projectSettings.format})`]
      : []),
    ...info.objects.flatMap((o) => {
      const own = (s?: Record<string, unknown>) =>
        s && Object.keys(s).length
          ? ` (${Object.entries(s)
              .map(([k, v]) => `${k}=${String(v)}`)
              .join(', ')})`
          : '';
      const lines = [
        ...(o.volumes ?? []).map((v) => `    ${v.kind} "${v.name}": ${v.triangles} triangles${own(v.settings)}`),
        ...(o.layerRanges ?? []).map((r) => `    layers ${r.fromZ}–${r.toZ} mm${own(r.settings)}`),
      ];
      return o.settings || lines.length ? [`  object "${o.name}"${own(o.settings)}`, ...lines] : [];
    }),
  ].join('\n');
}

export async function cmdInfo(args: ParsedArgs, write: (s: string) => void): Promise<void> {
  if (args.positional.length === 0) throw new StrataError('BAD_FILE', 'info needs a model file');
  const input = new InputReader();
  const infos: ModelInfo[] = [];
  for (const p of args.positional)
    infos.push(modelInfo(p, await input.bytes(p, 'model', 'model'), Number(SCHEMA.inflateBudget.default) * MiB));
  if (args.flags.json === true) write(JSON.stringify(infos, null, 2) + '\n');
  else for (const i of infos) write(text(i) + '\n');
}
