/**
 * From whatever the caller passed to placed objects: read the models (files, three.js, arrays),
 * prepare each object's mesh (weld, drop degenerate triangles, report), refuse a model with nothing
 * to print, then turn, scale and arrange the models on the bed (mesh/place.ts).
 */
import { StrataError } from '../errors.js';
import { mergeObjects, placeModels, prepareMesh, toModels } from '../mesh/index.js';
import type { ModelInput } from '../mesh/place.js';
import { nothingToPrint } from '../mesh/solid.js';
import type { Mesh, MeshObject, MeshReport, SettingsSource } from '../mesh/types.js';
import type { SliceOptions } from '../settings/schema.js';
import type { Config } from '../settings/resolve.js';

export interface PreparedModel {
  /** Every object merged into one mesh, in bed coordinates. */
  mesh: Mesh;
  /**
   * The objects one by one, in bed coordinates (after rotation, scaling and arrangement), with
   * unique names (a repeated name gets " (2)", " (3)"…), in input order.
   */
  objects: MeshObject[];
  /** What preparing the meshes found, over all objects, before placement. */
  report: MeshReport;
  /** Translation applied to the first model after its rotation and scaling, mm. */
  offset: [number, number, number];
  warnings: string[];
  /** The config the model was placed with: the caller's, or with a project's print settings under it. */
  config: Config;
  /** A project file's print settings as it gave them, and the options they made with the caller's. */
  project?: { settings: SettingsSource; options: SliceOptions };
}

/** A config for a project's print settings (under the caller's options), with notes on what was left out. */
export type ProjectConfig = (settings: SettingsSource) => { config: Config; options: SliceOptions; warnings: string[] };

export const MiB = 1024 * 1024;

/** Load, repair-check and place whatever the caller passed (bytes, text, three.js objects, arrays, or a list of them). */
export function prepareModel(input: unknown, cfg: Config): PreparedModel {
  const steps = prepareModelSteps(input, cfg);
  for (;;) {
    const r = steps.next();
    if (r.done) return r.value;
  }
}

/** `prepareModel` as steps: yields after reading and after each object's preparation, so a caller can pause. */
export function* prepareModelSteps(
  input: unknown,
  given: Config,
  reconfigure?: ProjectConfig,
): Generator<void, PreparedModel> {
  const loaded = toModels(input, { maxInflatedBytes: given.inflateBudget * MiB, upAxis: given.upAxis });
  // a project's print settings go under the caller's own before the models are placed
  const project = loaded.projectSettings && reconfigure ? reconfigure(loaded.projectSettings) : null;
  const cfg = project?.config ?? given;
  yield;
  const models = loaded.models.filter((m) => m.objects.length > 0);
  if (models.length === 0) throw new StrataError('EMPTY_MODEL', 'the input holds no mesh');
  const totalObjects = models.reduce((n, m) => n + m.objects.length, 0);
  const reports: MeshReport[] = [];
  const warnings: string[] = [];
  const prepared: ModelInput[] = [];
  for (const m of models) {
    const objects: MeshObject[] = [];
    for (const o of m.objects) {
      const { mesh, report } = prepareMesh(o.mesh);
      reports.push(report);
      const prefix = totalObjects > 1 ? `${o.name}: ` : '';
      for (const w of report.warnings) warnings.push(prefix + w);
      if (mesh.indices.length > 0) objects.push(withVolumesPrepared({ ...o, mesh }, warnings));
      yield;
    }
    const why =
      objects.length === 0
        ? 'has no printable triangles'
        : nothingToPrint(mergeObjects(objects), combineReports(reports.slice(-m.objects.length)));
    if (why !== undefined) throw new StrataError('EMPTY_MODEL', `nothing to print: ${m.name} ${why}`);
    prepared.push({ name: m.name, objects });
  }
  const brim = cfg.adhesionType === 'brim' ? cfg.brimWidth : 0;
  // sequential printing keeps the print head's clearance radius between the models (the brim lies under it)
  const spacing = cfg.sequentialPrinting
    ? Math.max(cfg.objectSpacing + 2 * brim, cfg.extruderClearanceRadius)
    : cfg.objectSpacing + 2 * brim;
  const placed = placeModels(prepared, {
    center: cfg.center,
    bedWidth: cfg.buildPlateWidth,
    bedLength: cfg.buildPlateLength,
    bedHeight: cfg.buildVolumeHeight,
    originAtCenter: cfg.originAtCenter,
    spacing,
    ...(spacing > cfg.objectSpacing + 2 * brim
      ? { spacingSetting: 'extruderClearanceRadius (sequentialPrinting keeps it between the models)' }
      : {}),
    margin: adhesionMargin(cfg),
    transform: {
      upAxis: cfg.upAxis,
      rotate: [cfg.rotateX, cfg.rotateY, cfg.rotateZ],
      scale: [cfg.scaleX ?? cfg.scale, cfg.scaleY ?? cfg.scale, cfg.scaleZ ?? cfg.scale],
    },
  });
  if (prepared.length > 1) {
    warnings.unshift(
      cfg.center
        ? `${prepared.length} models arranged around the bed centre, ${round(cfg.sequentialPrinting ? spacing : cfg.objectSpacing)} mm apart${cfg.sequentialPrinting && spacing > cfg.objectSpacing + 2 * brim ? ' (extruderClearanceRadius, for sequential printing)' : ''}`
        : `${prepared.length} models kept at their own coordinates`,
    );
  }
  warnings.push(...loaded.warnings, ...(project?.warnings ?? []), ...placed.warnings);
  const objects = uniqueNames(placed.objects);
  return {
    mesh: objects.length === 1 ? objects[0].mesh : mergeObjects(objects),
    objects,
    report: combineReports(reports),
    offset: placed.offsets[0],
    warnings: [...new Set(warnings)],
    config: cfg,
    ...(project ? { project: { settings: loaded.projectSettings!, options: project.options } } : {}),
  };
}

/** Names made unique in order: the second "cube" becomes "cube (2)"; an empty name becomes "object N". */
function uniqueNames(objects: MeshObject[]): MeshObject[] {
  const used = new Set<string>();
  return objects.map((o, i) => {
    const base = o.name.trim() === '' ? `object ${i + 1}` : o.name;
    let name = base;
    for (let k = 2; used.has(name); k++) name = `${base} (${k})`;
    used.add(name);
    return name === o.name ? o : { ...o, name };
  });
}

/** The object with its volumes welded and cleaned as its parts are (an empty volume is dropped, with a note). */
function withVolumesPrepared(o: MeshObject, warnings: string[]): MeshObject {
  if (!o.volumes?.length) return o;
  const volumes = [];
  for (const v of o.volumes) {
    const { mesh } = prepareMesh(v.mesh);
    if (mesh.indices.length > 0) volumes.push({ ...v, mesh });
    else warnings.push(`${o.name}: ${v.kind} "${v.name}" has no triangles and is ignored`);
  }
  return { ...o, volumes };
}

/** Sums and overall bounds of several objects' reports. */
function combineReports(reports: readonly MeshReport[]): MeshReport {
  if (reports.length === 1) return reports[0];
  const out: MeshReport = {
    triangles: 0,
    vertices: 0,
    degenerateRemoved: 0,
    openEdges: 0,
    nonManifoldEdges: 0,
    volume: 0,
    min: [Infinity, Infinity, Infinity],
    max: [-Infinity, -Infinity, -Infinity],
    warnings: [],
  };
  for (const r of reports) {
    out.triangles += r.triangles;
    out.vertices += r.vertices;
    out.degenerateRemoved += r.degenerateRemoved;
    out.openEdges += r.openEdges;
    out.nonManifoldEdges += r.nonManifoldEdges;
    out.volume += r.volume;
    if (r.triangles === 0) continue;
    for (let k = 0; k < 3; k++) {
      out.min[k] = Math.min(out.min[k], r.min[k]);
      out.max[k] = Math.max(out.max[k], r.max[k]);
    }
    out.warnings.push(...r.warnings);
  }
  if (out.min[0] === Infinity) {
    out.min = [0, 0, 0];
    out.max = [0, 0, 0];
  }
  return out;
}

/** How far the skirt or brim reaches beyond the models, mm. */
function adhesionMargin(cfg: Config): { mm: number; what: string } {
  const line = cfg.firstLayerLineWidthMm;
  if (cfg.adhesionType === 'skirt') return { mm: cfg.skirtDistance + cfg.skirtLoops * line, what: 'skirt' };
  if (cfg.adhesionType === 'brim') return { mm: cfg.brimWidth + line / 2, what: 'brim' };
  if (cfg.adhesionType === 'raft') return { mm: cfg.raftMargin, what: 'raft' };
  return { mm: 0, what: '' };
}

function round(v: number): number {
  return Math.round(v * 1000) / 1000;
}
