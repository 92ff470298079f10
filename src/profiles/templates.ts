/**
 * G-code templates from other slicers (start, end, layer change, colour change, pause), kept as their
 * authors wrote them: Strata's template language reads PrusaSlicer's and OrcaSlicer's macros (`[key]`,
 * `{key[0]}`, `{if …}`, arithmetic) and Cura's `{key}` / `{key, 0}`, and knows their names for the
 * quantities Strata has (temperatures, heights, the bed, the layer: gcode/template-vars.ts), which the
 * G-code then gets from Strata's settings.
 *
 * A name Strata has no quantity for (`printer_model`, `filament_notes`, `print_settings_id`,
 * `nozzle_high_flow`…) is fixed to the profile's own value where the profile holds one: `[printer_model]`
 * becomes `MK4`, `{filament_notes[0] =~ /HT_MBL10/}` compares the profile's notes. A template naming
 * anything else, or that does not parse, cannot be kept: the caller keeps Strata's and says why.
 */
import { legacyIsText, parseTemplate, variableUses, type Expr, type VariableUse } from '../gcode/template-parse.js';
import { isTemplateVariable } from '../gcode/template-vars.js';
import { StrataError } from '../errors.js';
import type { ImportContext } from './context.js';
import { text } from './values.js';

/** A profile's raw value of a key (undefined when it has none). */
export type ProfileLookup = (key: string) => string | undefined;

/** The entries of a list value: `a,b`, `"a";"b"` (PrusaSlicer's text lists, `\n` escapes), or one value. */
export function listEntries(raw: string): string[] {
  const v = raw.trim();
  if (v.startsWith('"')) {
    const out: string[] = [];
    const re = /"((?:[^"\\]|\\.)*)"\s*[;,]?\s*/gy;
    let m: RegExpExecArray | null;
    while ((m = re.exec(v)))
      out.push(m[1]!.replace(/\\(.)/g, (_w, c: string) => (c === 'n' ? '\n' : c === 't' ? '\t' : c)));
    if (re.lastIndex === 0 && out.length === 0) return [v];
    return out;
  }
  if (v.includes(';')) return v.split(';').map((s) => s.trim());
  const parts = v.split(',').map((s) => s.trim());
  return parts.length > 1 && parts.every((p) => /^-?(\d+\.?\d*|\.\d+)%?$/.test(p) || p === 'nil') ? parts : [v];
}

const NUMBER = /^-?(\d+\.?\d*|\.\d+)$/;

/** An expression literal for a profile value: a number, true / false (Cura's), or quoted text (one line). */
function literal(value: string): string {
  if (NUMBER.test(value)) return String(Number(value));
  if (value === 'True' || value === 'False') return value === 'True' ? 'true' : 'false';
  return `"${value.replace(/\r?\n/g, ' ').replace(/\\/g, '\\\\').replace(/"/g, '\\"')}"`;
}

/** The index a use asks for, when it can be known now (a number, or an extruder number: 0); else 0. */
function indexOf(use: VariableUse): number {
  const i = use.index;
  if (i === null) return 0;
  if (typeof i === 'string') return /^\d+$/.test(i) ? Number(i) : 0;
  const e: Expr = i;
  return e.k === 'num' && Number.isInteger(e.v) && e.v >= 0 ? e.v : 0;
}

/**
 * `template` kept in its own syntax, with the names Strata has no quantity for replaced by the profile's
 * values; or why it cannot be kept (`unknown`: names neither Strata nor the profile has; `error`: it does
 * not parse).
 */
export function keepTemplate(
  template: string,
  profile: ProfileLookup,
): { text: string } | { unknown: string[] } | { error: string } {
  let uses: VariableUse[];
  try {
    uses = variableUses(parseTemplate('template', template));
  } catch (e) {
    if (e instanceof StrataError) return { error: e.message.replace(/^template /, '') };
    throw e;
  }
  const unknown = new Set<string>();
  const edits: Array<{ start: number; end: number; text: string }> = [];
  let replacedTo = -1;
  for (const use of [...uses].sort((a, b) => a.start - b.start)) {
    if (use.start < replacedTo) continue; // inside a replaced reference (its index)
    let name = use.name;
    let index = indexOf(use);
    if (isTemplateVariable(name)) continue;
    const suffix = use.legacy && use.index === null ? /^(.+)_(\d+)$/.exec(name) : null;
    if (suffix && isTemplateVariable(suffix[1]!)) continue;
    const raw = profile(name) ?? (suffix ? profile(suffix[1]!) : undefined);
    if (raw === undefined || raw.startsWith('=')) {
      if (!(use.legacy && legacyIsText(use))) unknown.add(name);
      continue;
    }
    if (suffix && profile(name) === undefined) {
      name = suffix[1]!;
      index = Number(suffix[2]);
    }
    const entries = listEntries(raw);
    const value = entries[index] ?? entries[0]!;
    if (value === 'nil') {
      unknown.add(name);
      continue;
    }
    // `[name]` writes text as it is, where it stands; inside an expression it is a literal
    const text = use.legacy ? (/[{}[\]\n]/.test(value) ? `{${literal(value)}}` : value) : literal(value);
    edits.push({ start: use.start, end: use.end, text });
    replacedTo = use.end;
  }
  if (unknown.size) return { unknown: [...unknown] };
  let out = template;
  for (const e of edits.sort((a, b) => b.start - a.start)) out = out.slice(0, e.start) + e.text + out.slice(e.end);
  return { text: out };
}

/** The template settings an import can set. */
export type TemplateSetting =
  | 'startGcode'
  | 'endGcode'
  | 'beforeLayerChangeGcode'
  | 'layerChangeGcode'
  | 'colorChangeGcode'
  | 'pauseGcode';

/**
 * Take the template under the first of `keys` the profile has for `setting`, kept as written (see
 * keepTemplate), or report why not. `unwrap` takes off a quoting of the whole value (Cura's `"""`).
 */
export function importTemplate(
  c: ImportContext,
  keys: readonly string[],
  setting: TemplateSetting,
  unwrap = (v: string) => v,
): void {
  const t = c.getAny(...keys);
  if (!t) return;
  const kept = keepTemplate(text(unwrap(t.value)) ?? '', (k) => c.get(k));
  if ('text' in kept) c.set(setting, kept.text, t.key);
  else if ('unknown' in kept)
    c.reject(
      t.key,
      `uses placeholders Strata cannot fill (${kept.unknown.slice(0, 6).join(', ')}); the preset's is kept`,
    );
  else c.reject(t.key, `cannot be read (${kept.error}); the preset's is kept`);
}
