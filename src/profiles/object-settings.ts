/**
 * Settings a project file gives one object, volume or layer range (mesh/types.ts `SettingsSource`), mapped
 * onto Strata's keys with the same tables as whole profiles (slic3r-keys.ts, cura-keys.ts).
 *
 * An object's settings are a few overrides over the print's, and some of them only mean something next to
 * print settings: PrusaSlicer's `top_solid_layers` counts layers of the print's `layer_height`, a width in %
 * is of the print's nozzle. So the overrides are mapped over `context` (the project's print settings, same
 * slicer), and only the Strata settings that some override went into are kept.
 */
import { SCHEMA, type SettingKey, type Settings } from '../settings/schema.js';
import { validateValue } from '../settings/resolve.js';
import { StrataError } from '../errors.js';
import type { SettingsSource } from '../mesh/types.js';
import { ImportContext, type RejectedValue } from './context.js';
import { mapCuraKeys } from './cura-keys.js';
import { mapSlic3rKeys, SLIC3R_METADATA } from './slic3r-keys.js';

export interface ObjectSettings {
  /** Strata settings, each checked against the schema. */
  settings: Record<string, unknown>;
  /** Keys of the source that no Strata setting takes. */
  ignored: string[];
  /** Values that map onto a setting but could not be taken, and why. */
  rejected: RejectedValue[];
}

/** An import that remembers which of the source's keys each setting was computed from. */
class TracingContext extends ImportContext {
  readonly from = new Map<string, string>();
  override set<K extends SettingKey>(
    setting: K,
    value: Settings[K] | undefined,
    fromKey: string,
    reasonIfUndefined?: string,
  ): void {
    if (value !== undefined) this.from.set(setting, fromKey);
    super.set(setting, value, fromKey, reasonIfUndefined);
  }
}

/** A raw value as the text the slicer wrote: lists (Orca's JSON) joined with commas, G-code by its first entry. */
function asText(key: string, v: unknown): string | undefined {
  if (typeof v === 'string') return v;
  if (typeof v === 'number' || typeof v === 'boolean') return String(v);
  if (Array.isArray(v) && v.every((e) => typeof e === 'string' || typeof e === 'number')) {
    return /gcode$/.test(key) ? String(v[0] ?? '') : v.map(String).join(',');
  }
  return undefined;
}

/** Map `src` onto Strata settings; `context` (the print's settings, same format) is read but not returned. */
export function settingsFromSource(src: SettingsSource, context?: SettingsSource): ObjectSettings {
  if (src.format === 'strata') return strataSettings(src.values);
  const own = new Map<string, string>();
  const ignored: string[] = [];
  for (const [k, v] of Object.entries(src.values)) {
    const t = asText(k, v);
    if (t === undefined) ignored.push(k);
    else own.set(k, t);
  }
  const values = new Map<string, string>();
  if (context !== undefined && context.format === src.format) {
    for (const [k, v] of Object.entries(context.values)) {
      const t = asText(k, v);
      if (t !== undefined) values.set(k, t);
    }
  }
  for (const [k, v] of own) values.set(k, v);
  const c = new TracingContext(values);
  if (src.format === 'cura') mapCuraKeys(c);
  else mapSlic3rKeys(c, src.format);
  const settings: Record<string, unknown> = {};
  for (const [setting, value] of Object.entries(c.settings)) {
    const keys = (c.from.get(setting) ?? '').split(/[\s+,]+/);
    if (keys.some((k) => own.has(k))) settings[setting] = value;
  }
  const meta = src.format === 'cura' ? new Set<string>() : SLIC3R_METADATA;
  for (const k of own.keys()) if (!c.used.has(k) && !meta.has(k)) ignored.push(k);
  const rejected = c.rejected.filter((r) => r.key.split(/[\s+,]+/).some((k) => own.has(k)));
  return { settings, ignored, rejected };
}

function strataSettings(values: Readonly<Record<string, unknown>>): ObjectSettings {
  const out: ObjectSettings = { settings: {}, ignored: [], rejected: [] };
  for (const [k, v] of Object.entries(values)) {
    if (!Object.hasOwn(SCHEMA, k)) {
      out.ignored.push(k);
      continue;
    }
    try {
      out.settings[k] = validateValue(k as SettingKey, v, 'project setting');
    } catch (e) {
      if (!(e instanceof StrataError)) throw e;
      out.rejected.push({
        key: k,
        value: JSON.stringify(v) ?? String(v),
        reason: e.message.replace(/^.*? is not allowed: /, ''),
      });
    }
  }
  return out;
}
