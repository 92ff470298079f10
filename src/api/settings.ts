/**
 * Checking settings one at a time, as a settings editor does (the web page's panels): a key, a value, where a
 * setting may be given, and the config an object, layer range or modifier slices with. Each check throws the
 * `StrataError` the slicer would throw for the same settings, in the same words.
 */
import { ConfigTable } from '../settings/scoped.js';
import { checkKey, resolveConfig, validateValue, type Config } from '../settings/resolve.js';
import type { SettingKey, Settings, SliceOptions } from '../settings/schema.js';
import { checkScope, type ScopeUse } from '../settings/scope.js';

export type { ScopeUse } from '../settings/scope.js';

/**
 * The name of a setting, checked: returned as a `SettingKey`, or a `StrataError` (`UNKNOWN_SETTING`) that
 * suggests the closest name. `source` names the setting's kind in the message (`unknown option "…"`).
 */
export function checkSettingKey(key: string, source = 'option'): SettingKey {
  return checkKey(key, source);
}

/**
 * A value of one setting, checked against the schema (its type, range, allowed values or form): returned as
 * the setting takes it, or a `StrataError` (`BAD_SETTING`) that names what is allowed. `source` names the
 * setting's kind in the message (`option infillDensity = 120 is not allowed: …`).
 */
export function validateSetting<K extends SettingKey>(key: K, value: unknown, source = 'option'): Settings[K] {
  return validateValue(key, value, source) as Settings[K];
}

/**
 * Whether a setting may be given where `use` says (an object's own settings, a layer range's, a modifier's):
 * a `StrataError` (`BAD_SETTING`) if not, naming `where` (e.g. `object "cube"`), the setting, and where to
 * set it instead. `SETTING_SCOPE` says each setting's scope.
 */
export function checkSettingScope(key: SettingKey, use: ScopeUse, where: string): void {
  checkScope(key, use, where);
}

/** Settings given at one level of an object: its own (`use: 'object'`), a layer range's or a modifier's. */
export interface ScopedSettingsLayer {
  settings: Readonly<Record<string, unknown>> | undefined;
  use: ScopeUse;
  /** Names the level in messages, e.g. `object "cube"` or `modifier "Modifier 1" of "cube"`. */
  where: string;
}

/**
 * The config a part of the plate slices with: the print's `options`, then each layer's settings over them in
 * order (an object's own, then a layer range's or a modifier's in it), every key checked against its scope.
 * Throws the slicer's `StrataError` for settings that do not resolve, prefixed with the levels' `where`.
 */
export function resolveScopedConfig(options: SliceOptions, layers: readonly ScopedSettingsLayer[]): Config {
  const table = new ConfigTable(options, resolveConfig(options));
  return table.configs[table.resolve(layers)];
}
