/**
 * The config parts slicers keep beside a 3MF's model, read into plain data (no geometry here):
 * - PrusaSlicer `Metadata/Slic3r_PE_model.config` and OrcaSlicer / Bambu Studio `Metadata/model_settings.config`:
 *   `<config><object id="…">` with `<metadata [type="object"] key="…" value="…"/>` and its volumes, PrusaSlicer's as
 *   `<volume firstid="…" lastid="…">` (triangle ranges of the object's mesh), Orca's as `<part id="…" subtype="…">`
 *   (the component holding the part's mesh), each with metadata of its own;
 * - layer ranges, `Metadata/Prusa_Slicer_layer_config_ranges.xml` (PrusaSlicer) and `Metadata/layer_config_ranges.xml`
 *   (Orca): `<objects><object id="…"><range min_z="…" max_z="…"><option opt_key="…">value</option>`;
 * - PrusaSlicer's print config `Metadata/Slic3r_PE.config`: `; key = value` lines;
 * - variable layer height profiles, `Metadata/Slic3r_PE_layer_heights_profile.txt` (PrusaSlicer) and
 *   `Metadata/layer_heights_profile.txt` (Orca, Bambu Studio): a line `object_id=N|z;h;z;h;…` per object.
 */
import { StrataError } from '../errors.js';
import { printable } from './printable.js';
import { XML_END, XML_EOF, XmlScanner } from './xml-scanner.js';

/** Where the slicers keep them (as written; looked up by partKey). */
export const PRUSA_MODEL_CONFIG = 'Metadata/Slic3r_PE_model.config';
export const PRUSA_PRINT_CONFIG = 'Metadata/Slic3r_PE.config';
export const PRUSA_LAYER_RANGES = 'Metadata/Prusa_Slicer_layer_config_ranges.xml';
export const ORCA_MODEL_CONFIG = 'Metadata/model_settings.config';
export const ORCA_PROJECT_CONFIG = 'Metadata/project_settings.config';
export const ORCA_LAYER_RANGES = 'Metadata/layer_config_ranges.xml';
export const PRUSA_HEIGHT_PROFILE = 'Metadata/Slic3r_PE_layer_heights_profile.txt';
export const ORCA_HEIGHT_PROFILE = 'Metadata/layer_heights_profile.txt';
/** Strata's own full copy of a project's settings, beside PrusaSlicer's (threemf-write.ts). */
export const STRATA_PROJECT = 'Metadata/Strata_project.json';
/** Most bytes one config part may unpack to. */
export const MAX_CONFIG_BYTES = 64 * 1024 * 1024;

export interface ConfigVolume {
  /** Orca: the object id of the component holding the part. */
  id: number | null;
  /** PrusaSlicer: inclusive triangle range of the object's mesh. */
  firstId: number | null;
  lastId: number | null;
  /** Orca's `subtype` attribute ('' when absent). */
  subtype: string;
  metadata: Map<string, string>;
}

export interface ConfigObject {
  id: number;
  metadata: Map<string, string>;
  volumes: ConfigVolume[];
}

export interface ConfigRange {
  minZ: number;
  maxZ: number;
  options: Map<string, string>;
}

const MAX_DEPTH = 32;

/** A model config (PrusaSlicer's or Orca's) by object id. */
export function parseModelConfig(bytes: Uint8Array, fileName: string): Map<number, ConfigObject> {
  const x = new XmlScanner(bytes, `3MF ${fileName}`, MAX_DEPTH);
  const objects = new Map<number, ConfigObject>();
  let object: ConfigObject | null = null;
  let volume: ConfigVolume | null = null;
  // depth of the <object> and <volume>/<part> being read (-1: none)
  let objectDepth = -1;
  let volumeDepth = -1;
  for (let ev = x.next(); ev !== XML_EOF; ev = x.next()) {
    if (ev === XML_END) {
      if (x.depth === volumeDepth) {
        volume = null;
        volumeDepth = -1;
      } else if (x.depth === objectDepth) {
        object = null;
        objectDepth = -1;
      }
      continue;
    }
    const depth = x.selfClosing ? x.depth : x.depth - 1;
    if (depth === 1 && x.is('object')) {
      const id = uintAttr(x, 'id');
      if (id < 0) x.fail('an <object> needs a numeric id', x.nameStart);
      if (objects.has(id)) x.fail(`two objects have the id ${id}`, x.nameStart);
      object = { id, metadata: new Map(), volumes: [] };
      objects.set(id, object);
      if (!x.selfClosing) objectDepth = depth;
    } else if (object !== null && depth === objectDepth + 1 && (x.is('volume') || x.is('part'))) {
      volume = { id: null, firstId: null, lastId: null, subtype: '', metadata: new Map() };
      while (x.nextAttr()) {
        if (x.attrIs('id')) volume.id = checkedUint(x, 'id');
        else if (x.attrIs('firstid')) volume.firstId = checkedUint(x, 'firstid');
        else if (x.attrIs('lastid')) volume.lastId = checkedUint(x, 'lastid');
        else if (x.attrIs('subtype')) volume.subtype = x.value();
      }
      object.volumes.push(volume);
      if (!x.selfClosing) volumeDepth = depth;
    } else if (object !== null && x.is('metadata') && (depth === objectDepth + 1 || depth === volumeDepth + 1)) {
      let type = '';
      let key = '';
      let value = '';
      while (x.nextAttr()) {
        if (x.attrIs('type')) type = x.value();
        else if (x.attrIs('key')) key = x.value();
        else if (x.attrIs('value')) value = x.value();
      }
      if (key === '') continue;
      const target = volume !== null && depth === volumeDepth + 1 && type !== 'object' ? volume : object;
      target.metadata.set(key, value);
    }
  }
  return objects;
}

/** Layer ranges by object number (1-based, as the file counts them), each object's sorted by Z. */
export function parseLayerRanges(bytes: Uint8Array, fileName: string, warnings: string[]): Map<number, ConfigRange[]> {
  const x = new XmlScanner(bytes, `3MF ${fileName}`, MAX_DEPTH);
  const out = new Map<number, ConfigRange[]>();
  let ranges: ConfigRange[] | null = null;
  let range: ConfigRange | null = null;
  let option = '';
  let optionStart = -1;
  for (let ev = x.next(); ev !== XML_EOF; ev = x.next()) {
    if (ev === XML_END) {
      if (optionStart >= 0 && x.is('option')) {
        range?.options.set(option, x.textContent(optionStart).trim());
        optionStart = -1;
      }
      continue;
    }
    const depth = x.selfClosing ? x.depth : x.depth - 1;
    if (depth === 1 && x.is('object')) {
      const id = uintAttr(x, 'id');
      range = null;
      ranges = null;
      if (id < 1) {
        warnings.push(`3MF ${fileName}: an object without a valid id; its layer ranges are not used`);
      } else if (out.has(id)) {
        warnings.push(`3MF ${fileName}: object ${id} is listed twice; its second list of layer ranges is not used`);
      } else {
        ranges = [];
        out.set(id, ranges);
      }
    } else if (depth === 2 && x.is('range') && ranges !== null) {
      let minZ = NaN;
      let maxZ = NaN;
      while (x.nextAttr()) {
        if (x.attrIs('min_z')) minZ = x.number();
        else if (x.attrIs('max_z')) maxZ = x.number();
      }
      if (!Number.isFinite(minZ) || !Number.isFinite(maxZ))
        x.fail('a <range> needs numbers in min_z and max_z', x.nameStart);
      if (!(minZ < maxZ)) x.fail(`the layer range ${minZ}–${maxZ} mm is empty`, x.nameStart);
      range = { minZ, maxZ, options: new Map() };
      ranges.push(range);
    } else if (depth === 3 && x.is('option') && range !== null) {
      option = '';
      while (x.nextAttr()) if (x.attrIs('opt_key')) option = x.value();
      if (option !== '' && !x.selfClosing) optionStart = x.contentStart();
    }
  }
  for (const [id, list] of out) {
    list.sort((a, b) => a.minZ - b.minZ);
    for (let i = 1; i < list.length; i++) {
      if (list[i].minZ < list[i - 1].maxZ) {
        throw new StrataError(
          'BAD_FILE',
          `3MF ${fileName}: the layer ranges ${list[i - 1].minZ}–${list[i - 1].maxZ} mm and ${list[i].minZ}–${list[i].maxZ} mm of object ${id} overlap`,
        );
      }
    }
  }
  return out;
}

/** Most points of one object's layer height profile (each a Z and a height). */
const MAX_PROFILE_POINTS = 1_000_000;

/**
 * Variable layer height profiles by object number (1-based, as the file counts them): each the flat list
 * z0, h0, z1, h1, … (mm from the object's bottom, layer height there), Z rising. A line that is not one is
 * left out with a warning.
 */
export function parseHeightProfiles(text: string, fileName: string, warnings: string[]): Map<number, number[]> {
  const out = new Map<number, number[]>();
  for (const line of text.split(/\r?\n/)) {
    if (line.trim() === '') continue;
    const m = /^\s*object_id\s*=\s*(\d+)\s*\|(.*)$/.exec(line);
    const values = m ? m[2].split(';').map((v) => (v.trim() === '' ? NaN : Number(v))) : [];
    const ok =
      m !== null &&
      values.length >= 4 &&
      values.length % 2 === 0 &&
      values.length <= 2 * MAX_PROFILE_POINTS &&
      values.every((v, i) => Number.isFinite(v) && (i % 2 === 0 ? v >= 0 && (i === 0 || v > values[i - 2]) : v > 0));
    if (!ok) {
      warnings.push(
        `3MF ${fileName}: a line that is not a layer height profile (object_id=N|z;h;…, Z rising, heights above 0) is not used`,
      );
      continue;
    }
    const id = Number(m![1]);
    if (out.has(id))
      warnings.push(`3MF ${fileName}: object ${id} has two layer height profiles; the second is not used`);
    else out.set(id, values);
  }
  return out;
}

/** PrusaSlicer's `; key = value` print config. */
export function parseSlic3rConfig(text: string): Record<string, string> {
  const out: Record<string, string> = {};
  for (const line of text.replace(/^\uFEFF/, '').split(/\r?\n/)) {
    const m = /^;\s*([A-Za-z0-9_]+)\s*=\s?(.*)$/.exec(line.trim());
    if (m) out[m[1]] = m[2].trimEnd();
  }
  return out;
}

function uintAttr(x: XmlScanner, name: string): number {
  let v = -1;
  while (x.nextAttr()) if (x.attrIs(name)) v = x.uint();
  return v;
}

function checkedUint(x: XmlScanner, name: string): number {
  const v = x.uint();
  if (v < 0) x.fail(`${name}="${printable(x.value())}" is not a whole number`, x.nameStart);
  return v;
}
