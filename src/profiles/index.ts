/**
 * Profiles from other slicers, and Strata's own JSON, read into Strata settings:
 * - PrusaSlicer / SuperSlicer `.ini` exports and config bundles (`[print:…]`, `[filament:…]`,
 *   `[printer:…]` with the `[presets]` choice, `inherits` followed inside the bundle), and the config
 *   block at the end of their G-code;
 * - OrcaSlicer: `.ini` exports and its JSON presets (`"type": "process" | "filament" | "machine"`);
 * - Cura `.cfg` / `.inst.cfg` profiles (`[values]`);
 * - Strata JSON: an object of Strata settings (may name `printer` and `filament`).
 * Every key that maps onto a Strata setting is converted (units, percentages); what is left is listed
 * in one warning, and values that map but cannot be taken in another. No I/O: callers pass the text.
 */
import { StrataError } from '../errors.js';
import { SCHEMA, type SliceOptions } from '../settings/schema.js';
import { ImportContext, type RejectedValue } from './context.js';
import { mapCuraKeys } from './cura-keys.js';
import { parseIni, type IniFile } from './ini.js';
import { mapSlic3rKeys, SLIC3R_METADATA, type Slic3rFlavor } from './slic3r-keys.js';

export type ProfileFormat = 'strata' | Slic3rFlavor | 'cura';

export interface ImportedProfile {
  format: ProfileFormat;
  /** Strata settings (each checked against the schema), plus `printer` / `filament` for Strata JSON. */
  settings: SliceOptions;
  /** Keys of the profile that map onto no Strata setting. */
  unused: string[];
  /** Values that map onto a setting but could not be taken, and why. */
  rejected: RejectedValue[];
  /** At most two lines for the user: the unused keys, and the values not taken. */
  warnings: string[];
}

/** Cura sections that hold no settings. */
const CURA_META_SECTIONS = new Set(['general', 'metadata']);

function describe(source: string, unused: string[], rejected: RejectedValue[]): string[] {
  const out: string[] = [];
  if (unused.length)
    out.push(
      `${source}: ${unused.length} setting${unused.length === 1 ? '' : 's'} with no Strata equivalent, not used: ${unused.join(', ')}`,
    );
  if (rejected.length) out.push(`${source}: not taken: ${rejected.map((r) => `${r.key} (${r.reason})`).join('; ')}`);
  return out;
}

function finish(format: ProfileFormat, c: ImportContext, ignore: ReadonlySet<string>, source: string): ImportedProfile {
  const unused = c.unused(ignore);
  return {
    format,
    settings: { ...c.settings },
    unused,
    rejected: c.rejected,
    warnings: describe(source, unused, c.rejected),
  };
}

/** Which Slic3r-family slicer wrote a file, from its generator line or its keys. */
function slic3rFlavor(generator: string | undefined, keys: Iterable<string>): Slic3rFlavor {
  const g = (generator ?? '').toLowerCase();
  if (g.includes('superslicer')) return 'superslicer';
  if (g.includes('orca') || g.includes('bambu')) return 'orcaslicer';
  if (g.includes('prusaslicer') || g.includes('slic3r')) return 'prusaslicer';
  const set = new Set(keys);
  if (
    ['sparse_infill_density', 'wall_loops', 'outer_wall_speed', 'printable_area', 'initial_layer_print_height'].some(
      (k) => set.has(k),
    )
  )
    return 'orcaslicer';
  if (
    [
      'thin_walls_min_width',
      'perimeter_round_corners',
      'top_fan_speed',
      'external_perimeter_cut_corners',
      'start_gcode_manual',
    ].some((k) => set.has(k))
  )
    return 'superslicer';
  return 'prusaslicer';
}

/** A bundle's sections of one kind (`print`, `filament`, `printer`) by name. */
function bundleSections(ini: IniFile, kind: string): Map<string, Map<string, string>> {
  const out = new Map<string, Map<string, string>>();
  for (const s of ini.sections) if (s.name.startsWith(kind + ':')) out.set(s.name.slice(kind.length + 1), s.values);
  return out;
}

/** A bundle section's values with its `inherits` chain (inside the bundle) applied under it. */
function withParents(
  sections: Map<string, Map<string, string>>,
  name: string,
  seen = new Set<string>(),
): Map<string, string> {
  const own = sections.get(name)!;
  const parents = (own.get('inherits') ?? '')
    .split(';')
    .map((s) => s.trim())
    .filter((p) => p && sections.has(p) && !seen.has(p));
  const merged = new Map<string, string>();
  seen.add(name);
  for (const p of parents) for (const [k, v] of withParents(sections, p, seen)) merged.set(k, v);
  for (const [k, v] of own) merged.set(k, v);
  return merged;
}

/** The flat key → value map of a Slic3r-family INI (a plain export, a G-code config block, or a bundle). */
function slic3rValues(ini: IniFile): Map<string, string> {
  const kinds = ['printer', 'filament', 'print'];
  if (!ini.sections.some((s) => kinds.some((k) => s.name.startsWith(k + ':')))) {
    const merged = new Map<string, string>();
    for (const s of ini.sections) for (const [k, v] of s.values) merged.set(k, v);
    return merged;
  }
  const chosen = ini.sections.find((s) => s.name === 'presets')?.values;
  const merged = new Map<string, string>();
  for (const kind of kinds) {
    const sections = bundleSections(ini, kind);
    const name = [chosen?.get(kind), ...sections.keys()].find(
      (n) => n !== undefined && sections.has(n) && !n.startsWith('*'),
    );
    if (name === undefined) continue;
    for (const [k, v] of withParents(sections, name)) merged.set(k, v);
  }
  return merged;
}

function importIni(text: string, source: string, cura: boolean): ImportedProfile {
  const ini = parseIni(text);
  const isCura =
    cura || (ini.sections.some((s) => s.name === 'values') && ini.sections.some((s) => s.name === 'general'));
  if (isCura) {
    const values = new Map<string, string>();
    for (const s of ini.sections) {
      if (CURA_META_SECTIONS.has(s.name)) continue;
      for (const [k, v] of s.values) values.set(k, v);
    }
    const c = new ImportContext(values);
    mapCuraKeys(c);
    return finish('cura', c, new Set(), source);
  }
  const values = slic3rValues(ini);
  if (values.size === 0) throw new StrataError('BAD_FILE', `${source} holds no settings (key = value lines)`);
  const flavor = slic3rFlavor(ini.generator, values.keys());
  const c = new ImportContext(values);
  mapSlic3rKeys(c, flavor);
  return finish(flavor, c, SLIC3R_METADATA, source);
}

function importJson(text: string, source: string): ImportedProfile {
  let obj: unknown;
  try {
    obj = JSON.parse(text);
  } catch (e) {
    throw new StrataError('BAD_FILE', `${source} is not valid JSON: ${(e as Error).message}`);
  }
  if (!obj || typeof obj !== 'object' || Array.isArray(obj))
    throw new StrataError('BAD_FILE', `${source} must hold a JSON object of settings`);
  const record = obj as Record<string, unknown>;
  // JSON.parse keeps "__proto__" as a key, but copying it (Object.assign, a spread into a setter) would
  // drop it or change a prototype: refused here, as the Slicer and the page refuse it
  if (Object.hasOwn(record, '__proto__'))
    throw new StrataError(
      'UNKNOWN_SETTING',
      `${source}: unknown setting "__proto__"; \`strata settings\` lists them all`,
    );
  const keys = Object.keys(record);
  const strataKeys = keys.filter((k) => Object.hasOwn(SCHEMA, k) || k === 'printer' || k === 'filament');
  // an OrcaSlicer / Bambu Studio preset: their keys, values as strings or lists of strings
  if (strataKeys.length < keys.length / 2 && keys.some((k) => /_/.test(k))) {
    const values = new Map<string, string>();
    for (const [k, v] of Object.entries(record)) {
      if (typeof v === 'string') values.set(k, v);
      else if (typeof v === 'number' || typeof v === 'boolean') values.set(k, String(v));
      else if (Array.isArray(v) && v.every((x) => typeof x === 'string' || typeof x === 'number')) {
        values.set(k, /gcode$/.test(k) ? String(v[0] ?? '') : v.map(String).join(','));
      }
    }
    const c = new ImportContext(values);
    mapSlic3rKeys(c, 'orcaslicer');
    return finish('orcaslicer', c, SLIC3R_METADATA, source);
  }
  return { format: 'strata', settings: record as SliceOptions, unused: [], rejected: [], warnings: [] };
}

/**
 * Read a profile. `fileName` picks the format by its extension (`.json`, `.ini`, `.cfg`, `.inst.cfg`,
 * `.gcode`); without one the text decides. Throws StrataError BAD_FILE for a file that is none of them.
 */
export function importProfile(text: string, fileName = 'profile'): ImportedProfile {
  const name = fileName.toLowerCase();
  const trimmed = text.replace(/^\uFEFF/, '').trimStart();
  if (name.endsWith('.json') || (!/\.(ini|cfg|gcode|txt)$/.test(name) && trimmed.startsWith('{')))
    return importJson(trimmed, fileName);
  if (trimmed.startsWith('{')) return importJson(trimmed, fileName);
  if (!/^\s*([#;[]|[A-Za-z_][\w.]*\s*=)/m.test(text)) {
    throw new StrataError(
      'BAD_FILE',
      `${fileName} is neither JSON nor a PrusaSlicer/SuperSlicer/OrcaSlicer .ini or Cura .cfg profile`,
    );
  }
  return importIni(text, fileName, name.endsWith('.cfg'));
}

export { settingsFromSource, type ObjectSettings } from './object-settings.js';
