/**
 * Writing a project 3MF in PrusaSlicer's layout, so PrusaSlicer opens it with its volumes and settings, plus
 * Strata's own lossless copy of the settings (threemf-strata.ts), which parse3mfProject prefers:
 * - `3D/3dmodel.model`: one object per MeshObject, its mesh's triangles then each volume's, with one build
 *   item each and no transform (the meshes are already where they stand on the bed);
 * - `Metadata/Slic3r_PE_model.config`: each object's name and settings, its volumes as inclusive triangle
 *   ranges with their type (ModelPart for the mesh) and settings, in PrusaSlicer's keys where Strata's have
 *   one (profiles/to-slic3r.ts; raw PrusaSlicer settings are written as they are);
 * - `Metadata/Prusa_Slicer_layer_config_ranges.xml` when an object has layer ranges;
 * - `Metadata/Slic3r_PE.config` when PrusaSlicer print settings are given;
 * - `Metadata/Strata_project.json`: every setting in Strata's keys.
 */
import { strToU8, zipSync } from 'fflate';
import { StrataError } from '../errors.js';
import { SCHEMA } from '../settings/schema.js';
import { settingsFromSource } from './object-settings.js';
import { toSlic3rKeys } from './to-slic3r.js';
import { PRUSA_LAYER_RANGES, PRUSA_MODEL_CONFIG, PRUSA_PRINT_CONFIG, STRATA_PROJECT } from '../mesh/threemf-configs.js';
import { STRATA_PROJECT_VERSION, type StrataProject, type StrataProjectObject } from '../mesh/threemf-strata.js';
import type { Mesh, MeshObject, SettingsSource, VolumeKind } from '../mesh/types.js';

export interface WriteProjectOptions {
  /** The print's settings in Strata's keys (kept in Strata's copy). */
  printSettings?: Record<string, unknown>;
  /** The print's settings in PrusaSlicer's keys, written as its `Metadata/Slic3r_PE.config`. */
  slic3rPrintSettings?: Record<string, string>;
}

const CONTENT_TYPES = `<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">
 <Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>
 <Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>
 <Default Extension="config" ContentType="text/plain"/>
 <Default Extension="xml" ContentType="application/xml"/>
 <Default Extension="json" ContentType="application/json"/>
</Types>`;

const RELS = `<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
 <Relationship Target="/3D/3dmodel.model" Id="rel-1" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>`;

const VOLUME_TYPES: Readonly<Record<'part' | VolumeKind, string>> = {
  part: 'ModelPart',
  modifier: 'ParameterModifier',
  negative: 'NegativeVolume',
  'support-blocker': 'SupportBlocker',
  'support-enforcer': 'SupportEnforcer',
};
const IDENTITY = '1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1';

export function writeProject3mf(objects: readonly MeshObject[], opts: WriteProjectOptions = {}): Uint8Array {
  if (objects.length === 0) throw new StrataError('EMPTY_MODEL', 'a project needs at least one object to write');
  objects.forEach((o, i) => {
    if (o.mesh.indices.length === 0)
      throw new StrataError('BAD_MESH', `object ${i + 1} ("${o.name}") has no triangles to write`);
  });
  const layerHeight =
    typeof opts.printSettings?.layerHeight === 'number'
      ? opts.printSettings.layerHeight
      : (SCHEMA.layerHeight.default as number);
  const files: Record<string, Uint8Array> = {
    '[Content_Types].xml': strToU8(CONTENT_TYPES),
    '_rels/.rels': strToU8(RELS),
    '3D/3dmodel.model': strToU8(modelXml(objects)),
    [PRUSA_MODEL_CONFIG]: strToU8(modelConfigXml(objects, layerHeight)),
  };
  if (objects.some((o) => (o.layerRanges ?? []).length > 0))
    files[PRUSA_LAYER_RANGES] = strToU8(layerRangesXml(objects, layerHeight));
  if (opts.slic3rPrintSettings !== undefined)
    files[PRUSA_PRINT_CONFIG] = strToU8(slic3rConfig(opts.slic3rPrintSettings));
  files[STRATA_PROJECT] = strToU8(JSON.stringify(strataProject(objects, opts.printSettings ?? {}), null, 1));
  return zipSync(files);
}

/** The volumes written: those with triangles (an empty one changes nothing, and PrusaSlicer refuses it). */
const written = (o: MeshObject) => (o.volumes ?? []).filter((v) => v.mesh.indices.length > 0);

function modelXml(objects: readonly MeshObject[]): string {
  const out: string[] = [
    '<?xml version="1.0" encoding="UTF-8"?>\n',
    '<model unit="millimeter" xml:lang="en-US" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02" xmlns:slic3rpe="http://schemas.slic3r.org/3mf/2017/06">\n',
    ' <metadata name="slic3rpe:Version3mf">1</metadata>\n',
    ' <metadata name="Application">Strata</metadata>\n',
    ' <resources>\n',
  ];
  objects.forEach((o, i) => {
    const meshes = [o.mesh, ...written(o).map((v) => v.mesh)];
    out.push(`  <object id="${i + 1}" name="${attr(o.name)}" type="model">\n   <mesh>\n    <vertices>\n`);
    for (const m of meshes) {
      const p = m.positions;
      for (let k = 0; k < p.length; k += 3)
        out.push(`     <vertex x="${coord(p[k])}" y="${coord(p[k + 1])}" z="${coord(p[k + 2])}"/>\n`);
    }
    out.push('    </vertices>\n    <triangles>\n');
    let base = 0;
    for (const m of meshes) {
      const t = m.indices;
      for (let k = 0; k < t.length; k += 3)
        out.push(`     <triangle v1="${t[k] + base}" v2="${t[k + 1] + base}" v3="${t[k + 2] + base}"/>\n`);
      base += m.positions.length / 3;
    }
    out.push('    </triangles>\n   </mesh>\n  </object>\n');
  });
  out.push(' </resources>\n <build>\n');
  objects.forEach((_, i) => out.push(`  <item objectid="${i + 1}" printable="1"/>\n`));
  out.push(' </build>\n</model>\n');
  return out.join('');
}

function modelConfigXml(objects: readonly MeshObject[], layerHeight: number): string {
  const out: string[] = ['<?xml version="1.0" encoding="UTF-8"?>\n<config>\n'];
  const meta = (indent: string, type: string, key: string, value: string) =>
    out.push(`${indent}<metadata type="${type}" key="${attr(key)}" value="${attr(value)}"/>\n`);
  objects.forEach((o, i) => {
    out.push(` <object id="${i + 1}" instances_count="1">\n`);
    meta('  ', 'object', 'name', o.name);
    for (const [k, v] of Object.entries(slic3rValues(o.settings, layerHeight))) meta('  ', 'object', k, v);
    let first = 0;
    const volume = (mesh: Mesh, name: string, kind: 'part' | VolumeKind, settings: SettingsSource | undefined) => {
      const count = mesh.indices.length / 3;
      out.push(`  <volume firstid="${first}" lastid="${first + count - 1}">\n`);
      meta('   ', 'volume', 'name', name);
      if (kind === 'modifier') meta('   ', 'volume', 'modifier', '1');
      meta('   ', 'volume', 'volume_type', VOLUME_TYPES[kind]);
      meta('   ', 'volume', 'matrix', IDENTITY);
      for (const [k, v] of Object.entries(slic3rValues(settings, layerHeight))) meta('   ', 'volume', k, v);
      out.push(
        '   <mesh edges_fixed="0" degenerate_facets="0" facets_removed="0" facets_reversed="0" backwards_edges="0"/>\n  </volume>\n',
      );
      first += count;
    };
    volume(o.mesh, o.name, 'part', undefined);
    for (const v of written(o)) volume(v.mesh, v.name, v.kind, v.settings);
    out.push(' </object>\n');
  });
  out.push('</config>\n');
  return out.join('');
}

function layerRangesXml(objects: readonly MeshObject[], layerHeight: number): string {
  const out: string[] = ['<?xml version="1.0" encoding="utf-8"?>\n<objects>\n'];
  objects.forEach((o, i) => {
    const ranges = o.layerRanges ?? [];
    if (ranges.length === 0) return;
    out.push(` <object id="${i + 1}">\n`);
    for (const r of ranges) {
      out.push(`  <range min_z="${r.fromZ}" max_z="${r.toZ}">\n`);
      // PrusaSlicer's ranges always hold a layer height and an extruder (2.5 crashes slicing a range without the first)
      const values = { layer_height: String(layerHeight), extruder: '0', ...slic3rValues(r.settings, layerHeight) };
      for (const [k, v] of Object.entries(values)) out.push(`   <option opt_key="${attr(k)}">${text(v)}</option>\n`);
      out.push('  </range>\n');
    }
    out.push(' </object>\n');
  });
  out.push('</objects>\n');
  return out.join('');
}

function slic3rConfig(settings: Readonly<Record<string, string>>): string {
  const lines = ['; generated by Strata', ''];
  for (const [k, v] of Object.entries(settings)) lines.push(`; ${k} = ${String(v).replace(/\r?\n/g, '\\n')}`);
  return lines.join('\n') + '\n';
}

/** Settings in Strata's keys (raw Strata values as they are; another slicer's mapped, what has no equivalent left out). */
function strataValues(src: SettingsSource | undefined): Record<string, unknown> {
  if (src === undefined) return {};
  return src.format === 'strata' ? { ...src.values } : settingsFromSource(src).settings;
}

/** Settings in PrusaSlicer's keys: PrusaSlicer's own as they are, the others through Strata's. */
function slic3rValues(src: SettingsSource | undefined, layerHeight: number): Record<string, string> {
  if (src === undefined) return {};
  if (src.format === 'prusaslicer') {
    const out: Record<string, string> = {};
    for (const [k, v] of Object.entries(src.values))
      if (typeof v === 'string' || typeof v === 'number' || typeof v === 'boolean') out[k] = String(v);
    return out;
  }
  return toSlic3rKeys(strataValues(src), layerHeight);
}

function strataProject(objects: readonly MeshObject[], printSettings: Record<string, unknown>): StrataProject {
  return {
    version: STRATA_PROJECT_VERSION,
    printSettings,
    objects: objects.map(
      (o, i): StrataProjectObject => ({
        id: i + 1,
        name: o.name,
        settings: strataValues(o.settings),
        volumes: written(o).map((v) => ({ kind: v.kind, name: v.name, settings: strataValues(v.settings) })),
        layerRanges: (o.layerRanges ?? []).map((r) => ({
          fromZ: r.fromZ,
          toZ: r.toZ,
          settings: strataValues(r.settings),
        })),
      }),
    ),
  };
}

/** A float32 coordinate in the fewest digits that read back as the same float32. */
function coord(v: number): string {
  if (Number.isInteger(v)) return String(v === 0 ? 0 : v);
  for (let p = 6; p < 9; p++) {
    const s = v.toPrecision(p);
    if (Math.fround(Number(s)) === v) return String(Number(s));
  }
  return String(Number(v.toPrecision(9)));
}

function attr(s: string): string {
  return s
    .replace(/[\u0000-\u0008\u000b\u000c\u000e-\u001f]/g, '')
    .replace(/&/g, '&amp;')
    .replace(/</g, '&lt;')
    .replace(/>/g, '&gt;')
    .replace(/"/g, '&quot;')
    .replace(/\n/g, '&#10;')
    .replace(/\r/g, '&#13;')
    .replace(/\t/g, '&#9;');
}

function text(s: string): string {
  return s
    .replace(/[\u0000-\u0008\u000b\u000c\u000e-\u001f]/g, '')
    .replace(/&/g, '&amp;')
    .replace(/</g, '&lt;')
    .replace(/>/g, '&gt;');
}
