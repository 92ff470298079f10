/**
 * Seeded fuzzing of the whole slicer: mutated STL, OBJ, 3MF, PNG and GLSL inputs (from the shared
 * models and the shipped infillers), random settings in and out of range, and the command line's
 * inputs as devices and streams (endless, empty, random, a folder, a FIFO, standard input in random
 * pieces). Every outcome must be
 * valid G-code or one StrataError with a one-line message: never another exception, a hang or
 * unbounded memory. The case counts are fixed (so CI time is bounded and a failure replays with the
 * same seed); STRATA_FUZZ_SEED picks another seed and STRATA_FUZZ_SCALE multiplies the counts.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { strToU8, zipSync } from 'fflate';
import { Slicer } from '#strata/api/slicer.js';
import { StrataError } from '#strata/errors.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import type { resolveConfig } from '#strata/settings/resolve.js';
import { SCHEMA, SETTING_KEYS, type SettingDef, type SettingKey, type SliceOptions } from '#strata/settings/schema.js';
import { blockWithHole } from '../cli/test-model.js';
import { modelPath, skipWithoutModels } from './models-dir.js';

const SEED = Number(process.env.STRATA_FUZZ_SEED ?? 9001);
const SCALE = Math.max(0.1, Number(process.env.STRATA_FUZZ_SCALE ?? 1));
const count = (n: number) => Math.max(1, Math.round(n * SCALE));
const skip = skipWithoutModels();
const ROOT = fileURLToPath(new URL('../../../', import.meta.url));

/** A small seeded generator (xorshift32): the same seed gives the same cases. */
class Rng {
  #s: number;
  constructor(seed: number) {
    this.#s = seed >>> 0 || 1;
  }
  next(): number {
    let x = this.#s;
    x ^= x << 13;
    x >>>= 0;
    x ^= x >>> 17;
    x ^= x << 5;
    return (this.#s = x >>> 0);
  }
  int(n: number): number {
    return this.next() % Math.max(1, n);
  }
  float(): number {
    return this.next() / 4294967296;
  }
  pick<T>(a: readonly T[]): T {
    return a[this.int(a.length)];
  }
  chance(p: number): boolean {
    return this.float() < p;
  }
}

// ── mutations ────────────────────────────────────────────────────────────────

function mutateBytes(r: Rng, src: Uint8Array): Uint8Array {
  const b = src.slice();
  switch (r.int(5)) {
    case 0: {
      for (let k = 1 + r.int(8); k > 0; k--) b[r.int(b.length)] = r.int(256);
      return b;
    }
    case 1:
      return b.subarray(0, r.int(b.length));
    case 2: {
      // copy a run over another place
      const from = r.int(b.length),
        to = r.int(b.length),
        n = r.int(Math.min(64, b.length - Math.max(from, to)));
      b.copyWithin(to, from, from + n);
      return b;
    }
    case 3: {
      const at = r.int(b.length);
      const ins = Uint8Array.from({ length: 1 + r.int(32) }, () => r.int(256));
      const out = new Uint8Array(b.length + ins.length);
      out.set(b.subarray(0, at));
      out.set(ins, at);
      out.set(b.subarray(at), at + ins.length);
      return out;
    }
    default: {
      const at = r.int(b.length);
      b.fill(r.chance(0.5) ? 0 : 0xff, at, at + 1 + r.int(16));
      return b;
    }
  }
}

const ODD_NUMBERS = [
  '0',
  '-0',
  '1e30',
  '-1e30',
  'NaN',
  'inf',
  '1e-30',
  '99999999999',
  '-3.5',
  '4294967296',
  '0x10',
  '',
  '1.5.5',
];

function mutateText(r: Rng, src: string): string {
  const lines = src.split('\n');
  const i = r.int(lines.length);
  switch (r.int(6)) {
    case 0: {
      // a number becomes an odd one
      let seen = 0;
      const target = r.int(40);
      return src.replace(/-?\d+(\.\d+)?(e-?\d+)?/g, (m) => (seen++ === target ? r.pick(ODD_NUMBERS) : m));
    }
    case 1:
      lines.splice(i, 1);
      return lines.join('\n');
    case 2:
      lines.splice(i, 0, lines[r.int(lines.length)]);
      return lines.join('\n');
    case 3: {
      const j = r.int(lines.length);
      [lines[i], lines[j]] = [lines[j], lines[i]];
      return lines.join('\n');
    }
    case 4:
      return src.slice(0, r.int(src.length));
    default: {
      const at = r.int(src.length);
      return (
        src.slice(0, at) +
        r.pick(['{', '}', '(', ';', '#', '\0', 'for(;;){', '/*', '"', '<', '>', '&', '\uFFFD']) +
        src.slice(at)
      );
    }
  }
}

// ── inputs ───────────────────────────────────────────────────────────────────

/** Triangles of a binary STL as [x,y,z]×3 lists. */
function stlTriangles(b: Uint8Array): number[][] {
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  const n = dv.getUint32(80, true);
  const out: number[][] = [];
  for (let t = 0; t < n; t++)
    out.push(Array.from({ length: 9 }, (_, k) => dv.getFloat32(84 + 50 * t + 12 + 4 * k, true)));
  return out;
}

function objText(tris: number[][]): string {
  const v = tris
    .map((t) => `v ${t[0]} ${t[1]} ${t[2]}\nv ${t[3]} ${t[4]} ${t[5]}\nv ${t[6]} ${t[7]} ${t[8]}`)
    .join('\n');
  const f = tris.map((_, i) => `f ${3 * i + 1} ${3 * i + 2} ${3 * i + 3}`).join('\n');
  return `o cube\n${v}\n${f}\n`;
}

function modelXml(tris: number[][]): string {
  const v = tris
    .map(
      (t) =>
        `<vertex x="${t[0]}" y="${t[1]}" z="${t[2]}"/><vertex x="${t[3]}" y="${t[4]}" z="${t[5]}"/><vertex x="${t[6]}" y="${t[7]}" z="${t[8]}"/>`,
    )
    .join('\n');
  const f = tris.map((_, i) => `<triangle v1="${3 * i}" v2="${3 * i + 1}" v3="${3 * i + 2}"/>`).join('\n');
  return `<?xml version="1.0"?>\n<model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"><resources>\n<object id="1" name="cube"><mesh><vertices>\n${v}\n</vertices><triangles>\n${f}\n</triangles></mesh></object>\n</resources><build><item objectid="1" transform="1 0 0 0 1 0 0 0 1 5 5 0"/></build></model>\n`;
}

// ── outcomes ─────────────────────────────────────────────────────────────────

const WORD = /^([GMT]\d+(\.\d+)?|[A-Z][A-Z0-9_]+)$/;
const PARAM = /^([A-Z][-+]?(\d+(\.\d*)?|\.\d+)|[A-Z]+=[-+\w.{}]+|"[^"]*"|[A-Z])$/;

/**
 * Valid G-code for these settings: well-formed lines, finite numbers, the layers announced, E balanced,
 * and the print inside the bed (the start and end templates may move where their author chose).
 */
function checkGcode(gcode: string, cfg: ReturnType<typeof resolveConfig>, layers: number, what: string): void {
  const lines = gcode.split('\n');
  const x0 = cfg.originAtCenter ? -cfg.buildPlateWidth / 2 : 0;
  const y0 = cfg.originAtCenter ? -cfg.buildPlateLength / 2 : 0;
  const firstLayer = lines.findIndex((l) => l.startsWith(';LAYER:'));
  let lastLayerLine = lines.length - 1;
  while (lastLayerLine > 0 && !lines[lastLayerLine].startsWith(';TIME_ELAPSED:')) lastLayerLine--;
  for (let n = 0; n < lines.length; n++) {
    const code = lines[n].split(';')[0].trim();
    if (!code) continue;
    const [word, ...params] = code.split(/\s+/);
    assert.match(word, WORD, `${what}: line ${n + 1} "${lines[n]}"`);
    // M117 shows a message (free text); Klipper commands take KEY=VALUE of their own forms
    if (word === 'M117' || !/^[GMT]\d/.test(word)) continue;
    for (const p of params) assert.match(p, PARAM, `${what}: line ${n + 1} "${lines[n]}"`);
    if (word === 'G0' || word === 'G1') {
      const inLayers = n > firstLayer && n < lastLayerLine;
      for (const p of params) {
        const v = Number(p.slice(1));
        assert.ok(Number.isFinite(v), `${what}: line ${n + 1} "${lines[n]}"`);
        if (!inLayers) continue;
        if (p[0] === 'X')
          assert.ok(
            v >= x0 - 1e-3 && v <= x0 + cfg.buildPlateWidth + 1e-3,
            `${what}: X off the bed at line ${n + 1}: ${lines[n]}`,
          );
        if (p[0] === 'Y')
          assert.ok(
            v >= y0 - 1e-3 && v <= y0 + cfg.buildPlateLength + 1e-3,
            `${what}: Y off the bed at line ${n + 1}: ${lines[n]}`,
          );
      }
    }
  }
  assert.ok(gcode.includes(`;LAYER_COUNT:${layers}\n`), `${what}: layer count`);
  const parsed = parseGcode(gcode);
  assert.equal(parsed.layers.filter((l) => l.extrusions.count > 0).length > 0, true, `${what}: something is extruded`);
  // an extra prime after each retraction pushes more than was pulled back, on purpose
  if (cfg.retractionExtraPrime === 0) assert.equal(parsed.balance.unbalanced, 0, `${what}: retractions balanced`);
}

let maxRssSeen = 0;
const outcomes = { gcode: 0, refused: 0 };

/** One case: valid G-code, or one StrataError. */
async function attempt(
  what: string,
  options: SliceOptions & { customInfill?: unknown },
  input: unknown,
): Promise<void> {
  let slicer: Slicer;
  try {
    slicer = new Slicer(options as SliceOptions);
    const { gcode, stats } = await slicer.slice(input);
    checkGcode(gcode, slicer.config, stats.layers, what);
    outcomes.gcode++;
  } catch (e) {
    if (e instanceof assert.AssertionError) throw e;
    assert.ok(
      e instanceof StrataError,
      `${what}: threw ${e instanceof Error ? `${e.name}: ${e.message}\n${e.stack}` : String(e)}`,
    );
    assert.ok(e.message.length > 0 && !e.message.includes('\n'), `${what}: one line: ${e.message}`);
    outcomes.refused++;
  }
  maxRssSeen = Math.max(maxRssSeen, process.memoryUsage().rss);
}

/** Settings that keep every case small (a mutated vertex far away is refused, not sliced for minutes). */
const SMALL: SliceOptions = {
  threads: 1,
  layerHeight: 0.3,
  buildVolumeHeight: 40,
  adhesionType: 'none',
  infillDensity: 15,
};

test('mutated STL, OBJ and 3MF models: valid G-code or one StrataError', { skip, timeout: 600_000 }, async () => {
  const r = new Rng(SEED);
  const cube = new Uint8Array(readFileSync(modelPath('CalibrationCube.stl')));
  const ascii = readFileSync(modelPath('HollowCalibrationCube.stl'), 'utf8');
  const tris = stlTriangles(cube);
  const obj = objText(tris);
  const xml = modelXml(tris);
  for (let i = 0; i < count(30); i++) await attempt(`binary STL #${i} (seed ${SEED})`, SMALL, mutateBytes(r, cube));
  for (let i = 0; i < count(12); i++) await attempt(`ASCII STL #${i}`, SMALL, strToU8(mutateText(r, ascii)));
  for (let i = 0; i < count(12); i++) await attempt(`OBJ #${i}`, SMALL, strToU8(mutateText(r, obj)));
  for (let i = 0; i < count(10); i++)
    await attempt(`3MF XML #${i}`, SMALL, zipSync({ '3D/3dmodel.model': strToU8(mutateText(r, xml)) }));
  const zipped = zipSync({ '3D/3dmodel.model': strToU8(xml) });
  for (let i = 0; i < count(10); i++) await attempt(`3MF bytes #${i}`, SMALL, mutateBytes(r, zipped));
  assert.ok(outcomes.gcode > 0 && outcomes.refused > 0, `both outcomes seen: ${JSON.stringify(outcomes)}`);
});

test('mutated infill images and shaders: a working infiller or one StrataError', {
  skip,
  timeout: 600_000,
}, async () => {
  const r = new Rng(SEED + 1);
  const png = new Uint8Array(readFileSync(ROOT + 'infillers/example-image/cells.png'));
  const shaders = ['checker', 'hexagon-grid', 'tpms-gyroid', 'tpms-schwarz-p', 'voronoi-foam'].map((n) =>
    readFileSync(`${ROOT}infillers/${n}/shader.glsl`, 'utf8'),
  );
  const pin = blockWithHole(6, 2.4, 1.5, 16);
  const opts = { ...SMALL, layerHeight: 0.3 };
  let sliced = 0;
  const tryInfill = async (what: string, spec: { name: string; image?: Uint8Array; shader?: string }) => {
    let ok = true;
    try {
      new Slicer({ ...opts, customInfill: spec } as SliceOptions);
    } catch (e) {
      ok = false;
      assert.ok(
        e instanceof StrataError && !e.message.includes('\n'),
        `${what}: ${e instanceof Error ? e.stack : String(e)}`,
      );
    }
    // slice a few that load, on a small part
    if (ok && sliced < count(6)) {
      sliced++;
      await attempt(what, { ...opts, customInfill: spec }, pin);
    }
  };
  for (let i = 0; i < count(40); i++) await tryInfill(`cells.png #${i}`, { name: 'fuzz', image: mutateBytes(r, png) });
  for (let i = 0; i < count(40); i++)
    await tryInfill(`shader #${i}`, { name: 'fuzz', shader: mutateText(r, r.pick(shaders)) });
  assert.ok(sliced > 0);
});

/** A random value for a setting: in its range, or (with `outside`) just out of it or of the wrong type. */
function randomValue(r: Rng, def: SettingDef, outside: boolean): unknown {
  switch (def.type) {
    case 'number':
    case 'integer': {
      if (outside)
        return r.pick(
          [def.max + 1 + r.float() * def.max, def.min - 1 - r.float() * 10, NaN, Infinity, '12', null].filter(
            (v) => v !== null || !def.nullable,
          ),
        );
      if (def.nullable && r.chance(0.3)) return null;
      const v = def.min + (def.max - def.min) * r.float() ** 3;
      return def.type === 'integer' ? Math.round(v) : v;
    }
    case 'boolean':
      return outside ? r.pick(['yes', 1, null]) : r.chance(0.5);
    case 'enum':
      return outside ? 'no-such-choice' : r.pick(def.values);
    case 'string':
      return outside
        ? 'x'.repeat(def.maxLength + 1)
        : r.pick(['G28', 'G28\nG1 Z5 F600', '; nothing', 'M117 {layerCount} layers']);
  }
}

test('random settings in and out of range: valid G-code or one StrataError', { skip, timeout: 600_000 }, async () => {
  const r = new Rng(SEED + 2);
  const part = blockWithHole(8, 3, 2, 24);
  // the settings that size the work stay modest, so a case takes well under a second
  const bounded = new Set<SettingKey>([
    'threads',
    'layerHeight',
    'firstLayerHeight',
    'buildVolumeHeight',
    'inflateBudget',
  ]);
  const keys = SETTING_KEYS.filter((k) => !bounded.has(k));
  for (let i = 0; i < count(40); i++) {
    const outside = r.chance(0.3);
    const opts: Record<string, unknown> = { threads: 1, layerHeight: 0.2 + 0.1 * r.int(3) };
    for (let k = 1 + r.int(6); k > 0; k--) {
      const key = r.pick(keys);
      opts[key] = randomValue(r, SCHEMA[key], outside && k === 1);
    }
    if (r.chance(0.2)) opts.printer = r.pick(['prusa-mk4', 'voron-2.4-350', 'flsun-q5', 'no-such-printer']);
    const what = `settings #${i} ${JSON.stringify(opts).slice(0, 300)}`;
    if (outside) {
      assert.throws(
        () => new Slicer(opts as SliceOptions),
        (e: unknown) => e instanceof StrataError && !e.message.includes('\n'),
        what,
      );
      continue;
    }
    await attempt(what, opts, part);
  }
});

test('peak memory stays bounded over all the cases', { skip }, () => {
  const peakMiB = Math.max(maxRssSeen, process.resourceUsage().maxRSS * 1024) / (1024 * 1024);
  assert.ok(peakMiB < 512, `peak RSS ${Math.round(peakMiB)} MiB`);
});

// ── devices and streams through the command line ────────────────────────────

const CLI = fileURLToPath(new URL('../../../dist/cli/main.js', import.meta.url));
const CUBE = ROOT + 'examples/calibration-cube.stl';

interface CliOutcome {
  status: number | null;
  stderr: string;
  /** Peak resident memory of the run, MiB (when /usr/bin/time can tell). */
  peakMiB: number | null;
  ms: number;
}

/** Run the CLI with `stdin` written in random pieces at random moments (then closed), or nothing on it. */
function runCli(args: string[], r: Rng, stdin?: Uint8Array): Promise<CliOutcome> {
  const dir = mkdtempSync(join(tmpdir(), 'strata-fuzz-cli-'));
  const timeFile = join(dir, 'rss');
  const timed = existsSync('/usr/bin/time');
  const [cmd, argv] = timed
    ? ['/usr/bin/time', ['-o', timeFile, '-f', '%M', process.execPath, CLI, ...args]]
    : [process.execPath, [CLI, ...args]];
  const t0 = performance.now();
  const child = spawn(cmd, argv, { stdio: ['pipe', 'ignore', 'pipe'] });
  let stderr = '';
  child.stderr.on('data', (d) => (stderr += d));
  child.stdin.on('error', () => {});
  const pieces: Uint8Array[] = [];
  for (let at = 0; stdin && at < stdin.length; ) {
    const n = 1 + r.int(Math.min(stdin.length - at, 1 + r.int(256 * 1024)));
    pieces.push(stdin.subarray(at, at + n));
    at += n;
  }
  const delays = pieces.map(() => (r.chance(0.2) ? r.int(30) : 0));
  void (async () => {
    for (const [i, p] of pieces.entries()) {
      if (delays[i]) await new Promise((res) => setTimeout(res, delays[i]));
      if (child.stdin.destroyed || !child.stdin.write(p))
        await new Promise((res) =>
          child.stdin.destroyed ? res(null) : child.stdin.once('drain', res).once('close', res),
        );
    }
    child.stdin.end();
  })();
  return new Promise((resolve) => {
    const killer = setTimeout(() => child.kill('SIGKILL'), 120_000);
    child.on('close', (status) => {
      clearTimeout(killer);
      const ms = performance.now() - t0;
      const rss =
        timed && existsSync(timeFile) ? Number(readFileSync(timeFile, 'utf8').trim().split('\n').at(-1)) : NaN;
      rmSync(dir, { recursive: true, force: true });
      resolve({ status, stderr, peakMiB: Number.isFinite(rss) ? rss / 1024 : null, ms });
    });
  });
}

test('devices and streams as models, configs, shaders and images: G-code or one line, within the limits', {
  skip: process.platform !== 'linux' && 'needs Linux devices',
  timeout: 900_000,
}, async () => {
  const r = new Rng(SEED + 3);
  const work = mkdtempSync(join(tmpdir(), 'strata-fuzz-dev-'));
  const fifo = join(work, 'fifo');
  const haveFifo = spawnSync('mkfifo', [fifo]).status === 0;
  const cube = new Uint8Array(readFileSync(CUBE));
  const random = (n: number) => Uint8Array.from({ length: n }, () => r.int(256));
  // a flag, and how much memory that kind of input may take (its read limit and the slicer around it)
  const kinds = [
    { flag: null, limitMiB: 954 },
    { flag: '--config', limitMiB: 16 },
    { flag: '--infill-shader', limitMiB: 1 },
    { flag: '--infill-image', limitMiB: 64 },
  ];
  const sources: Array<{ name: string; path: string; stdin?: () => Uint8Array; fifo?: () => Uint8Array }> = [
    { name: '/dev/zero', path: '/dev/zero' },
    { name: '/dev/urandom', path: '/dev/urandom' },
    { name: '/dev/null', path: '/dev/null' },
    { name: 'a folder', path: work },
    { name: 'stdin: random bytes', path: '-', stdin: () => random(r.int(200_000)) },
    { name: 'stdin: the cube in pieces', path: '-', stdin: () => cube },
    { name: 'stdin: a mutated cube in pieces', path: '-', stdin: () => mutateBytes(r, cube) },
    { name: 'stdin: nothing', path: '-', stdin: () => new Uint8Array(0) },
    ...(haveFifo ? [{ name: 'a FIFO with random bytes', path: fifo, fifo: () => random(r.int(100_000)) }] : []),
  ];
  const seen = { gcode: 0, refused: 0 };
  for (const kind of kinds) {
    for (const src of sources) {
      const what = `${kind.flag ?? 'model'} ${src.name}`;
      const args = kind.flag === null ? ['slice', src.path] : ['slice', CUBE, kind.flag, src.path];
      args.push('-o', join(work, 'out.gcode'), '-q', '--threads', '1');
      let writer: ReturnType<typeof spawn> | null = null;
      if (src.fifo) {
        // a writer that sends its bytes and closes, as a pipe from another program does
        writer = spawn('sh', ['-c', `cat > "${fifo}"`], { stdio: ['pipe', 'ignore', 'ignore'] });
        writer.stdin!.on('error', () => {});
        writer.stdin!.end(src.fifo());
      }
      const out = await runCli(args, r, src.stdin?.());
      writer?.kill('SIGKILL');
      assert.ok(out.status === 0 || out.status === 1, `${what}: exit ${out.status}: ${out.stderr}`);
      if (out.status === 1) {
        assert.match(out.stderr, /^strata: error: [^\n]+\n$/, `${what}: one line`);
        seen.refused++;
      } else seen.gcode++;
      if (out.peakMiB !== null)
        assert.ok(out.peakMiB < kind.limitMiB + 450, `${what}: peak ${Math.round(out.peakMiB)} MiB`);
      assert.deepEqual(
        readdirSync(work).filter((f) => f.endsWith('.tmp')),
        [],
        `${what}: no temporary file left`,
      );
      rmSync(join(work, 'out.gcode'), { force: true });
    }
  }
  rmSync(work, { recursive: true, force: true });
  assert.ok(seen.gcode > 0 && seen.refused > 0, JSON.stringify(seen));
});
