/**
 * Every flag the CLI accepts does what it says, or is refused: no flag is taken and ignored.
 *
 * - Every setting (walked generically over the schema): each value tried is either refused with one
 *   line, or slices; at least one accepted value changes the G-code (every value, for a choice), or a
 *   value the setting limits by is refused by the slice itself (a model taller than the volume).
 *   `onlyWith` settings are set first (a list's first value), `needs` inputs given. Runtime settings
 *   (threads…) must leave the G-code byte-identical. Out-of-range values are refused.
 * - Every other flag (args.ts FLAGS): proven to act on each command it belongs to, and refused by
 *   every command it does not belong to.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, existsSync, writeFileSync, mkdirSync, copyFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { resolveConfig } from '#strata/settings/resolve.js';
import { SCHEMA, SETTING_KEYS, type SettingDef, type SettingKey, type SettingNeed } from '#strata/settings/schema.js';
import { COMMANDS, FLAGS, kebab, SLICING, type Command } from '#strata/cli/args.js';
import { main } from '#strata/cli/main.js';
import { blockWithHole, overhangPart, thinFeatures } from './test-model.js';
import { fakeHost, type Received } from '../send/test-fake-host.js';

const ROOT = fileURLToPath(new URL('../../../', import.meta.url));
const DIR = mkdtempSync(join(tmpdir(), 'strata-flags-'));
const MODEL = join(DIR, 'block.stl');
// 14 × 14 × 10.4 mm: 52 layers, taller than the smallest build volume a setting allows (10 mm)
writeFileSync(MODEL, blockWithHole(14, 10.4, 3.5));
const MODEL2 = join(DIR, 'block2.stl');
copyFileSync(MODEL, MODEL2);
const OFF_CENTRE = join(DIR, 'off-centre.stl');
writeFileSync(OFF_CENTRE, blockWithHole(14, 10.4, 3.5, 64, [40, 30]));
const TUBE = join(DIR, 'tube.stl');
writeFileSync(TUBE, blockWithHole(14, 10.4, 6, 8, [0, 0], true));
const THIN = join(DIR, 'thin.stl');
writeFileSync(THIN, thinFeatures());
const OVERHANGS = join(DIR, 'overhangs.stl');
writeFileSync(OVERHANGS, overhangPart());
// a 5 mm block through the model's corner (a modifier's or negative volume's mesh), and one over everything
const CORNER = join(DIR, 'corner.stl');
writeFileSync(CORNER, blockWithHole(5, 30, 1, 16, [5, 5]));
const EVERYTHING = join(DIR, 'everything.stl');
writeFileSync(EVERYTHING, blockWithHole(150, 60, 1, 16));

interface Run {
  code: number;
  out: string;
  err: string;
}

/** Run the CLI in this process, capturing what it prints. */
async function cli(...args: string[]): Promise<Run> {
  let out = '';
  let err = '';
  const code = await main(args, { out: (s) => (out += s), err: (s) => (err += s), errIsTTY: false });
  return { code, out, err };
}

let outputs = 0;
/** Slice with these extra arguments; the G-code, or the one-line error. */
async function slice(
  extra: readonly string[],
  models: readonly string[] = [MODEL],
): Promise<{ gcode?: string; error?: string }> {
  const file = join(DIR, `o${outputs++}.gcode`);
  const r = await cli('slice', ...models, '-o', file, '-q', '--threads', '1', ...extra);
  if (r.code !== 0) {
    assert.equal(r.code, 1, `${extra.join(' ')}: ${r.err}`);
    assert.match(r.err, /^strata: error: [^\n]+\n$/, `${extra.join(' ')}: one line`);
    assert.ok(!existsSync(file), 'nothing written');
    return { error: r.err };
  }
  return { gcode: readFileSync(file, 'utf8') };
}

/** How each kind of input a setting may need is given. */
const NEEDS = {
  'several-models': { args: [], models: [MODEL, MODEL2] },
  'off-centre-model': { args: ['--no-center'], models: [OFF_CENTRE] },
  'thin-walls': { args: [], models: [TUBE] },
  'thin-features': { args: [], models: [THIN] },
  overhangs: { args: [], models: [OVERHANGS] },
  // the slab's top, 14 mm up, and the ledge's, 3 mm up
  'several-tops': { args: [], models: [OVERHANGS] },
  'custom-infill': { args: ['--infill-pattern', 'checker'], models: [MODEL] },
  'custom-image-infill': { args: ['--infill-pattern', 'example-image'], models: [MODEL] },
  // the model is 10.4 mm tall
  'color-change': { args: ['--color-change-at', '5'], models: [MODEL] },
  pause: { args: ['--pause-at', '5'], models: [MODEL] },
  'template-placeholder': { args: ['--start-gcode', 'G28\nM117 {filamentType}'], models: [MODEL] },
  // a fan below its maximum, raised for layers shorter than a minute
  'fan-by-layer-time': { args: ['--fan-speed', '40', '--fan-below-layer-time', '60'], models: [MODEL] },
} as const satisfies Record<SettingNeed, { args: readonly string[]; models: readonly string[] }>;

const flagValue = (v: unknown) => (typeof v === 'string' ? v : JSON.stringify(v));

/** Arguments that put one setting at a value. */
function setting(key: string, value: unknown): string[] {
  const def: SettingDef = SCHEMA[key as SettingKey];
  if (def.type === 'boolean') return [value ? `--${kebab(key)}` : `--no-${kebab(key)}`];
  return [`--${kebab(key)}`, flagValue(value)];
}

const DEFAULTS = resolveConfig({}).settings;
const round = (v: number, integer: boolean) => (integer ? Math.round(v) : Math.round(v * 1000) / 1000);

/** Values to try for a setting, other than its current one, in the order they are tried. */
function candidates(key: SettingKey, def: SettingDef, current: unknown): unknown[] {
  switch (def.type) {
    case 'boolean':
      return [!current];
    case 'enum':
      return def.values.filter((v) => v !== current);
    case 'string':
      return [def.example ?? 'G28 ; home\nG1 Z5 F600'];
    case 'number':
    case 'integer': {
      const integer = def.type === 'integer';
      // a derived (empty) value: start from what it stands for ("Empty (null) = nozzleDiameter")
      const from = /Empty \(null\) = (\w+)/.exec(def.description)?.[1];
      const base =
        typeof current === 'number'
          ? current
          : from && typeof DEFAULTS[from as SettingKey] === 'number'
            ? (DEFAULTS[from as SettingKey] as number)
            : def.min + 1;
      const raw = [
        ...(base === 0 ? [2, 1] : []),
        base * 1.5,
        base * 0.5,
        base + (def.max - def.min) / 10,
        base === 0 ? 1 : base * 3,
        def.min,
        def.max,
        (def.min + def.max) / 2,
      ];
      const out: number[] = [];
      for (const v of raw) {
        const c = round(Math.min(def.max, Math.max(def.min, v)), integer);
        if (c !== current && !out.includes(c) && c >= def.min && c <= def.max) out.push(c);
      }
      return out;
    }
  }
  void key;
}

/** Values the schema refuses. */
function outOfRange(def: SettingDef): string[] {
  switch (def.type) {
    case 'number':
    case 'integer':
      return [
        String(def.max + Math.max(1, def.max)),
        String(def.min - Math.max(1, Math.abs(def.min))),
        'lots',
        ...(def.type === 'integer' ? [String(def.min + 0.5)] : []),
      ];
    case 'enum':
      return ['no-such-choice'];
    case 'boolean':
      return ['maybe'];
    case 'string':
      return ['x'.repeat(def.maxLength + 1)];
  }
}

/** Refusals that come from the setting doing its job (a limit), not from the value being invalid. */
const LIMIT_REFUSAL = /does not fit|leaves the bed|raise inflateBudget/;

const baselines = new Map<string, Promise<string>>();
function baseline(args: readonly string[], models: readonly string[]): Promise<string> {
  const k = JSON.stringify([args, models]);
  let b = baselines.get(k);
  if (!b) {
    b = slice(args, models).then((r) => {
      assert.ok(r.gcode !== undefined, `baseline ${args.join(' ')}: ${r.error}`);
      return r.gcode;
    });
    baselines.set(k, b);
  }
  return b;
}

test('every setting flag changes the G-code (or is refused by the slice it limits); runtime settings change nothing', {
  timeout: 600_000,
}, async () => {
  const problems: string[] = [];
  for (const key of SETTING_KEYS) {
    const def: SettingDef = SCHEMA[key];
    const context: string[] = [];
    for (const [k, v] of Object.entries(def.onlyWith ?? {}))
      context.push(
        ...setting(k, Array.isArray(v) ? v[0] : typeof v === 'object' ? (v as { example: number }).example : v),
      );
    const need = def.needs ? NEEDS[def.needs] : { args: [], models: [MODEL] };
    context.push(...need.args);
    const base = await baseline(context, need.models);
    const current = DEFAULTS[key];
    let changed = 0;
    let limited = 0;
    const same: unknown[] = [];
    for (const value of candidates(key, def, current)) {
      const r = await slice([...context, ...setting(key, value)], need.models);
      if (r.error !== undefined) {
        if (LIMIT_REFUSAL.test(r.error)) limited++;
        continue;
      }
      if (def.stage === 'runtime') {
        if (r.gcode !== base) problems.push(`${key}=${flagValue(value)} (runtime) changed the G-code`);
        changed++;
        break;
      }
      if (r.gcode !== base) {
        changed++;
        if (def.type !== 'enum') break;
      } else same.push(value);
    }
    // an 'auto' default stands for one of the other values, which may then give the same G-code
    if (def.type === 'enum' && current === 'auto' && same.length === 1) same.length = 0;
    if (def.type === 'enum' && same.length)
      problems.push(`${key}: ${same.map(flagValue).join(', ')} gave the same G-code as ${flagValue(current)}`);
    if (!changed && !limited)
      problems.push(
        `${key}: no value changed the G-code (tried ${candidates(key, def, current).map(flagValue).join(', ')})`,
      );
    for (const bad of outOfRange(def)) {
      const r = await cli('slice', MODEL, '-o', join(DIR, 'never.gcode'), '-q', `--${kebab(key)}`, bad);
      if (r.code !== 1 || !/^strata: error: [^\n]+\n$/.test(r.err))
        problems.push(`${key}=${bad.slice(0, 20)} was not refused (${r.code}: ${r.err.slice(0, 80)})`);
    }
  }
  assert.deepEqual(problems, []);
});

const INFILLERS = join(ROOT, 'infillers');
const SENT = join(DIR, 'sent.gcode');
writeFileSync(SENT, ';FLAVOR:Marlin\nG28\nG1 X10 Y10 E1\n');
const CONFIG = join(DIR, 'profile.json');
writeFileSync(CONFIG, JSON.stringify({ layerHeight: 0.25 }));
const EXTRA_INFILLERS = join(DIR, 'more-infillers');
mkdirSync(join(EXTRA_INFILLERS, 'my-stripes'), { recursive: true });
writeFileSync(
  join(EXTRA_INFILLERS, 'my-stripes', 'shader.glsl'),
  'vec4 cellular(vec3 world) { return vec4(mod(floor(world.x / 2.0), 2.0), 0.0, 0.0, 1.0); }\n',
);
const DENSITY = join(DIR, 'density.glsl');
writeFileSync(DENSITY, 'float density(vec3 world) { return world.z > 5.0 ? 40.0 : 10.0; }\n');

/** Arguments that make a command run at all (a model for those that need one). */
const BASE_ARGS: Record<Command, string[]> = {
  slice: ['slice', MODEL, '-q', '--threads', '1'],
  preview: ['preview', MODEL, '--threads', '1'],
  info: ['info', MODEL],
  infillers: ['infillers'],
  presets: ['presets'],
  settings: ['settings'],
  // nothing listens on port 9 (discard): the send fails after its flags are checked
  send: ['send', SENT, '--to', 'octoprint', 'http://127.0.0.1:9'],
};

/** What a print host received from `strata send SENT … URL` with these flags. */
async function sent(...flags: string[]): Promise<Received> {
  const host = await fakeHost(() => ({ status: 201, body: { effectivePrint: true, print_started: true } }));
  try {
    const r = await cli('send', SENT, ...flags, host.url);
    assert.equal(r.code, 0, r.err);
    return host.received.find((r) => r.method === 'POST')!;
  } finally {
    await host.close();
  }
}

/** What a run produced: standard output, or the file written with -o. */
async function produce(args: string[]): Promise<Run & { file?: string }> {
  const i = args.indexOf('-o');
  const r = await cli(...args);
  return i >= 0 && existsSync(args[i + 1]) ? { ...r, file: readFileSync(args[i + 1], 'utf8') } : r;
}

const fresh = (ext: string) => join(DIR, `f${outputs++}.${ext}`);

/**
 * For each flag and each command it applies to: a proof that it acts. Each returns nothing and
 * asserts; a flag in FLAGS without a proof fails the test.
 */
const PROOFS: Record<string, (command: Command) => Promise<void>> = {
  help: async (c) => {
    const r = await cli(...BASE_ARGS[c], '--help');
    assert.equal(r.code, 0);
    assert.match(r.out, /^strata .*\n\nUsage:/);
  },
  version: async (c) => {
    const r = await cli(...BASE_ARGS[c], '--version');
    assert.equal(r.code, 0);
    assert.match(r.out, /^strata \d+\.\d+\.\d+\n$/);
  },
  output: async (c) => {
    const f = fresh(c === 'slice' ? 'gcode' : 'svg');
    const r = await produce([...BASE_ARGS[c], '-o', f]);
    assert.equal(r.code, 0, r.err);
    assert.ok(r.file && r.file.length > 100 && !r.out, 'written to the file, not standard output');
  },
  quiet: async (c) => {
    const loud = await cli(...BASE_ARGS[c].filter((a) => a !== '-q'), '-o', fresh('x'));
    const quiet = await cli(...BASE_ARGS[c].filter((a) => a !== '-q'), '-o', fresh('x'), '-q');
    assert.ok(loud.err.length > 0, 'a summary without -q');
    assert.equal(quiet.err, '');
  },
  printer: (c) => differs(c, ['--printer', 'prusa-mk4']),
  filament: (c) => differs(c, ['--filament', 'petg']),
  config: (c) => differs(c, ['--config', CONFIG]),
  set: (c) => differs(c, ['--set', 'wallCount=4']),
  rotate: (c) => differs(c, ['--rotate', '30']).then(() => differs(c, ['--rotate', '90,0,0'])),
  'infill-shader': (c) => differs(c, ['--infill-shader', join(INFILLERS, 'checker', 'shader.glsl')]),
  'infill-image': (c) => differs(c, ['--infill-image', join(INFILLERS, 'example-image', 'cells.png')]),
  'infill-param': (c) =>
    differs(c, ['--infill-pattern', 'checker', '--infill-param', 'angle=30'], ['--infill-pattern', 'checker']),
  'infill-density-shader': (c) =>
    differs(c, ['--infill-pattern', 'checker', '--infill-density-shader', DENSITY], ['--infill-pattern', 'checker']),
  'infill-density-layers': (c) =>
    differs(c, ['--infill-pattern', 'checker', '--infill-density-layers', '10,40'], ['--infill-pattern', 'checker']),
  infillers: async (c) => {
    if (c === 'infillers') {
      const r = await cli('infillers', '--infillers', EXTRA_INFILLERS);
      assert.match(r.out, /my-stripes/);
      assert.doesNotMatch((await cli('infillers')).out, /my-stripes/);
      return;
    }
    const without = await cli(...BASE_ARGS[c], '--infill-pattern', 'my-stripes', '-o', fresh('x'));
    assert.equal(without.code, 1, 'an unknown infiller without --infillers');
    await differs(c, ['--infillers', EXTRA_INFILLERS, '--infill-pattern', 'my-stripes']);
  },
  object: (c) => differs(c, ['--object', 'infill-density=60,wall-count=3']),
  modifier: (c) => differs(c, ['--modifier', `${CORNER}:infill-density=90,wallCount=1`]),
  negative: (c) => differs(c, ['--negative', CORNER]),
  'support-blocker': (c) =>
    differs(c, [OVERHANGS, '--support-enabled', '--support-blocker', EVERYTHING], [OVERHANGS, '--support-enabled']),
  'support-enforcer': (c) => differs(c, [OVERHANGS, '--support-enforcer', EVERYTHING], [OVERHANGS]),
  'layer-range': (c) => differs(c, ['--layer-range', '2-6:infill-density=100']),
  'save-project': async () => {
    const project = fresh('3mf');
    const r = await cli(
      ...BASE_ARGS.slice,
      '--object',
      'infill-density=60',
      '--modifier',
      `${CORNER}:infill-density=90`,
      '--save-project',
      project,
      '-o',
      fresh('gcode'),
    );
    assert.equal(r.code, 0, r.err);
    // the project slices to the same G-code as the command line it was saved from
    const again = await produce(['slice', project, '-q', '--threads', '1', '-o', fresh('gcode')]);
    const first = await produce([
      ...BASE_ARGS.slice,
      '--object',
      'infill-density=60',
      '--modifier',
      `${CORNER}:infill-density=90`,
      '-o',
      fresh('gcode'),
    ]);
    assert.equal(again.code, 0, again.err);
    assert.ok(again.file && again.file === first.file, 'the saved project slices as the command line did');
  },
  layer: (c) => differs(c, ['--layer', '3']),
  width: (c) => differs(c, ['--width', '300']),
  travel: (c) => differs(c, ['--travel']),
  to: async () => {
    assert.equal((await sent('--to', 'octoprint')).path, '/api/files/local');
    assert.equal((await sent('--to', 'moonraker')).path, '/server/files/upload');
  },
  'api-key': async () => {
    assert.equal((await sent('--to', 'octoprint', '--api-key', 'K1')).headers['x-api-key'], 'K1');
    assert.equal((await sent('--to', 'octoprint')).headers['x-api-key'], undefined);
  },
  print: async () => {
    assert.equal((await sent('--to', 'moonraker', '--print')).fields.print, 'true');
    assert.equal((await sent('--to', 'moonraker')).fields.print, 'false');
  },
  json: async (c) => {
    const text = await cli(...BASE_ARGS[c]);
    const json = await cli(...BASE_ARGS[c], '--json');
    assert.equal(json.code, 0, json.err);
    assert.notEqual(json.out, text.out);
    assert.doesNotThrow(() => JSON.parse(json.out));
  },
};

const produced = new Map<string, Promise<Run & { file?: string }>>();
/** produce(), once per argument list (the output file aside). */
function produceOnce(args: string[]): Promise<Run & { file?: string }> {
  const key = JSON.stringify(args);
  let r = produced.get(key);
  if (!r) produced.set(key, (r = produce([...args, '-o', fresh('x')])));
  return r;
}

/** The command's output (G-code or SVG) with `extra` differs from that with `base`. */
async function differs(c: Command, extra: string[], base: string[] = []): Promise<void> {
  const a = await produceOnce([...BASE_ARGS[c], ...base]);
  const b = await produce([...BASE_ARGS[c], ...extra, '-o', fresh('x')]);
  assert.equal(a.code, 0, a.err);
  assert.equal(b.code, 0, `${extra.join(' ')}: ${b.err}`);
  assert.ok(b.file !== undefined && b.file !== a.file, `${c} ${extra.join(' ')} changes the output`);
}

/** A value for a flag on a command it does not apply to (it must be refused before the value matters). */
const SOME_VALUE: Record<string, string> = { layer: '1', width: '300', set: 'wallCount=3', rotate: '10' };

test('every other flag acts on each command it belongs to and is refused by the others', {
  timeout: 600_000,
}, async () => {
  for (const f of FLAGS) {
    const proof = PROOFS[f.name];
    assert.ok(proof, `--${f.name} has a proof in this test`);
    for (const c of COMMANDS) {
      if (f.commands.length === 0 || f.commands.includes(c)) {
        await proof(c);
        continue;
      }
      const args = [...BASE_ARGS[c], `--${f.name}`, ...(f.value ? [SOME_VALUE[f.name] ?? 'x'] : [])];
      const r = await cli(...args);
      assert.equal(r.code, 1, `${args.join(' ')} is refused`);
      assert.match(r.err, new RegExp(`^strata: error: --${f.name} does not apply to strata ${c} `));
    }
  }
  // settings belong to the slicing commands only
  for (const c of COMMANDS.filter((x) => !SLICING.includes(x))) {
    const r = await cli(...BASE_ARGS[c], '--layer-height', '0.3');
    assert.equal(r.code, 1);
    assert.match(r.err, /is a slicing setting/);
  }
  // --scale also takes one factor per axis
  await differs('slice', ['--scale', '1,1,0.5'], ['--scale', '1']);
});
