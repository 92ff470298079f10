/**
 * Cura projects (Cura's 3MFWriter through libSavitar, confirmed in libSavitar `src/Scene.cpp`,
 * `src/SceneNode.cpp` and Cura `plugins/3MFReader`, `plugins/3MFWriter`):
 * - a node's per-object settings are its object's `<metadatagroup>` entries `<metadata name="cura:key">value
 *   </metadata>` (older files: `<settings><setting key="…">value</setting></settings>`), the prefix bound to
 *   http://software.ultimaker.com/xml/cura/3mf/2015/10 (or written `cura:` without a declaration);
 * - a node with a mesh and children keeps its mesh in a component of its own, named by its
 *   `mesh_node_objectid` entry; groups are objects with components;
 * - a mesh with `infill_mesh` or `cutting_mesh` set is a modifier (it changes the settings inside it),
 *   `anti_overhang_mesh` a support blocker, `support_mesh` a support enforcer;
 * - the print's settings are the project's container stacks, `Cura/*.global.cfg` and `Cura/*.extruder.cfg`,
 *   each listing its containers (`[containers]` 0 = the user's changes … last = the definition), whose
 *   `Cura/<id>.inst.cfg` hold `[values]`.
 */
import type { ObjectSpec, PieceSpec, TriangleRun } from './threemf-assemble.js';
import type { ModelObject, ModelPart } from './threemf-model.js';
import { partKey, type ThreeMfPackage } from './threemf-package.js';
import type { Build, BuildItem, ExpandedItem } from './threemf.js';
import type { SettingsSource, VolumeKind } from './types.js';

export const CURA_NS = 'http://software.ultimaker.com/xml/cura/3mf/2015/10';
/** Most bytes one Cura container file may hold. */
const MAX_STACK_FILE_BYTES = 4 * 1024 * 1024;

/** Entries that say what a node is or where it goes rather than how it prints. */
const NOT_SETTINGS = new Set([
  'mesh_node_objectid',
  'extruder_nr',
  'print_order',
  'drop_to_buildplate',
  'setting_version',
]);
const MESH_KINDS: ReadonlyArray<readonly [string, VolumeKind]> = [
  ['infill_mesh', 'modifier'],
  ['cutting_mesh', 'modifier'],
  ['anti_overhang_mesh', 'support-blocker'],
  ['support_mesh', 'support-enforcer'],
];

/** Whether a 3MF was written by Cura: its Cura/ folder, its Application, or Cura-namespaced entries. */
export function isCuraProject(build: Build): boolean {
  const app = build.root.metadata.get('Application') ?? '';
  if (/cura/i.test(app)) return true;
  if (build.pkg.keys().some((k) => k.startsWith('cura/'))) return true;
  if ([...build.root.namespaces.values()].includes(CURA_NS)) return true;
  for (const o of build.root.objects.values()) {
    if (o.metadata !== null && [...o.metadata.keys()].some((k) => k.startsWith('cura:'))) return true;
  }
  return false;
}

/** A node's Cura settings (prefix removed), or null when it has none. */
function nodeSettings(
  metadata: ReadonlyMap<string, string> | null | undefined,
  root: ModelPart,
): Map<string, string> | null {
  if (!metadata) return null;
  const out = new Map<string, string>();
  for (const [name, value] of metadata) {
    const colon = name.indexOf(':');
    let key = name;
    if (colon >= 0) {
      const prefix = name.slice(0, colon);
      if (prefix !== 'cura' && root.namespaces.get(prefix) !== CURA_NS) continue;
      key = name.slice(colon + 1);
    }
    if (key !== '' && !NOT_SETTINGS.has(key)) out.set(key, value);
  }
  return out.size > 0 ? out : null;
}

const isTrue = (v: string | undefined): boolean => v !== undefined && /^(true|1|yes)$/i.test(v.trim());

/** What each of an item's triangles is, for a Cura project. */
export function curaPlanner(build: Build): (item: BuildItem, e: ExpandedItem) => ObjectSpec {
  const settingsOf = new Map<ModelObject, Map<string, string> | null>();
  const own = (o: ModelObject): Map<string, string> | null => {
    if (!settingsOf.has(o)) settingsOf.set(o, nodeSettings(o.metadata, build.root));
    return settingsOf.get(o)!;
  };
  return (item, e) => {
    const itemSettings = nodeSettings(item.ref.metadata, build.root);
    // each run of triangles takes the settings of the nearest node above it that has some
    const owners = e.segments.map((s) => {
      for (let k = s.path.length - 1; k >= 0; k--) {
        const node = s.path[k];
        let settings = own(node);
        if (k === 0 && itemSettings !== null) settings = new Map([...(settings ?? []), ...itemSettings]);
        // a node's own mesh, kept in a component of its own, is the node's
        if (settings === null && k > 0 && s.path[k - 1].metadata?.get('mesh_node_objectid') === String(node.id))
          continue;
        if (settings !== null) return { node, settings };
      }
      return null;
    });
    // runs grouped by the node whose settings they take (null: none), printed ones and volumes apart
    const printed = new Map<ModelObject | null, { settings: SettingsSource | null; runs: TriangleRun[] }>();
    const volumes = new Map<ModelObject, { kind: VolumeKind; settings: SettingsSource | null; runs: TriangleRun[] }>();
    e.segments.forEach((s, k) => {
      const run = { start: s.start, count: s.count };
      const owner = owners[k];
      const kind = owner === null ? undefined : MESH_KINDS.find(([key]) => isTrue(owner.settings.get(key)))?.[1];
      if (owner !== null && kind !== undefined) {
        const known = volumes.get(owner.node);
        if (known) known.runs.push(run);
        else volumes.set(owner.node, { kind, settings: stripKinds(owner.settings), runs: [run] });
        return;
      }
      const node = owner?.node ?? null;
      const known = printed.get(node);
      if (known) known.runs.push(run);
      else printed.set(node, { settings: owner === null ? null : stripKinds(owner.settings), runs: [run] });
    });
    const spec: ObjectSpec = { name: item.label, pieces: [] };
    for (const [node, { settings, runs }] of printed) {
      const p: PieceSpec = { kind: 'part', name: node?.name || item.label, runs };
      // one printed mesh: its settings are the object's; several: each one's are a modifier over it
      if (settings !== null && printed.size === 1) spec.settings = settings;
      else if (settings !== null) p.settings = settings;
      spec.pieces.push(p);
    }
    for (const [node, { kind, settings, runs }] of volumes) {
      const p: PieceSpec = { kind, name: node.name || `${item.label} ${kind}`, runs };
      if (settings !== null) p.settings = settings;
      spec.pieces.push(p);
    }
    return spec;
  };
}

/** A node's settings without the entries that say what kind of mesh it is. */
function stripKinds(settings: ReadonlyMap<string, string>): SettingsSource | null {
  const values: Record<string, string> = {};
  let any = false;
  for (const [k, v] of settings) {
    if (MESH_KINDS.some(([key]) => key === k)) continue;
    values[k] = v;
    any = true;
  }
  return any ? { format: 'cura', values } : null;
}

/**
 * The print's settings from a Cura project's stacks: the global stack's containers, then the first
 * extruder's over them, each from the definition up to the user's changes. Undefined when there are none.
 */
export function curaProjectSettings(
  pkg: ThreeMfPackage,
  readText: (key: string, maxBytes: number) => string | undefined,
): SettingsSource | undefined {
  const keys = pkg.keys().filter((k) => k.startsWith('cura/'));
  const globalKey = keys.find((k) => k.endsWith('.global.cfg'));
  if (globalKey === undefined) return undefined;
  const extruders = keys
    .filter((k) => k.endsWith('.extruder.cfg'))
    .map((k) => ({ k, ini: parseCuraIni(readText(k, MAX_STACK_FILE_BYTES) ?? '') }))
    .sort(
      (a, b) =>
        Number(a.ini.get('metadata')?.get('position') ?? 99) - Number(b.ini.get('metadata')?.get('position') ?? 99),
    );
  const stacks = [
    parseCuraIni(readText(globalKey, MAX_STACK_FILE_BYTES) ?? ''),
    ...(extruders.length > 0 ? [extruders[0].ini] : []),
  ];
  const values: Record<string, string> = {};
  let any = false;
  for (const stack of stacks) {
    const containers = [...(stack.get('containers') ?? new Map()).entries()]
      .filter(([i]) => /^\d+$/.test(i))
      .sort((a, b) => Number(b[0]) - Number(a[0]));
    for (const [, id] of containers) {
      const text = readText(partKey(`Cura/${id}.inst.cfg`), MAX_STACK_FILE_BYTES);
      if (text === undefined) continue;
      for (const [k, v] of parseCuraIni(text).get('values') ?? []) {
        values[k] = v;
        any = true;
      }
    }
  }
  return any ? { format: 'cura', values } : undefined;
}

/**
 * Cura's container files: `[section]` headers, `key = value` lines, indented lines continuing a value (a
 * start G-code's lines, which profiles/ini.ts would take for keys of their own).
 */
function parseCuraIni(text: string): Map<string, Map<string, string>> {
  const out = new Map<string, Map<string, string>>();
  let section: Map<string, string> | null = null;
  let last = '';
  for (const raw of text.replace(/^\uFEFF/, '').split(/\r?\n/)) {
    const line = raw.trim();
    if (line === '' || line.startsWith('#') || line.startsWith(';')) continue;
    const header = /^\[([^\]]*)\]$/.exec(line);
    if (header) {
      section = new Map();
      out.set(header[1].trim(), section);
      last = '';
      continue;
    }
    if (section === null) continue;
    if (/^\s/.test(raw) && last !== '') {
      section.set(last, `${section.get(last)}\n${line}`);
      continue;
    }
    const eq = line.indexOf('=');
    if (eq <= 0) continue;
    last = line.slice(0, eq).trim();
    section.set(last, line.slice(eq + 1).trim());
  }
  return out;
}
