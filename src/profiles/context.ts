/**
 * What an import collects: the Strata settings a profile's keys map onto (each checked against the
 * schema), the keys read, and the values that map onto a setting but could not be taken (with why).
 */
import { StrataError } from '../errors.js';
import { validateValue } from '../settings/resolve.js';
import type { SettingKey, Settings } from '../settings/schema.js';

export interface RejectedValue {
  /** The profile's key(s). */
  key: string;
  value: string;
  reason: string;
}

export class ImportContext {
  readonly settings: Partial<Settings> = {};
  readonly used = new Set<string>();
  readonly rejected: RejectedValue[] = [];

  constructor(private readonly values: ReadonlyMap<string, string>) {}

  /** The raw value of a key, marking it read. */
  get(key: string): string | undefined {
    const v = this.values.get(key);
    if (v !== undefined) this.used.add(key);
    return v;
  }

  /** Whether the profile has a key (without marking it read). */
  has(key: string): boolean {
    return this.values.has(key);
  }

  /** The raw value of the first of `keys` the profile has. */
  getAny(...keys: string[]): { key: string; value: string } | undefined {
    for (const key of keys) {
      const value = this.get(key);
      if (value !== undefined) return { key, value };
    }
    return undefined;
  }

  /** Take `value` for `setting` when it fits the schema; otherwise record it as rejected. */
  set<K extends SettingKey>(
    setting: K,
    value: Settings[K] | undefined,
    fromKey: string,
    reasonIfUndefined?: string,
  ): void {
    if (value === undefined) {
      if (reasonIfUndefined) this.reject(fromKey, reasonIfUndefined);
      return;
    }
    try {
      (this.settings as Record<string, unknown>)[setting] = validateValue(setting, value, `${fromKey} →`);
    } catch (e) {
      if (!(e instanceof StrataError)) throw e;
      this.reject(
        fromKey,
        e.message.replace(/^.*? is not allowed: /, `${setting} ${JSON.stringify(value)} is not allowed: `),
      );
    }
  }

  reject(key: string, reason: string): void {
    this.rejected.push({ key, value: this.values.get(key.split(/[ +,]/)[0]!) ?? '', reason });
  }

  /** Keys of the profile that were not read. */
  unused(ignore: ReadonlySet<string>): string[] {
    return [...this.values.keys()].filter((k) => !this.used.has(k) && !ignore.has(k));
  }
}
