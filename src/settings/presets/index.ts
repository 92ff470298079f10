/**
 * Printer and filament presets: frozen tables keyed by id, and lookup by id, name or alias.
 *
 * Lookup is case-insensitive and treats runs of spaces and underscores as a hyphen, so "Creality Ender-3",
 * "creality_ender-3" and "ender 3" (an alias) all find `creality-ender-3`. Aliases are listed in the tables.
 */
import { FILAMENTS, type FilamentPreset } from './filaments.js';
import { PRINTERS, type PrinterPreset } from './printers.js';

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
  return name.trim().toLowerCase().replace(/[\s_]+/g, '-');
}

/** Every lookup key (id, name, aliases, normalized) of every preset → its id. Two presets sharing a key is a table error. */
function lookupIndex(list: readonly { readonly id: string; readonly name: string; readonly aliases: readonly string[] }[]): Readonly<Record<string, string>> {
  const index: Record<string, string> = Object.create(null) as Record<string, string>;
  for (const p of list) {
    for (const key of new Set([p.id, p.name, ...p.aliases].map(normalizePresetName))) {
      const other = index[key];
      if (other !== undefined && other !== p.id) throw new Error(`preset tables: "${key}" names both ${other} and ${p.id}`);
      index[key] = p.id;
    }
  }
  return Object.freeze(index);
}

const PRINTER_INDEX = lookupIndex(PRINTERS);
const FILAMENT_INDEX = lookupIndex(FILAMENTS);

/** The printer preset with this id, name or alias (case-insensitive), or undefined. */
export function findPrinter(idOrName: string): PrinterPreset | undefined {
  if (typeof idOrName !== 'string') return undefined;
  const id = PRINTER_INDEX[normalizePresetName(idOrName)];
  return id === undefined ? undefined : PRINTER_PRESETS[id];
}

/** The filament preset with this id, name or alias (case-insensitive), or undefined. */
export function findFilament(idOrName: string): FilamentPreset | undefined {
  if (typeof idOrName !== 'string') return undefined;
  const id = FILAMENT_INDEX[normalizePresetName(idOrName)];
  return id === undefined ? undefined : FILAMENT_PRESETS[id];
}

export interface PresetSummary {
  id: string;
  name: string;
  aliases: string[];
}

/** Every preset's id, name and aliases, in table order (for `strata presets` and error messages). */
export function listPresets(): { printers: PresetSummary[]; filaments: PresetSummary[] } {
  const summary = (p: { id: string; name: string; aliases: readonly string[] }): PresetSummary => ({ id: p.id, name: p.name, aliases: [...p.aliases] });
  return { printers: PRINTERS.map(summary), filaments: FILAMENTS.map(summary) };
}
