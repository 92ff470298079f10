/**
 * Project 3MFs: every build item as a MeshObject (as parse3mf reads it) with what the slicer that wrote the
 * file knows of it: which of its triangles are modifiers, negative volumes, support blockers or enforcers,
 * its own settings and its layer ranges; and the project's print settings. Read from, in this order:
 * Strata's own data over PrusaSlicer's layout (threemf-strata.ts), PrusaSlicer (and SuperSlicer),
 * OrcaSlicer / Bambu Studio (threemf-slic3r.ts), Cura (threemf-cura.ts); any other 3MF is plain objects.
 * Settings stay raw, in the writing slicer's keys (profiles/ maps them). Config parts are read through
 * the same unpack budget as the model, each within MAX_CONFIG_BYTES.
 */
import { StrataError } from '../errors.js';
import { assemble, type ObjectSpec } from './threemf-assemble.js';
import {
  MAX_CONFIG_BYTES,
  ORCA_LAYER_RANGES,
  ORCA_MODEL_CONFIG,
  ORCA_PROJECT_CONFIG,
  parseLayerRanges,
  parseModelConfig,
  parseSlic3rConfig,
  PRUSA_LAYER_RANGES,
  PRUSA_HEIGHT_PROFILE,
  ORCA_HEIGHT_PROFILE,
  parseHeightProfiles,
  PRUSA_MODEL_CONFIG,
  PRUSA_PRINT_CONFIG,
  STRATA_PROJECT,
} from './threemf-configs.js';
import { curaPlanner, curaProjectSettings, isCuraProject } from './threemf-cura.js';
import { partKey } from './threemf-package.js';
import { orcaPlanner, prusaPlanner, wholeItem } from './threemf-slic3r.js';
import { overlayStrata, readStrataProject, type StrataProjectObject } from './threemf-strata.js';
import {
  expandItem,
  openBuild,
  type Build,
  type BuildItem,
  type ExpandedItem,
  type ThreeMfOptions,
} from './threemf.js';
import type { MeshObject, MeshVolume, SettingsSource } from './types.js';

export interface ThreeMfProject {
  objects: MeshObject[];
  /** The print's settings the project holds, in the writing slicer's keys. */
  projectSettings?: SettingsSource;
  /** What was read differently from how the file says it, one line each. */
  warnings: string[];
}

type Planner = (item: BuildItem, e: ExpandedItem) => ObjectSpec;

export function parse3mfProject(bytes: Uint8Array, name = 'model', opts: ThreeMfOptions = {}): ThreeMfProject {
  const build = openBuild(bytes, name, opts);
  const warnings: string[] = [];
  const keys = new Set(build.pkg.keys());
  const read = (file: string): Uint8Array | undefined => {
    const key = partKey(file);
    return keys.has(key) ? build.pkg.readFile(key, MAX_CONFIG_BYTES) : undefined;
  };
  const { planner, projectSettings, cura } = readProjectData(build, read, warnings);

  const out: MeshObject[] = [];
  const used = new Set<string>();
  const loose: Array<{ from: string; volumes: MeshVolume[] }> = [];
  build.items.forEach((item, i) => {
    if (item.triangles === 0) return;
    const e = expandItem(build, item);
    const spec = planner(item, e);
    const { object, volumes } = assemble(e, spec);
    if (object === null) {
      if (cura) loose.push({ from: spec.name, volumes });
      else if (volumes.length > 0)
        warnings.push(`3MF: object "${spec.name}" has no printed part; its volumes are not used`);
      return;
    }
    if (used.has(object.name)) object.name = `${object.name} (${i + 1})`;
    used.add(object.name);
    out.push(object);
  });
  // Cura keeps a modifier mesh as an object of its own: it belongs to the printed object it overlaps
  const boxes = loose.length > 0 ? out.map((o) => bounds([o.mesh.positions])) : [];
  for (const { from, volumes } of loose) {
    if (out.length === 0) {
      warnings.push(`3MF: "${from}" changes settings or support but no printed object is there; not used`);
      continue;
    }
    const box = bounds(volumes.map((v) => v.mesh.positions));
    const target = out.find((_, k) => overlaps(boxes[k], box));
    if (target === undefined) warnings.push(`3MF: "${from}" overlaps no printed object; applied to "${out[0].name}"`);
    const o = target ?? out[0];
    o.volumes = [...(o.volumes ?? []), ...volumes];
  }
  if (out.length === 0) throw new StrataError('EMPTY_MODEL', '3MF: the build has no printed objects');
  const result: ThreeMfProject = { objects: out, warnings };
  if (projectSettings !== undefined) result.projectSettings = projectSettings;
  return result;
}

/** Which slicer wrote the project, what each item's triangles are by its data, and its print settings. */
function readProjectData(
  build: Build,
  read: (file: string) => Uint8Array | undefined,
  warnings: string[],
): { planner: Planner; projectSettings?: SettingsSource; cura: boolean } {
  const text = (file: string): string | undefined => {
    const data = read(file);
    return data === undefined ? undefined : new TextDecoder('utf-8').decode(data);
  };
  const prusaModel = read(PRUSA_MODEL_CONFIG);
  if (prusaModel !== undefined) {
    const config = parseModelConfig(prusaModel, PRUSA_MODEL_CONFIG);
    const rangesXml = read(PRUSA_LAYER_RANGES);
    const ranges = rangesXml === undefined ? undefined : parseLayerRanges(rangesXml, PRUSA_LAYER_RANGES, warnings);
    const profileText = text(PRUSA_HEIGHT_PROFILE);
    const profiles =
      profileText === undefined ? undefined : parseHeightProfiles(profileText, PRUSA_HEIGHT_PROFILE, warnings);
    let planner: Planner = prusaPlanner(build, { format: 'prusaslicer', config, ranges, profiles }, warnings);
    const printText = text(PRUSA_PRINT_CONFIG);
    let projectSettings: SettingsSource | undefined =
      printText === undefined ? undefined : { format: 'prusaslicer', values: parseSlic3rConfig(printText) };
    const strataText = text(STRATA_PROJECT);
    if (strataText !== undefined) {
      const project = readStrataProject(strataText);
      if (typeof project === 'string') {
        warnings.push(`3MF: ${STRATA_PROJECT} is not used: ${project}`);
      } else {
        const prusa = planner;
        const byId = new Map<number, StrataProjectObject>();
        for (const o of project.objects) if (!byId.has(o.id)) byId.set(o.id, o);
        planner = (item, e) => overlayStrata(prusa(item, e), byId, warnings);
        if (Object.keys(project.printSettings).length > 0)
          projectSettings = { format: 'strata', values: project.printSettings };
      }
    }
    return { planner, projectSettings, cura: false };
  }
  const orcaModel = read(ORCA_MODEL_CONFIG);
  if (orcaModel !== undefined) {
    const config = parseModelConfig(orcaModel, ORCA_MODEL_CONFIG);
    const rangesXml = read(ORCA_LAYER_RANGES);
    const ranges = rangesXml === undefined ? undefined : parseLayerRanges(rangesXml, ORCA_LAYER_RANGES, warnings);
    const profileText = text(ORCA_HEIGHT_PROFILE);
    const profiles =
      profileText === undefined ? undefined : parseHeightProfiles(profileText, ORCA_HEIGHT_PROFILE, warnings);
    const planner = orcaPlanner(build, { format: 'orcaslicer', config, ranges, profiles }, warnings);
    return { planner, projectSettings: orcaProjectSettings(text(ORCA_PROJECT_CONFIG), warnings), cura: false };
  }
  if (isCuraProject(build)) {
    const projectSettings = curaProjectSettings(build.pkg, (key, max) => {
      const data = build.pkg.readFile(key, Math.min(max, MAX_CONFIG_BYTES));
      return data === undefined ? undefined : new TextDecoder('utf-8').decode(data);
    });
    return { planner: curaPlanner(build), projectSettings, cura: true };
  }
  // PrusaSlicer's print config alone (a model saved without objects of its own settings)
  const printText = text(PRUSA_PRINT_CONFIG);
  if (printText !== undefined)
    return {
      planner: wholeItem,
      projectSettings: { format: 'prusaslicer', values: parseSlic3rConfig(printText) },
      cura: false,
    };
  return { planner: wholeItem, cura: false };
}

/** Orca's print settings: a JSON object of its keys (values strings or lists of strings). */
function orcaProjectSettings(json: string | undefined, warnings: string[]): SettingsSource | undefined {
  if (json === undefined) return undefined;
  try {
    const values: unknown = JSON.parse(json);
    if (typeof values === 'object' && values !== null && !Array.isArray(values))
      return { format: 'orcaslicer', values: values as Record<string, unknown> };
  } catch {
    // reported below
  }
  warnings.push(`3MF: ${ORCA_PROJECT_CONFIG} is not a JSON object; the project's print settings are not used`);
  return undefined;
}

type Box = [number, number, number, number, number, number];

function bounds(all: readonly Float32Array[]): Box {
  const b: Box = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  for (const p of all) {
    for (let i = 0; i < p.length; i += 3) {
      for (let a = 0; a < 3; a++) {
        if (p[i + a] < b[a]) b[a] = p[i + a];
        if (p[i + a] > b[a + 3]) b[a + 3] = p[i + a];
      }
    }
  }
  return b;
}

function overlaps(a: Box, b: Box): boolean {
  return a[0] <= b[3] && b[0] <= a[3] && a[1] <= b[4] && b[1] <= a[4] && a[2] <= b[5] && b[2] <= a[5];
}
