/**
 * Command-line argument parsing. Every setting gets a flag generated from the schema:
 * `layerHeight` → `--layer-height 0.2`; booleans also take `--no-…`. The other flags are listed in
 * FLAGS with the commands they apply to; a flag given to a command it does not apply to is an error,
 * so no flag is ever accepted and ignored.
 */
import { StrataError } from '../errors.js';
import { SCHEMA, SETTING_KEYS, type SettingKey } from '../settings/schema.js';
import { checkKey, parseDecimal, parseSettingText, suggest } from '../settings/resolve.js';

export function kebab(key: string): string {
  return key.replace(/[A-Z]/g, (c) => '-' + c.toLowerCase());
}

export const COMMANDS = ['slice', 'info', 'preview', 'infillers', 'presets', 'settings', 'send'] as const;
export type Command = (typeof COMMANDS)[number];

/** Commands that slice, and so take every setting's flag. */
export const SLICING: readonly Command[] = ['slice', 'preview'];

export interface FlagDef {
  /** Long name without dashes. */
  name: string;
  short?: string;
  /** What the value is called in help ('' for on/off flags). */
  value: string;
  /** Given several times, the values accumulate (newline-separated). */
  repeat?: boolean;
  /** Belongs to the model file given before it (kept in `ParsedArgs.modelFlags`). */
  ofModel?: boolean;
  /** Commands the flag applies to (empty: any command, and none). */
  commands: readonly Command[];
  help: string;
}

/** Every flag that is not a setting. */
export const FLAGS: readonly FlagDef[] = [
  { name: 'help', short: 'h', value: '', commands: [], help: 'show this help' },
  { name: 'version', short: 'v', value: '', commands: [], help: 'show the version' },
  { name: 'output', short: 'o', value: 'FILE', commands: SLICING, help: 'where to write (- for standard output)' },
  { name: 'quiet', short: 'q', value: '', commands: SLICING, help: 'no progress bar, summary or warnings' },
  { name: 'printer', value: 'NAME', commands: SLICING, help: 'printer preset' },
  { name: 'filament', value: 'NAME', commands: SLICING, help: 'filament preset' },
  { name: 'config', value: 'FILE.json', repeat: true, commands: SLICING, help: 'settings from a JSON object' },
  { name: 'set', value: 'KEY=VALUE', repeat: true, commands: SLICING, help: 'any setting by its key' },
  {
    name: 'rotate',
    value: 'Z|X,Y,Z',
    commands: SLICING,
    help: 'turn each model (degrees): about Z, or about X, Y and Z',
  },
  { name: 'infill-shader', value: 'FILE', commands: SLICING, help: 'custom infill from a GLSL cellular() shader' },
  { name: 'infill-image', value: 'FILE', commands: SLICING, help: 'custom infill from a cells.png image' },
  { name: 'infill-param', value: 'NAME=VALUE', repeat: true, commands: SLICING, help: "a shader's ui_ parameter" },
  { name: 'infill-density-shader', value: 'FILE', commands: SLICING, help: 'density() from a shader' },
  { name: 'infill-density-layers', value: 'A,B,…', commands: SLICING, help: 'density() per layer' },
  {
    name: 'infillers',
    value: 'DIR',
    repeat: true,
    commands: [...SLICING, 'infillers'],
    help: 'another infiller folder',
  },
  {
    name: 'object',
    value: 'KEY=VALUE,…',
    repeat: true,
    ofModel: true,
    commands: SLICING,
    help: 'settings of the model file before it only (object- and region-scoped ones)',
  },
  {
    name: 'modifier',
    value: 'FILE[:KEY=VALUE,…]',
    repeat: true,
    ofModel: true,
    commands: SLICING,
    help: 'a mesh that changes the settings of the model before it inside it (not printed)',
  },
  {
    name: 'negative',
    value: 'FILE',
    repeat: true,
    ofModel: true,
    commands: SLICING,
    help: 'a mesh cut out of the model before it',
  },
  {
    name: 'support-blocker',
    value: 'FILE',
    repeat: true,
    ofModel: true,
    commands: SLICING,
    help: 'no support for the model before it inside this mesh',
  },
  {
    name: 'support-enforcer',
    value: 'FILE',
    repeat: true,
    ofModel: true,
    commands: SLICING,
    help: 'support under every overhang of the model before it inside this mesh',
  },
  {
    name: 'layer-range',
    value: 'FROM-TO:KEY=VALUE,…',
    repeat: true,
    ofModel: true,
    commands: SLICING,
    help: 'settings of the model before it from Z FROM to TO mm',
  },
  {
    name: 'save-project',
    value: 'FILE.3mf',
    commands: ['slice'],
    help: 'also write the plate as a project 3MF (objects, volumes, settings)',
  },
  { name: 'layer', value: 'N', commands: ['preview'], help: 'the layer to draw' },
  { name: 'width', value: 'PX', commands: ['preview'], help: 'picture width' },
  { name: 'travel', value: '', commands: ['preview'], help: 'draw travels too' },
  { name: 'json', value: '', commands: ['info', 'presets', 'settings'], help: 'print JSON' },
  {
    name: 'to',
    value: 'octoprint|moonraker',
    commands: ['send'],
    help: 'the print host: its software (then its address)',
  },
  { name: 'api-key', value: 'KEY', commands: ['send'], help: "the host's API key (or STRATA_API_KEY)" },
  { name: 'print', value: '', commands: ['send'], help: 'start printing the file once it is uploaded' },
];

const BY_NAME: ReadonlyMap<string, FlagDef> = new Map(
  FLAGS.flatMap((f) => [[f.name, f] as const, ...(f.short ? [[f.short, f] as const] : [])]),
);
/**
 * Other names a setting's flag answers to, as other slicers call the same thing (`--no-` works for them too
 * when the setting is on/off): PrusaSlicer's "vase mode", Cura's "spiralize".
 */
export const FLAG_ALIASES: Readonly<Record<string, SettingKey>> = {
  'vase-mode': 'spiralVase',
  spiralize: 'spiralVase',
};
export const FLAG_TO_KEY: ReadonlyMap<string, SettingKey> = new Map([
  ...SETTING_KEYS.map((k) => [kebab(k), k] as const),
  ...Object.entries(FLAG_ALIASES),
]);

/** Every flag the CLI accepts, with dashes: the FLAGS table and every setting's (with --no- for on/off ones). */
export function allFlags(): string[] {
  const out = FLAGS.map((f) => `--${f.name}`);
  for (const k of SETTING_KEYS) {
    out.push(`--${kebab(k)}`);
    if (SCHEMA[k].type === 'boolean') out.push(`--no-${kebab(k)}`);
  }
  for (const [alias, k] of Object.entries(FLAG_ALIASES)) {
    out.push(`--${alias}`);
    if (SCHEMA[k].type === 'boolean') out.push(`--no-${alias}`);
  }
  return out;
}

export interface ParsedArgs {
  command: string;
  positional: string[];
  /** Settings given on the command line, parsed by type (not yet validated). */
  settings: Record<string, unknown>;
  /** FLAGS given, by long name: true for on/off flags, the value (repeats joined by newlines) otherwise. */
  flags: Record<string, string | true>;
  /** Setting flags as given (for messages about the command). */
  settingFlags: string[];
  /** Flags that belong to one model file: the index of the file in `positional`, the flag's long name and value. */
  modelFlags: Array<{ model: number; flag: string; value: string }>;
}

/** A list of numbers "a,b,c" (exactly `n` of them when n > 1), or one number. */
function numbers(flag: string, text: string, n: number): number[] {
  const parts = text.split(',').map(parseDecimal);
  if ((parts.length !== 1 && parts.length !== n) || parts.some((v) => !Number.isFinite(v)) || text.trim() === '') {
    throw new StrataError('BAD_SETTING', `${flag} expects a number or ${n} numbers separated by commas, got "${text}"`);
  }
  return parts;
}

export function parseArgs(argv: readonly string[]): ParsedArgs {
  const out: ParsedArgs = { command: '', positional: [], settings: {}, flags: {}, settingFlags: [], modelFlags: [] };
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
    const def = BY_NAME.get(name);
    if (def && (def.short !== name || !a.startsWith('--'))) {
      if (def.value === '') {
        if (inline !== undefined) throw new StrataError('BAD_SETTING', `--${def.name} takes no value`);
        out.flags[def.name] = true;
        continue;
      }
      const v = value(a);
      // (before any model file: -1, refused by the slicing commands, which read these)
      if (def.ofModel) out.modelFlags.push({ model: out.positional.length - 1, flag: def.name, value: v });
      if (def.name === 'set') {
        const k = v.indexOf('=');
        if (k <= 0) throw new StrataError('BAD_SETTING', `--set expects key=value, got "${v}"`);
        const key = checkKey(v.slice(0, k), 'setting');
        out.settings[key] = parseSettingText(key, v.slice(k + 1));
        out.settingFlags.push(a);
      } else if (def.name === 'rotate') {
        const r = numbers(a, v, 3);
        const [x, y, z] = r.length === 1 ? [0, 0, r[0]] : r;
        Object.assign(out.settings, { rotateX: x, rotateY: y, rotateZ: z });
        out.settingFlags.push(a);
      }
      const prev = out.flags[def.name];
      out.flags[def.name] = def.repeat && typeof prev === 'string' ? prev + '\n' + v : v;
      continue;
    }
    const negated = name.startsWith('no-') ? name.slice(3) : null;
    const key = FLAG_TO_KEY.get(negated ?? name);
    if (key) {
      const d = SCHEMA[key];
      out.settingFlags.push(a);
      if (d.type === 'boolean') {
        out.settings[key] = negated ? false : inline !== undefined ? parseSettingText(key, inline) : true;
      } else if (negated) {
        throw new StrataError('BAD_SETTING', `--${name}: --no- applies only to on/off settings`);
      } else if (key === 'scale' && (inline ?? argv[i + 1] ?? '').includes(',')) {
        // --scale X,Y,Z scales each axis
        const [x, y, z] = numbers(a, value(a), 3);
        Object.assign(out.settings, { scaleX: x, scaleY: y, scaleZ: z });
      } else {
        out.settings[key] = parseSettingText(key, value(a));
      }
      continue;
    }
    const known = [...FLAG_TO_KEY.keys(), ...FLAGS.map((f) => f.name)];
    const s = suggest(negated ?? name, known);
    throw new StrataError(
      'UNKNOWN_SETTING',
      `unknown option ${a}${s ? ` (did you mean --${s}?)` : ''}; see strata --help`,
    );
  }
  return out;
}

/** Refuse flags that do not apply to the command (they would be silently ignored otherwise). */
export function checkFlagsFor(args: ParsedArgs): void {
  const command = args.command as Command;
  for (const name of Object.keys(args.flags)) {
    const def = BY_NAME.get(name)!;
    if (def.commands.length === 0 || def.commands.includes(command)) continue;
    throw new StrataError(
      'BAD_SETTING',
      `--${name} does not apply to strata ${args.command} (it is for strata ${def.commands.join(', ')})`,
    );
  }
  if (args.settingFlags.length > 0 && !SLICING.includes(command)) {
    throw new StrataError(
      'BAD_SETTING',
      `${args.settingFlags[0]} is a slicing setting; strata ${args.command} does not take settings (strata slice and preview do)`,
    );
  }
}
