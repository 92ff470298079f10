/**
 * Settings with a scope, resolved once: the print's config, each object's (its own settings over the
 * print's), and each region's (an object's layer range and modifier over the object's). Configs that
 * resolve the same are one config (as PrusaSlicer shares its PrintRegions): every stage then reads the
 * config of the object or region in hand by its index, and the G-code of a plate whose objects set
 * nothing of their own is the same as before objects had settings.
 */
import { StrataError } from '../errors.js';
import { resolveConfig, checkKey, type Config } from './resolve.js';
import type { SliceOptions } from './schema.js';
import { checkScope, type ScopeUse } from './scope.js';

/** Settings given to an object, a layer range or a modifier: Strata keys, values checked on resolution. */
export type ScopedSettings = Readonly<Record<string, unknown>>;

/** The configs of one print, deduplicated, the print's own first. */
export class ConfigTable {
  readonly configs: Config[] = [];
  readonly #byKey = new Map<string, number>();
  readonly #base: SliceOptions;

  constructor(base: SliceOptions, print: Config) {
    this.#base = base;
    this.#add(print);
  }

  #add(cfg: Config): number {
    const key = JSON.stringify(cfg);
    let id = this.#byKey.get(key);
    if (id === undefined) {
      id = this.configs.length;
      this.configs.push(cfg);
      this.#byKey.set(key, id);
    }
    return id;
  }

  /**
   * The config of the print's options with these layers of settings over them (object, then layer range,
   * then modifier), each checked against its scope; its index in `configs`.
   */
  resolve(layers: ReadonlyArray<{ settings: ScopedSettings | undefined; use: ScopeUse; where: string }>): number {
    const merged: Record<string, unknown> = { ...this.#base };
    let any = false;
    for (const { settings, use, where } of layers) {
      if (!settings) continue;
      for (const [k, v] of Object.entries(settings)) {
        if (v === undefined) continue;
        const key = checkKey(k, `${where} setting`);
        checkScope(key, use, where);
        merged[key] = v;
        any = true;
      }
    }
    if (!any) return 0;
    try {
      return this.#add(resolveConfig(merged as SliceOptions));
    } catch (e) {
      if (e instanceof StrataError) {
        const where = layers
          .filter((l) => l.settings)
          .map((l) => l.where)
          .join(', ');
        throw new StrataError(e.code, `${where}: ${e.message}`);
      }
      throw e;
    }
  }
}
