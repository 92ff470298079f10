/** `strata infillers`, `strata presets` and `strata settings`: what is available, as text or JSON. */
import { listPresets } from '../settings/presets/index.js';
import { SCHEMA, SETTING_KEYS, type OnlyWithValue, type SettingDef } from '../settings/schema.js';
import { SETTING_SCOPE } from '../settings/scope.js';
import { listInfillers } from '../shader/node-folder.js';
import { kebab, type ParsedArgs } from './args.js';
import { infillerDirs } from './inputs.js';

type Write = (s: string) => void;

export async function cmdInfillers(args: ParsedArgs, write: Write): Promise<void> {
  const dirs = args.positional.length ? args.positional : infillerDirs(args);
  for (const dir of dirs) {
    const list = await listInfillers(dir);
    if (!list.length) continue;
    write(`${dir}:\n`);
    for (const inf of list) {
      if (inf.error) {
        write(`  ${inf.name}  (cannot load: ${inf.error})\n`);
        continue;
      }
      write(`  ${inf.name}  ${inf.kind}${inf.numPasses && inf.numPasses > 1 ? `, ${inf.numPasses} passes` : ''}\n`);
      for (const p of inf.params ?? [])
        write(`      --infill-param ${p.name}=${p.default}  (${p.type})${p.tooltip ? '  ' + p.tooltip : ''}\n`);
    }
  }
}

export function cmdPresets(args: ParsedArgs, write: Write): void {
  const { printers, filaments } = listPresets();
  if (args.flags.json === true) {
    write(JSON.stringify({ printers, filaments }, null, 2) + '\n');
    return;
  }
  const w = Math.max(...printers.map((p) => p.id.length), ...filaments.map((f) => f.id.length));
  write('Printers:\n');
  for (const p of printers) write(`  ${p.id.padEnd(w)}  ${p.name}\n`);
  write('Filaments:\n');
  for (const f of filaments) write(`  ${f.id.padEnd(w)}  ${f.name}\n`);
}

/** One condition of `onlyWith` as the settings list prints it: `key=value`, `key=a|b`, `key>0`. */
function onlyWithText(key: string, v: OnlyWithValue): string {
  if (Array.isArray(v)) return `${key}=${v.join('|')}`;
  if (typeof v === 'object') return `${key}>${(v as { above: number }).above}`;
  return `${key}=${String(v)}`;
}

export function cmdSettings(args: ParsedArgs, write: Write): void {
  if (args.flags.json === true) {
    write(
      JSON.stringify(
        Object.fromEntries(
          SETTING_KEYS.map((k) => [k, { flag: `--${kebab(k)}`, scope: SETTING_SCOPE[k], ...SCHEMA[k] }]),
        ),
        null,
        2,
      ) + '\n',
    );
    return;
  }
  for (const key of SETTING_KEYS) {
    const d: SettingDef = SCHEMA[key];
    const range =
      d.type === 'number' || d.type === 'integer'
        ? ` [${d.min}–${d.max}]`
        : d.type === 'enum'
          ? ` {${d.values.join('|')}}`
          : d.type === 'boolean'
            ? ' (--no-' + kebab(key) + ')'
            : '';
    const def = d.type === 'string' ? '(template)' : JSON.stringify(d.default);
    const only = d.onlyWith
      ? `  (only with ${Object.entries(d.onlyWith)
          .map(([k, v]) => onlyWithText(kebab(k), v))
          .join(', ')})`
      : '';
    write(
      `--${kebab(key)} ${d.unit ? `(${d.unit}) ` : ''}default ${def}${range}${only}  [${SETTING_SCOPE[key]}]\n    ${d.description}\n`,
    );
  }
}
