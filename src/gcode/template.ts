/**
 * Start/end G-code templates: `{key}` placeholders replaced by values. A key is any setting, or one of
 * the derived values the writer adds (layer count, bounds, estimates). Numbers are written compactly
 * (up to 5 decimals), booleans as 1/0, strings as they are; replaced text is not expanded again.
 * Braces around anything that is not an identifier (`{ }`, `{a b}`) are left alone.
 */
import { StrataError } from '../errors.js';
import type { Settings } from '../settings/schema.js';
import { compact } from './format.js';

export type TemplateValue = number | string | boolean | null;
export type TemplateValues = Readonly<Record<string, TemplateValue>>;

/**
 * Nullable settings whose empty value means "same as another setting", as the schema describes: used
 * when the caller has not already resolved them.
 */
const FALLBACKS: Readonly<Record<string, readonly string[]>> = {
  firstLayerNozzleTemperature: ['nozzleTemperature'],
  firstLayerBedTemperature: ['bedTemperature'],
  lineWidth: ['nozzleDiameter'],
  firstLayerLineWidth: ['lineWidth', 'nozzleDiameter'],
  topSkinThickness: ['shellSkinThickness'],
  bottomSkinThickness: ['shellSkinThickness'],
};

const PLACEHOLDER = /\{([A-Za-z_][A-Za-z0-9_]*)\}/g;

/** A setting value with the schema's fallbacks for empty (null) derived settings applied. */
export function settingValue(settings: Settings, key: string): TemplateValue | undefined {
  const table = settings as unknown as Record<string, TemplateValue>;
  if (!Object.prototype.hasOwnProperty.call(table, key)) return undefined;
  let value = table[key];
  for (const other of FALLBACKS[key] ?? []) {
    if (value !== null && value !== undefined) break;
    value = table[other];
  }
  return value ?? null;
}

function text(value: TemplateValue): string {
  if (typeof value === 'number') return compact(value);
  if (typeof value === 'boolean') return value ? '1' : '0';
  return String(value);
}

/** The placeholder keys a template uses, in order of first use. */
export function placeholders(template: string): string[] {
  const keys: string[] = [];
  for (const m of template.matchAll(PLACEHOLDER)) if (!keys.includes(m[1]!)) keys.push(m[1]!);
  return keys;
}

/**
 * Replace the placeholders of `template` (the setting named `name`, for messages). `extra` values win
 * over settings. Throws StrataError BAD_SETTING for an unknown placeholder or one with no value.
 */
export function expandTemplate(name: string, template: string, settings: Settings, extra: TemplateValues = {}): string {
  return template.replace(PLACEHOLDER, (_whole, key: string) => {
    const value = Object.prototype.hasOwnProperty.call(extra, key) ? extra[key] : settingValue(settings, key);
    if (value === undefined) throw new StrataError('BAD_SETTING', `${name}: unknown placeholder {${key}}`);
    if (value === null) throw new StrataError('BAD_SETTING', `${name}: placeholder {${key}} has no value (the setting is empty)`);
    return text(value);
  });
}
