/**
 * What the page's module worker does (worker.ts is its entry): reads models, slices (the library's worker
 * pool runs inside it when more threads are asked for), and builds the preview arrays, so the page thread
 * only draws. The page cancels a slice by ending the worker.
 */
import {
  Slicer,
  StrataError,
  loadCustomInfill,
  loadModelBytes,
  prepareMesh,
  prepareModel,
  resolveConfig,
} from '../../src/browser.js';
import { loadModelFile } from '../../src/mesh/load.js';
import { mergeObjects } from '../../src/mesh/place.js';
import { writeProject3mf } from '../../src/profiles/threemf-write.js';
import { settingsFromSource } from '../../src/profiles/object-settings.js';
import { toSlic3rKeys } from '../../src/profiles/to-slic3r.js';
import type { SettingKey } from '../../src/settings/schema.js';
import { SETTING_SCOPE, type ScopeUse } from '../../src/settings/scope.js';
import { linearBounds, placeObjects, placementAffine } from '../../src/mesh/placement.js';
import { determinant, transformPoints, type Affine } from '../../src/mesh/transform.js';
import type { MeshObject, SettingsSource } from '../../src/mesh/types.js';
import { estimatePlan } from '../../src/plan/estimate.js';
import { planToArrays, transferList } from '../../src/preview/plan-arrays.js';
import type {
  FromWorker,
  LoadedModel,
  LoadedProject,
  MeshArrays,
  ProjectObject,
  SliceItem,
  SliceVolume,
  ToWorker,
} from './protocol.js';
import { drawArrays } from './shapes.js';

const scope = globalThis as unknown as {
  postMessage(m: FromWorker, transfer?: Transferable[]): void;
  onmessage: ((e: MessageEvent<ToWorker>) => void) | null;
};

function post(m: FromWorker, transfer: Transferable[] = []): void {
  scope.postMessage(m, transfer);
}

/** The error in words for the page: a StrataError's own message, anything else named as internal. */
function describe(e: unknown): string {
  if (e instanceof StrataError) return e.message;
  return `internal error: ${e instanceof Error ? e.message : String(e)}`;
}

/**
 * Read a model file: one model of all its objects, or, for a 3MF with a slicer's project data (volumes,
 * settings of objects, layer ranges, print settings), its objects one by one with their data. `asMesh`
 * reads any file as one mesh (a volume's).
 */
function load(
  fileName: string,
  bytes: ArrayBuffer,
  asMesh: boolean,
): { model: LoadedModel | null; project: LoadedProject | null } {
  const file = loadModelFile(new Uint8Array(bytes), fileName);
  if (file.objects.length === 0) throw new StrataError('EMPTY_MODEL', `${fileName} holds no mesh`);
  const isProject =
    file.projectSettings !== undefined ||
    file.objects.some((o) => o.volumes?.length || o.settings || o.layerRanges?.length || o.layerHeightProfile);
  if (asMesh || !isProject) {
    const model = modelOf(fileName, file.objects);
    model.warnings.unshift(...file.warnings);
    return { model, project: null };
  }
  return { model: null, project: projectOf(fileName, file.objects, file.projectSettings, file.warnings) };
}

/** Objects as one model: welded and checked, with the triangles to draw. */
function modelOf(fileName: string, objects: readonly MeshObject[]): LoadedModel {
  const { mesh, report } = prepareMesh(mergeObjects(objects));
  if (mesh.indices.length === 0) throw new StrataError('EMPTY_MODEL', `${fileName} has no printable triangles`);
  const { positions, normals } = drawArrays(mesh);
  return {
    objects: objects.map((o) => o.name),
    triangles: mesh.indices.length / 3,
    vertices: mesh.positions,
    indices: mesh.indices,
    positions,
    normals,
    openEdges: report.openEdges,
    nonManifoldEdges: report.nonManifoldEdges,
    warnings: [...report.warnings],
  };
}

/**
 * A project's objects for the plate, their settings in Strata's keys (another slicer's mapped over the
 * project's print settings, as the library reads them); settings that cannot vary where the project sets
 * them (Strata keeps them per print, or per object) are left to the print, with a warning.
 */
function projectOf(
  fileName: string,
  objects: readonly MeshObject[],
  print: SettingsSource | undefined,
  warnings: string[],
): LoadedProject {
  const ignored = new Set<string>(),
    outOfScope = new Set<string>();
  const read = (src: SettingsSource | undefined, use: ScopeUse): Partial<Record<SettingKey, unknown>> => {
    const out: Partial<Record<SettingKey, unknown>> = {};
    if (!src) return out;
    const mapped = settingsFromSource(src, print && print.format === src.format ? print : undefined);
    for (const k of mapped.ignored) ignored.add(k);
    for (const r of mapped.rejected) warnings.push(`object settings: ${r.key} = ${r.value} not taken: ${r.reason}`);
    for (const [k, v] of Object.entries(mapped.settings)) {
      const scope = SETTING_SCOPE[k as SettingKey];
      if (scope === 'print' || (scope === 'layer' && use !== 'layer range') || (scope === 'object' && use !== 'object'))
        outOfScope.add(k);
      else out[k as SettingKey] = v;
    }
    return out;
  };
  const out: ProjectObject[] = objects.map((o) => ({
    name: o.name,
    model: modelOf(fileName, [o]),
    settings: read(o.settings, 'object'),
    volumes: (o.volumes ?? []).map((v) => ({
      kind: v.kind,
      name: v.name,
      mesh: { positions: v.mesh.positions, indices: v.mesh.indices },
      settings: v.kind === 'modifier' ? read(v.settings, 'modifier') : {},
    })),
    layerRanges: (o.layerRanges ?? []).map((r) => ({
      fromZ: r.fromZ,
      toZ: r.toZ,
      settings: read(r.settings, 'layer range'),
    })),
    ...(o.layerHeightProfile ? { layerHeightProfile: [...o.layerHeightProfile] } : {}),
  }));
  if (ignored.size) warnings.push(`object settings not used by Strata, ignored: ${[...ignored].sort().join(', ')}`);
  if (outOfScope.size)
    warnings.push(
      `object settings that Strata keeps the same for the whole print (or object), left to the print: ${[...outOfScope].sort().join(', ')}`,
    );
  let printSettings: Record<string, unknown> | null = null;
  if (print?.format === 'strata') printSettings = { ...print.values };
  else if (print) {
    const mapped = settingsFromSource(print);
    printSettings = mapped.settings;
    if (mapped.rejected.length)
      warnings.push(
        `print settings not taken: ${mapped.rejected.map((r) => `${r.key} = ${r.value} (${r.reason})`).join('; ')}`,
      );
  }
  return { objects: out, printSettings, warnings };
}

/** Every array of a project, to transfer. */
function projectBuffers(p: LoadedProject): ArrayBuffer[] {
  const out = new Set<ArrayBuffer>();
  for (const o of p.objects) {
    for (const a of [o.model.vertices, o.model.indices, o.model.positions, o.model.normals])
      out.add(a.buffer as ArrayBuffer);
    for (const v of o.volumes) for (const a of [v.mesh.positions, v.mesh.indices]) out.add(a.buffer as ArrayBuffer);
  }
  return [...out];
}

/**
 * The slicer's input, one model per plate object. A plain file (no settings, volumes or layer ranges of
 * its own) at the place `strata slice` would put it goes in as read, its objects kept together (so the
 * G-code is the CLI's, byte for byte); a placed one is moved to its placement first. An object with
 * settings, volumes or layer ranges goes as the library's object description, its volumes moved with it.
 */
function sliceInput(items: readonly SliceItem[]): { input: unknown[]; placed: boolean } {
  let placed = false;
  const input = items.map((it): unknown => {
    const own =
      it.volumes.length > 0 ||
      it.layerRanges.length > 0 ||
      Object.keys(it.settings).length > 0 ||
      !!it.layerHeightProfile;
    if (!it.placement && it.bytes) {
      if (!own) return { name: it.fileName, objects: loadModelBytes(new Uint8Array(it.bytes), it.fileName) };
      return describeObject(it, new Uint8Array(it.bytes), it.volumes);
    }
    const objects: MeshObject[] = it.bytes
      ? loadModelBytes(new Uint8Array(it.bytes), it.fileName)
      : [{ name: it.name, mesh: it.mesh! }];
    if (!it.placement) return own ? describeObject(it, objects, it.volumes) : { name: it.fileName, objects };
    placed = true;
    if (!own) return { name: it.fileName, objects: placeObjects(objects, it.placement) };
    // the volumes take the transform of the object's parts
    const affine = placementAffine(it.placement, linearBounds(objects, it.placement.linear));
    return describeObject(
      it,
      placeObjects(objects, it.placement),
      it.volumes.map((v) => ({ ...v, mesh: transformed(v.mesh, affine) })),
    );
  });
  return { input, placed };
}

/** An object description for the library: `{ mesh, name, settings?, volumes?, layerRanges? }`. */
function describeObject(it: SliceItem, mesh: unknown, volumes: readonly SliceVolume[]): Record<string, unknown> {
  const out: Record<string, unknown> = { mesh, name: it.name };
  if (Object.keys(it.settings).length) out.settings = it.settings;
  if (volumes.length)
    out.volumes = volumes.map((v) =>
      v.settings && Object.keys(v.settings).length ? v : { type: v.type, name: v.name, mesh: v.mesh },
    );
  if (it.layerRanges.length) out.layerRanges = it.layerRanges;
  if (it.layerHeightProfile) out.layerHeightProfile = it.layerHeightProfile;
  return out;
}

/** A volume's mesh under an affine transform (corners swapped where it mirrors, to keep it facing out). */
function transformed(m: MeshArrays, affine: Affine): MeshArrays {
  const n = m.positions.length / 3;
  const positions = new Float32Array(n * 3);
  transformPoints(affine, m.positions, n, positions, 0);
  if (determinant(affine) >= 0) return { positions, indices: m.indices };
  const indices = m.indices.slice();
  for (let t = 0; t < indices.length; t += 3) [indices[t + 1], indices[t + 2]] = [indices[t + 2], indices[t + 1]];
  return { positions, indices };
}

async function handle(msg: ToWorker): Promise<void> {
  switch (msg.type) {
    case 'load': {
      const { model, project } = load(msg.fileName, msg.bytes, msg.mesh === true);
      const transfer = model
        ? ([model.vertices.buffer, model.indices.buffer, model.positions.buffer, model.normals.buffer] as ArrayBuffer[])
        : projectBuffers(project!);
      post({ type: 'loaded', id: msg.id, model, project }, transfer);
      return;
    }
    case 'save': {
      // the objects as the slice places them (volumes with them), so the project slices to the same G-code
      const { input, placed } = sliceInput(msg.items);
      const cfg = resolveConfig(placed ? { ...msg.options, center: false } : msg.options);
      const prepared = prepareModel(input, cfg);
      // PrusaSlicer's copy of the print settings: every one resolved, in its keys
      const resolved: Record<string, unknown> = { ...cfg.settings };
      const bytes = writeProject3mf(prepared.objects, {
        printSettings: msg.printSettings,
        slic3rPrintSettings: toSlic3rKeys(resolved, cfg.layerHeight),
      });
      post({ type: 'saved', id: msg.id, bytes: bytes.buffer as ArrayBuffer }, [bytes.buffer as ArrayBuffer]);
      return;
    }
    case 'infiller': {
      // the shader compiler loads here, the first time a custom infill is chosen
      const compiler = await loadCustomInfill();
      const shader = await import('../../src/shader/index.js');
      const info = shader.describeInfiller(shader.loadInfiller(msg.spec));
      compiler.customGenerator(msg.spec, new Slicer().config);
      post({
        type: 'infiller',
        id: msg.id,
        info: { kind: info.kind, params: info.params.map((p) => ({ ...p })), warnings: info.warnings },
      });
      return;
    }
    case 'slice': {
      const { input, placed } = sliceInput(msg.items);
      // a placed object is already where it goes: the slicer only drops it onto the bed
      const slicer = new Slicer(placed ? { ...msg.options, center: false } : msg.options);
      if (msg.custom) slicer.setCustomInfill(msg.custom);
      const chunks: string[] = [];
      const { plan, stats, warnings } = await slicer.slicePlan(
        input,
        {
          onProgress: (p) => post({ type: 'progress', id: msg.id, stage: p.stage, fraction: p.fraction }),
        },
        (c) => chunks.push(c),
      );
      const gcode = new TextEncoder().encode(chunks.join('')).buffer as ArrayBuffer;
      // the estimate's time per layer, to colour the preview by (the G-code's estimate, made again here)
      const preview = planToArrays(plan, estimatePlan(plan, slicer.config).layerSeconds);
      const { bounds: _bounds, ...summary } = stats;
      post({ type: 'sliced', id: msg.id, gcode, stats: summary, warnings, preview }, [gcode, ...transferList(preview)]);
      return;
    }
  }
}

/** Handle one message from the page; errors go back to it in words. */
export function onMessage(msg: ToWorker): void {
  handle(msg).catch((err: unknown) => post({ type: 'error', id: msg.id, message: describe(err) }));
}
