/**
 * Start, end and per-layer G-code templates: parsed and checked once (`compileTemplate`), run once per
 * use (`runCompiledTemplate`). The language is template-parse.ts's and template-lang.ts's (Strata's `{key}`, PrusaSlicer's and
 * OrcaSlicer's macros, Cura's `{key}`); the variables are template-vars.ts's (every setting, the values
 * the writer derives, and other slicers' names for them).
 *
 * `{key}` of a setting writes its value as before: numbers compactly (up to 5 decimals), booleans as
 * 1/0, text as it is; an empty derived setting (firstLayerNozzleTemperature…) falls back as the schema
 * says. Replaced text is never expanded again.
 */
import { StrataError } from '../errors.js';
import type { Settings } from '../settings/schema.js';
import { runTemplate } from './template-lang.js';
import { legacyIsText, parseTemplate, variableUses, type ParsedTemplate } from './template-parse.js';
import {
  aliasOf,
  isTemplateVariable,
  templateVariable,
  templateVariableSize,
  type TemplateValues,
} from './template-vars.js';

export type { TemplateValue } from './template-lang.js';
export type { TemplateValues } from './template-vars.js';
export { settingValue } from './template-vars.js';

/** Whether a legacy `[name]` / `[name_N]` names a variable. */
function legacyKnown(name: string, values: TemplateValues): boolean {
  if (isTemplateVariable(name, values)) return true;
  const suffix = /^(.+)_(\d+)$/.exec(name);
  return suffix !== null && isTemplateVariable(suffix[1]!, values);
}

/**
 * Parse `text` (the setting `name`, for messages) and check that every variable it uses, in every
 * branch, exists (`extraNames`: values the caller will give besides the usual ones). Throws StrataError
 * BAD_SETTING naming the line for a syntax error or an unknown placeholder.
 */
export function compileTemplate(name: string, text: string, extraNames: readonly string[] = []): ParsedTemplate {
  const t = parseTemplate(name, text);
  const extra: Record<string, null> = {};
  for (const k of extraNames) extra[k] = null;
  for (const use of variableUses(t)) {
    if (use.legacy ? legacyKnown(use.name, extra) || legacyIsText(use) : isTemplateVariable(use.name, extra)) continue;
    const alone = use.src === `{${use.name}}` || use.src === `[${use.name}]`;
    throw new StrataError(
      'BAD_SETTING',
      `${name} line ${use.line}: unknown placeholder ${alone ? use.src : `${use.name} in ${use.src}`}`,
    );
  }
  return t;
}

/** Run a compiled template with `settings` and this use's `values` (which win over settings): its lines. */
export function runCompiledTemplate(t: ParsedTemplate, settings: Settings, values: TemplateValues = {}): string[] {
  const scope = { settings, values };
  return runTemplate(t, {
    has: (n) => isTemplateVariable(n, values),
    value: (n, i) => templateVariable(n, i, scope) ?? null,
    size: (n) => templateVariableSize(n),
  }).map((l) => l.text);
}

/**
 * Expand `template` (the setting `name`, for messages) with `settings` and `extra` values (which win
 * over settings). Throws StrataError BAD_SETTING for a syntax error, an unknown placeholder or one with
 * no value, naming the line.
 */
export function expandTemplate(name: string, template: string, settings: Settings, extra: TemplateValues = {}): string {
  return runCompiledTemplate(compileTemplate(name, template, Object.keys(extra)), settings, extra).join('\n');
}

/**
 * The quantities a template uses, by their Strata names, in order of first use: a setting or derived
 * value under its own name, or the one another slicer's name stands for (`first_layer_temperature` is
 * firstLayerNozzleTemperature). A template that does not parse uses none.
 */
export function placeholders(template: string): string[] {
  let t: ParsedTemplate;
  try {
    t = parseTemplate('template', template);
  } catch {
    return [];
  }
  const keys: string[] = [];
  for (const use of variableUses(t)) {
    const suffix = use.legacy ? /^(.+)_(\d+)$/.exec(use.name) : null;
    const name = suffix && !isTemplateVariable(use.name) ? suffix[1]! : use.name;
    const key = aliasOf(name) ?? name;
    if (!keys.includes(key)) keys.push(key);
  }
  return keys;
}
