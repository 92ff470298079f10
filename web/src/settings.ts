/**
 * The page's settings: printer and filament presets, the settings the user changed (overrides) and
 * the custom infill chosen. Kept in localStorage across reloads; exported and imported as the JSON
 * object `strata slice --config FILE.json` reads (printer, filament and setting keys; a shipped
 * custom infiller as its `infillPattern` name).
 */
import {
  PATTERN_IDS,
  SCHEMA,
  StrataError,
  checkSettingKey,
  resolveConfig,
  validateSetting,
  type Config,
  type CustomInfillSpec,
  type SettingKey,
  type SliceOptions,
} from 'strata-slicer';

/** A custom infiller: one shipped with Strata (by name) or a file the user loaded. */
export interface CustomChoice {
  source: 'shipped' | 'file';
  name: string;
  /** Loaded file's name (shader.glsl or cells.png). */
  fileName?: string;
  shader?: string;
  image?: Uint8Array;
  params: Record<string, number | boolean>;
}

const STORAGE_KEY = 'strata.settings.v1';
/** The settings with no preset named: the library's default printer and filament. */
const DEFAULTS = resolveConfig();
/** Largest loaded image kept in localStorage (bytes); bigger ones last until the page closes. */
const MAX_STORED_IMAGE = 512 * 1024;

export type Overrides = Partial<Record<SettingKey, unknown>>;

export interface SavedSettings {
  printer: string;
  filament: string;
  overrides: Overrides;
  custom: CustomChoice | null;
}

function toBase64(bytes: Uint8Array): string {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

function fromBase64(text: string): Uint8Array {
  const s = atob(text);
  const out = new Uint8Array(s.length);
  for (let i = 0; i < s.length; i++) out[i] = s.charCodeAt(i);
  return out;
}

export class SettingsStore {
  printer = DEFAULTS.printerId;
  filament = DEFAULTS.filamentId;
  overrides: Overrides = {};
  custom: CustomChoice | null = null;
  #listeners: Array<() => void> = [];

  onChange(fn: () => void): void {
    this.#listeners.push(fn);
  }

  changed(): void {
    this.save();
    for (const fn of this.#listeners) fn();
  }

  /** The options for the slicer: presets and the changed settings. */
  options(): SliceOptions {
    return { printer: this.printer, filament: this.filament, ...this.overrides } as SliceOptions;
  }

  /** The presets alone (what a setting goes back to when reset). */
  base(): Config {
    return resolveConfig({ printer: this.printer, filament: this.filament });
  }

  /** The resolved settings; throws a StrataError naming the problem when they do not fit together. */
  config(): Config {
    return resolveConfig(this.options());
  }

  /** Set one setting (validated; throws naming the allowed values); a value equal to the preset's is dropped. */
  set(key: SettingKey, value: unknown): void {
    const v = validateSetting(key, value, 'setting');
    if (v === this.base().settings[key]) delete this.overrides[key];
    else this.overrides[key] = v;
    this.changed();
  }

  reset(key: SettingKey): void {
    delete this.overrides[key];
    this.changed();
  }

  customSpec(): CustomInfillSpec | null {
    const c = this.custom;
    if (!c) return null;
    return { name: c.name, shader: c.shader, image: c.image, params: { ...c.params } };
  }

  /** The settings file: the same JSON object `strata slice --config` reads. */
  toJson(): Record<string, unknown> {
    const out: Record<string, unknown> = { printer: this.printer, filament: this.filament };
    for (const [k, v] of Object.entries(this.overrides)) out[k] = v;
    if (this.custom?.source === 'shipped') out.infillPattern = this.custom.name;
    return out;
  }

  /**
   * Take a settings file (replacing the current settings only if all of it is valid). `shipped`:
   * the shipped infillers' names, which `infillPattern` may name as the CLI allows.
   */
  fromJson(obj: unknown, shipped: readonly string[]): void {
    if (!obj || typeof obj !== 'object' || Array.isArray(obj))
      throw new StrataError('BAD_FILE', 'a settings file must hold a JSON object of settings');
    const { printer, filament, ...rest } = obj as Record<string, unknown>;
    if (printer !== undefined && typeof printer !== 'string')
      throw new StrataError('UNKNOWN_PRESET', 'printer must be a preset name');
    if (filament !== undefined && typeof filament !== 'string')
      throw new StrataError('UNKNOWN_PRESET', 'filament must be a preset name');
    const overrides: Overrides = {};
    let custom: CustomChoice | null = null;
    for (const [k, v] of Object.entries(rest)) {
      if (k === 'infillPattern' && typeof v === 'string' && !(PATTERN_IDS as readonly string[]).includes(v)) {
        if (!shipped.includes(v))
          throw new StrataError(
            'BAD_SETTING',
            `infillPattern "${v}" is neither a built-in pattern (${PATTERN_IDS.join(', ')}) nor a shipped infiller (${shipped.join(', ')})`,
          );
        custom = { source: 'shipped', name: v, params: {} };
        continue;
      }
      const key = checkSettingKey(k, 'setting');
      overrides[key] = validateSetting(key, v, 'setting');
    }
    const next = { printer: printer ?? this.printer, filament: filament ?? this.filament };
    // the presets and values must resolve together before anything is replaced
    const base = resolveConfig(next);
    resolveConfig({ ...next, ...overrides } as SliceOptions);
    for (const k of Object.keys(overrides) as SettingKey[]) if (overrides[k] === base.settings[k]) delete overrides[k];
    this.printer = base.printerId;
    this.filament = base.filamentId;
    this.overrides = overrides;
    this.custom = custom;
    this.changed();
  }

  save(): void {
    try {
      const c = this.custom;
      const custom =
        c && (!c.image || c.image.length <= MAX_STORED_IMAGE)
          ? { ...c, image: c.image ? toBase64(c.image) : undefined }
          : null;
      localStorage.setItem(
        STORAGE_KEY,
        JSON.stringify({ printer: this.printer, filament: this.filament, overrides: this.overrides, custom }),
      );
    } catch {
      // storage full or off: the settings last until the page closes
    }
  }

  /** The saved settings, where valid (a setting the schema no longer has is dropped). */
  load(): void {
    let saved: { printer?: unknown; filament?: unknown; overrides?: unknown; custom?: unknown };
    try {
      saved = JSON.parse(localStorage.getItem(STORAGE_KEY) ?? 'null') ?? {};
    } catch {
      return;
    }
    try {
      if (typeof saved.printer === 'string') this.printer = resolveConfig({ printer: saved.printer }).printerId;
      if (typeof saved.filament === 'string') this.filament = resolveConfig({ filament: saved.filament }).filamentId;
    } catch {
      // a preset that is gone: keep the defaults
    }
    if (saved.overrides && typeof saved.overrides === 'object') {
      for (const [k, v] of Object.entries(saved.overrides)) {
        if (!Object.hasOwn(SCHEMA, k)) continue;
        try {
          this.overrides[k as SettingKey] = validateSetting(k as SettingKey, v, 'setting');
        } catch {
          // no longer valid: dropped
        }
      }
    }
    const c = saved.custom as (Omit<CustomChoice, 'image'> & { image?: string }) | null | undefined;
    if (c && typeof c.name === 'string' && (c.source === 'shipped' || c.source === 'file')) {
      this.custom = {
        source: c.source,
        name: c.name,
        fileName: c.fileName,
        shader: typeof c.shader === 'string' ? c.shader : undefined,
        image: typeof c.image === 'string' ? fromBase64(c.image) : undefined,
        params: c.params && typeof c.params === 'object' ? { ...c.params } : {},
      };
      if (this.custom.source === 'file' && !this.custom.shader && !this.custom.image) this.custom = null;
    }
  }
}
