/**
 * Command-line argument parsing. Every setting gets a flag generated from the schema:
 * `layerHeight` → `--layer-height 0.2`; booleans also take `--no-…`.
 */
import { StrataError } from '../errors.js';
import { SCHEMA, SETTING_KEYS, type SettingKey } from '../settings/schema.js';
import { checkKey, parseSettingText, suggest } from '../settings/resolve.js';

export function kebab(key: string): string {
  return key.replace(/[A-Z]/g, (c) => '-' + c.toLowerCase());
}

const FLAG_TO_KEY: ReadonlyMap<string, SettingKey> = new Map(SETTING_KEYS.map((k) => [kebab(k), k]));

export interface ParsedArgs {
  command: string;
  positional: string[];
  output?: string;
  printer?: string;
  filament?: string;
  configFiles: string[];
  /** Settings given on the command line, parsed by type (not yet validated). */
  settings: Record<string, unknown>;
  /** Other flags (command-specific), by name without dashes. */
  flags: Record<string, string | boolean>;
  help: boolean;
  quiet: boolean;
}

/** Command-specific flags that take a value. */
const VALUE_FLAGS = new Set(['layer', 'width', 'infill-param', 'infill-shader', 'infill-image', 'infill-density-shader', 'infill-density-layers', 'infill-image-pixel-size', 'infillers', 'scale']);
const BOOL_FLAGS = new Set(['json', 'travel']);

export function parseArgs(argv: readonly string[]): ParsedArgs {
  const out: ParsedArgs = { command: '', positional: [], configFiles: [], settings: {}, flags: {}, help: false, quiet: false };
  let i = 0;
  const need = (flag: string): string => {
    const v = argv[++i];
    if (v === undefined) throw new StrataError('BAD_SETTING', `${flag} needs a value`);
    return v;
  };
  for (; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--') {
      out.positional.push(...argv.slice(i + 1));
      break;
    }
    if (!a.startsWith('-') || a === '-') {
      if (!out.command) out.command = a;
      else out.positional.push(a);
      continue;
    }
    let name = a.replace(/^--?/, '');
    let inline: string | undefined;
    const eq = name.indexOf('=');
    if (eq >= 0) {
      inline = name.slice(eq + 1);
      name = name.slice(0, eq);
    }
    const value = (flag: string) => (inline !== undefined ? inline : need(flag));
    switch (name) {
      case 'h':
      case 'help':
        out.help = true;
        continue;
      case 'q':
      case 'quiet':
        out.quiet = true;
        continue;
      case 'o':
      case 'output':
        out.output = value(a);
        continue;
      case 'printer':
        out.printer = value(a);
        continue;
      case 'filament':
        out.filament = value(a);
        continue;
      case 'config':
        out.configFiles.push(value(a));
        continue;
      case 'set': {
        const kv = value(a);
        const k = kv.indexOf('=');
        if (k <= 0) throw new StrataError('BAD_SETTING', `--set expects key=value, got "${kv}"`);
        const key = checkKey(kv.slice(0, k), 'setting');
        out.settings[key] = parseSettingText(key, kv.slice(k + 1));
        continue;
      }
      case 'version':
      case 'v':
        out.flags.version = true;
        continue;
    }
    if (VALUE_FLAGS.has(name)) {
      const v = value(a);
      // repeated flags (--infill-param a=1 --infill-param b=2) accumulate, newline-separated
      const prev = out.flags[name];
      out.flags[name] = typeof prev === 'string' ? prev + '\n' + v : v;
      continue;
    }
    if (BOOL_FLAGS.has(name)) {
      out.flags[name] = true;
      continue;
    }
    const negated = name.startsWith('no-') ? name.slice(3) : null;
    const key = FLAG_TO_KEY.get(negated ?? name);
    if (key) {
      const def = SCHEMA[key];
      if (def.type === 'boolean') {
        out.settings[key] = negated ? false : inline !== undefined ? parseSettingText(key, inline) : true;
      } else {
        if (negated) throw new StrataError('BAD_SETTING', `--${name}: --no- applies only to on/off settings`);
        out.settings[key] = parseSettingText(key, value(a));
      }
      continue;
    }
    const known = [...FLAG_TO_KEY.keys(), 'output', 'printer', 'filament', 'config', 'set', 'help', 'quiet', ...VALUE_FLAGS, ...BOOL_FLAGS];
    const s = suggest(negated ?? name, known);
    throw new StrataError('UNKNOWN_SETTING', `unknown option ${a}${s ? ` (did you mean --${s}?)` : ''}; see strata --help`);
  }
  return out;
}
