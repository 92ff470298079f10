/**
 * Seeded fuzzing of the whole slicer: mutated STL, OBJ, 3MF, PNG and GLSL inputs (from the shared
 * models and the shipped infillers) and random settings in and out of range. Every outcome must be
 * valid G-code or one StrataError with a one-line message: never another exception, a hang or
 * unbounded memory. The case counts are fixed (so CI time is bounded and a failure replays with the
 * same seed); STRATA_FUZZ_SEED picks another seed and STRATA_FUZZ_SCALE multiplies the counts.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { strToU8, zipSync } from 'fflate';
import { Slicer } from '../api/slicer.js';
import { StrataError } from '../errors.js';
import { parseGcode } from '../analysis/gcode-parse.js';
import { resolveConfig } from '../settings/resolve.js';
import { SCHEMA, SETTING_KEYS, type SettingDef, type SettingKey, type SliceOptions } from '../settings/schema.js';
import { blockWithHole } from '../cli/test-model.js';
import { modelPath, skipWithoutModels } from './models-dir.js';

const SEED = Number(process.env.STRATA_FUZZ_SEED ?? 9001);
const SCALE = Math.max(0.1, Number(process.env.STRATA_FUZZ_SCALE ?? 1));
const count = (n: number) => Math.max(1, Math.round(n * SCALE));
const skip = skipWithoutModels();
const ROOT = fileURLToPath(new URL('../../', import.meta.url));

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
      const from = r.int(b.length), to = r.int(b.length), n = r.int(Math.min(64, b.length - Math.max(from, to)));
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

const ODD_NUMBERS = ['0', '-0', '1e30', '-1e30', 'NaN', 'inf', '1e-30', '99999999999', '-3.5', '4294967296', '0x10', '', '1.5.5'];

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
      return src.slice(0, at) + r.pick(['{', '}', '(', ';', '#', '\0', 'for(;;){', '/*', '"', '<', '>', '&', '\uFFFD']) + src.slice(at);
    }
  }
}

// ── inputs ───────────────────────────────────────────────────────────────────

/** Triangles of a binary STL as [x,y,z]×3 lists. */
function stlTriangles(b: Uint8Array): number[][] {
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  const n = dv.getUint32(80, true);
  const out: number[][] = [];
  for (let t = 0; t < n; t++) out.push(Array.from({ length: 9 }, (_, k) => dv.getFloat32(84 + 50 * t + 12 + 4 * k, true)));
  return out;
}

function objText(tris: number[][]): string {
  const v = tris.map((t) => `v ${t[0]} ${t[1]} ${t[2]}\nv ${t[3]} ${t[4]} ${t[5]}\nv ${t[6]} ${t[7]} ${t[8]}`).join('\n');
  const f = tris.map((_, i) => `f ${3 * i + 1} ${3 * i + 2} ${3 * i + 3}`).join('\n');
  return `o cube\n${v}\n${f}\n`;
}

function modelXml(tris: number[][]): string {
  const v = tris.map((t) => `<vertex x="${t[0]}" y="${t[1]}" z="${t[2]}"/><vertex x="${t[3]}" y="${t[4]}" z="${t[5]}"/><vertex x="${t[6]}" y="${t[7]}" z="${t[8]}"/>`).join('\n');
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
        if (p[0] === 'X') assert.ok(v >= x0 - 1e-3 && v <= x0 + cfg.buildPlateWidth + 1e-3, `${what}: X off the bed at line ${n + 1}: ${lines[n]}`);
        if (p[0] === 'Y') assert.ok(v >= y0 - 1e-3 && v <= y0 + cfg.buildPlateLength + 1e-3, `${what}: Y off the bed at line ${n + 1}: ${lines[n]}`);
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
async function attempt(what: string, options: SliceOptions & { customInfill?: unknown }, input: unknown): Promise<void> {
  let slicer: Slicer;
  try {
    slicer = new Slicer(options as SliceOptions);
    const { gcode, stats } = await slicer.slice(input);
    checkGcode(gcode, slicer.config, stats.layers, what);
    outcomes.gcode++;
  } catch (e) {
    if (e instanceof assert.AssertionError) throw e;
    assert.ok(e instanceof StrataError, `${what}: threw ${e instanceof Error ? `${e.name}: ${e.message}\n${e.stack}` : String(e)}`);
    assert.ok(e.message.length > 0 && !e.message.includes('\n'), `${what}: one line: ${e.message}`);
    outcomes.refused++;
  }
  maxRssSeen = Math.max(maxRssSeen, process.memoryUsage().rss);
}

/** Settings that keep every case small (a mutated vertex far away is refused, not sliced for minutes). */
const SMALL: SliceOptions = { threads: 1, layerHeight: 0.3, buildVolumeHeight: 40, adhesionType: 'none', infillDensity: 15 };

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
  for (let i = 0; i < count(10); i++) await attempt(`3MF XML #${i}`, SMALL, zipSync({ '3D/3dmodel.model': strToU8(mutateText(r, xml)) }));
  const zipped = zipSync({ '3D/3dmodel.model': strToU8(xml) });
  for (let i = 0; i < count(10); i++) await attempt(`3MF bytes #${i}`, SMALL, mutateBytes(r, zipped));
  assert.ok(outcomes.gcode > 0 && outcomes.refused > 0, `both outcomes seen: ${JSON.stringify(outcomes)}`);
});

test('mutated infill images and shaders: a working infiller or one StrataError', { skip, timeout: 600_000 }, async () => {
  const r = new Rng(SEED + 1);
  const png = new Uint8Array(readFileSync(ROOT + 'infillers/example-image/cells.png'));
  const shaders = ['checker', 'hexagon-grid', 'tpms-gyroid', 'tpms-schwarz-p', 'voronoi-foam'].map((n) => readFileSync(`${ROOT}infillers/${n}/shader.glsl`, 'utf8'));
  const pin = blockWithHole(6, 2.4, 1.5, 16);
  const opts = { ...SMALL, layerHeight: 0.3 };
  let sliced = 0;
  const tryInfill = async (what: string, spec: { name: string; image?: Uint8Array; shader?: string }) => {
    let ok = true;
    try {
      new Slicer({ ...opts, customInfill: spec } as SliceOptions);
    } catch (e) {
      ok = false;
      assert.ok(e instanceof StrataError && !e.message.includes('\n'), `${what}: ${e instanceof Error ? e.stack : String(e)}`);
    }
    // slice a few that load, on a small part
    if (ok && sliced < count(6)) {
      sliced++;
      await attempt(what, { ...opts, customInfill: spec }, pin);
    }
  };
  for (let i = 0; i < count(40); i++) await tryInfill(`cells.png #${i}`, { name: 'fuzz', image: mutateBytes(r, png) });
  for (let i = 0; i < count(40); i++) await tryInfill(`shader #${i}`, { name: 'fuzz', shader: mutateText(r, r.pick(shaders)) });
  assert.ok(sliced > 0);
});

/** A random value for a setting: in its range, or (with `outside`) just out of it or of the wrong type. */
function randomValue(r: Rng, def: SettingDef, outside: boolean): unknown {
  switch (def.type) {
    case 'number':
    case 'integer': {
      if (outside) return r.pick([def.max + 1 + r.float() * def.max, def.min - 1 - r.float() * 10, NaN, Infinity, '12', null].filter((v) => v !== null || !def.nullable));
      if (def.nullable && r.chance(0.3)) return null;
      const v = def.min + (def.max - def.min) * r.float() ** 3;
      return def.type === 'integer' ? Math.round(v) : v;
    }
    case 'boolean':
      return outside ? r.pick(['yes', 1, null]) : r.chance(0.5);
    case 'enum':
      return outside ? 'no-such-choice' : r.pick(def.values);
    case 'string':
      return outside ? 'x'.repeat(def.maxLength + 1) : r.pick(['G28', 'G28\nG1 Z5 F600', '; nothing', 'M117 {layerCount} layers']);
  }
}

test('random settings in and out of range: valid G-code or one StrataError', { skip, timeout: 600_000 }, async () => {
  const r = new Rng(SEED + 2);
  const part = blockWithHole(8, 3, 2, 24);
  // the settings that size the work stay modest, so a case takes well under a second
  const bounded = new Set<SettingKey>(['threads', 'layerHeight', 'firstLayerHeight', 'buildVolumeHeight', 'inflateBudget']);
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
      assert.throws(() => new Slicer(opts as SliceOptions), (e: unknown) => e instanceof StrataError && !e.message.includes('\n'), what);
      continue;
    }
    await attempt(what, opts, part);
  }
});

test('peak memory stays bounded over all the cases', { skip }, () => {
  const peakMiB = Math.max(maxRssSeen, process.resourceUsage().maxRSS * 1024) / (1024 * 1024);
  assert.ok(peakMiB < 512, `peak RSS ${Math.round(peakMiB)} MiB`);
});
