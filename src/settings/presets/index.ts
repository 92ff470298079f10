/**
 * Printer and filament presets: frozen tables keyed by id, and lookup by id, name or alias.
 *
 * Lookup is case-insensitive and treats runs of spaces and underscores as a hyphen, so "Creality Ender-3",
 * "creality_ender-3" and "ender 3" (an alias) all find `creality-ender-3`. Aliases are listed in the tables,
 * and the names other programs use (the seeds' library, PrusaSlicer, Cura) in aliases.ts.
 */
import { CURA_WITHOUT_PRESET, FOREIGN_NAMES, PRINTERS_WITHOUT_PRESET, type PrinterWithoutPreset } from './aliases.js';
import { FILAMENTS, type FilamentPreset } from './filaments.js';
import { PRINTERS, type PrinterPreset } from './printers.js';

export type { PrinterWithoutPreset } from './aliases.js';

export type { FilamentPreset } from './filaments.js';
export type { ExtruderKind, PrinterPreset } from './printers.js';

export const DEFAULT_PRINTER_ID = 'creality-ender-3';
export const DEFAULT_FILAMENT_ID = 'pla';

function byId<T extends { readonly id: string }>(list: readonly T[]): Readonly<Record<string, T>> {
  const table: Record<string, T> = Object.create(null) as Record<string, T>;
  for (const p of list) table[p.id] = p;
  return Object.freeze(table);
}

/** Printer presets keyed by id. */
export const PRINTER_PRESETS: Readonly<Record<string, PrinterPreset>> = byId(PRINTERS);
/** Filament presets keyed by id. */
export const FILAMENT_PRESETS: Readonly<Record<string, FilamentPreset>> = byId(FILAMENTS);

/** The form ids, names and aliases are compared in: trimmed, lower-case, spaces/underscores → one hyphen. */
export function normalizePresetName(name: string): string {
  return name
    .trim()
    .toLowerCase()
    .replace(/[\s_]+/g, '-');
}

/**
 * Every lookup key (id, name, aliases, other programs' names; normalized) of every preset → its id. Two
 * presets sharing a key, or a foreign name for a preset that does not exist, is a table error.
 */
function lookupIndex(
  list: readonly { readonly id: string; readonly name: string; readonly aliases: readonly string[] }[],
  foreign: ReadonlyArray<Readonly<Record<string, string>>>,
): Readonly<Record<string, string>> {
  const index: Record<string, string> = Object.create(null) as Record<string, string>;
  const add = (name: string, id: string) => {
    const key = normalizePresetName(name);
    const other = index[key];
    if (other !== undefined && other !== id) throw new Error(`preset tables: "${key}" names both ${other} and ${id}`);
    index[key] = id;
  };
  for (const p of list) for (const name of [p.id, p.name, ...p.aliases]) add(name, p.id);
  for (const table of foreign) {
    for (const [name, id] of Object.entries(table)) {
      if (!list.some((p) => p.id === id))
        throw new Error(`preset tables: "${name}" names ${id}, which is not a preset`);
      add(name, id);
    }
  }
  return Object.freeze(index);
}

const SOURCES = Object.values(FOREIGN_NAMES);
const PRINTER_INDEX = lookupIndex(
  PRINTERS,
  SOURCES.map((s) => s.printers),
);
const FILAMENT_INDEX = lookupIndex(
  FILAMENTS,
  SOURCES.map((s) => s.filaments),
);

/** PrusaSlicer's and OrcaSlicer's preset names end in the nozzle size: "Original Prusa MK4S 0.4 nozzle". */
const NOZZLE_SUFFIX = /[-\s]*\(?0\.4\s*(?:mm)?[-\s]*nozzle\)?$/i;

/** The printer preset with this id, name or alias (case-insensitive), or undefined. */
export function findPrinter(idOrName: string): PrinterPreset | undefined {
  if (typeof idOrName !== 'string') return undefined;
  const id =
    PRINTER_INDEX[normalizePresetName(idOrName)] ??
    PRINTER_INDEX[normalizePresetName(idOrName.trim().replace(NOZZLE_SUFFIX, ''))];
  return id === undefined ? undefined : PRINTER_PRESETS[id];
}

/** The filament preset with this id, name or alias (case-insensitive), or undefined. */
export function findFilament(idOrName: string): FilamentPreset | undefined {
  if (typeof idOrName !== 'string') return undefined;
  const id = FILAMENT_INDEX[normalizePresetName(idOrName)];
  return id === undefined ? undefined : FILAMENT_PRESETS[id];
}

const WITHOUT_PRESET_INDEX: Readonly<Record<string, PrinterWithoutPreset>> = Object.freeze(
  Object.assign(
    Object.create(null) as Record<string, PrinterWithoutPreset>,
    Object.fromEntries([
      ...Object.entries(PRINTERS_WITHOUT_PRESET).flatMap(([key, p]) => [
        [normalizePresetName(key), p],
        [normalizePresetName(p.name), p],
      ]),
      ...Object.entries(CURA_WITHOUT_PRESET).map(([cura, key]) => [
        normalizePresetName(cura),
        PRINTERS_WITHOUT_PRESET[key]!,
      ]),
    ]),
  ),
);

/** A printer other programs name that has no preset here (its build volume and why), or undefined. */
export function printerWithoutPreset(name: string): PrinterWithoutPreset | undefined {
  if (typeof name !== 'string') return undefined;
  return WITHOUT_PRESET_INDEX[normalizePresetName(name)];
}

export interface PresetSummary {
  id: string;
  name: string;
  aliases: string[];
}

/** Every preset's id, name and aliases, in table order (for `strata presets` and error messages). */
export function listPresets(): { printers: PresetSummary[]; filaments: PresetSummary[] } {
  const summary = (p: { id: string; name: string; aliases: readonly string[] }): PresetSummary => ({
    id: p.id,
    name: p.name,
    aliases: [...p.aliases],
  });
  return { printers: PRINTERS.map(summary), filaments: FILAMENTS.map(summary) };
}
