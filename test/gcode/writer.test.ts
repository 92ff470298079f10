import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '#strata/errors.js';
import type { Pt } from '#strata/geometry/types.js';
import { estimatePlan } from '#strata/plan/estimate.js';
import type { ExtrudeStep, FeatureType, LayerPlan, PrintPlan, TravelStep } from '#strata/plan/types.js';
import { SCHEMA, SETTING_KEYS, type Settings } from '#strata/settings/schema.js';
import { CHUNK_BYTES, gcodeToString, writeGcode } from '#strata/gcode/writer.js';

const META = { generator: 'Strata 0.0.0-test' };

function defaults(overrides: Partial<Settings> = {}): Settings {
  const values: Record<string, unknown> = {};
  for (const key of SETTING_KEYS) values[key] = SCHEMA[key].default;
  return { ...(values as Settings), ...overrides };
}

const pt = (xMm: number, yMm: number): Pt => ({ x: Math.round(xMm * 1000), y: Math.round(yMm * 1000) });

function extrude(feature: FeatureType, points: Pt[], closed: boolean, height = 0.2, speed = 30): ExtrudeStep {
  return { kind: 'extrude', feature, points, closed, width: 0.4, height, speed, flow: 1 };
}
function travel(points: Pt[], retract: boolean, zHop = 0, speed = 150): TravelStep {
  return { kind: 'travel', points, retract, zHop, speed };
}
const square = (x0: number, y0: number, side: number): Pt[] => [
  pt(x0, y0),
  pt(x0 + side, y0),
  pt(x0 + side, y0 + side),
  pt(x0, y0 + side),
];

/** Two layers: a brim loop, a square wall, a retracted hop travel, a fill line; then a layer change. */
function smallPlan(): PrintPlan {
  const layer0: LayerPlan = {
    index: 0,
    z: 0.2,
    height: 0.2,
    fan: 0,
    nozzleTemperature: 200,
    bedTemperature: 60,
    steps: [
      travel([pt(5, 5)], false),
      extrude('BRIM', square(5, 5, 30), true, 0.2, 20),
      travel([pt(10, 10)], false),
      extrude('WALL-OUTER', square(10, 10, 20), true, 0.2, 20),
      travel([pt(25, 35), pt(40, 40)], true, 0.4),
      extrude('FILL', [pt(40, 40), pt(60, 40), pt(60, 40.4), pt(40, 40.4)], false, 0.2, 60),
    ],
  };
  const layer1: LayerPlan = {
    index: 1,
    z: 0.4,
    height: 0.2,
    fan: 1,
    nozzleTemperature: 195,
    bedTemperature: 60,
    steps: [
      travel([pt(10, 10)], true),
      extrude('WALL-OUTER', square(10, 10, 20), true, 0.2, 40),
      extrude('WALL-OUTER', square(11, 11, 18), true, 0.2, 40),
    ],
  };
  return {
    layers: [layer0, layer1],
    objects: [],
    bounds: { minX: 5, minY: 5, minZ: 0, maxX: 60, maxY: 40.4, maxZ: 0.4 },
  };
}

/** The filament the small plan extrudes, mm, computed by hand (rectangular model, flow 1, flowRate 100). */
function smallPlanFilament(s: Settings): number {
  const perMm = (0.4 * 0.2) / (Math.PI * (s.filamentDiameter / 2) ** 2);
  const length = 120 + 80 + (20 + 0.4 + 20) + 80 + 72;
  return length * perMm + 2 * s.retractionExtraPrime;
}

interface Parsed {
  totalE: number;
  layers: number;
  layerCountHeader: number;
  types: string[][];
  retractions: number;
  primes: number;
  /** Net E at each prime minus net E before the matching retraction. */
  primeBalance: number[];
  /** For each extruding move: the Z it happened at and the layer's declared Z. */
  extrusionZ: { z: number; layerZ: number }[];
  /** Z of travel moves made while retracted. */
  retractedTravelZ: number[];
  maxFeed: number;
  lines: string[];
}

/** A tiny analyser for these tests: tracks E in absolute and relative modes, Z, retractions. */
function parse(gcode: string): Parsed {
  const out: Parsed = {
    totalE: 0,
    layers: 0,
    layerCountHeader: -1,
    types: [],
    retractions: 0,
    primes: 0,
    primeBalance: [],
    extrusionZ: [],
    retractedTravelZ: [],
    maxFeed: 0,
    lines: gcode.split('\n'),
  };
  let relative = false;
  let e = 0;
  let z = NaN;
  let layerZ = NaN;
  let retractedAt: number | null = null;
  let inBody = false;
  // The body runs from ;LAYER_COUNT to the last layer's ;TIME_ELAPSED; the end template is not counted.
  let bodyEnd = out.lines.length;
  for (let i = out.lines.length - 1; i >= 0; i--) {
    if (out.lines[i]!.startsWith(';TIME_ELAPSED:')) {
      bodyEnd = i;
      break;
    }
  }
  for (let i = 0; i < bodyEnd; i++) {
    const raw = out.lines[i]!;
    if (raw.startsWith(';LAYER_COUNT:')) {
      out.layerCountHeader = Number(raw.slice(13));
      inBody = true;
    }
    if (raw.startsWith(';LAYER:')) {
      out.layers++;
      out.types.push([]);
    }
    if (raw.startsWith(';Z:')) layerZ = Number(raw.slice(3));
    if (raw.startsWith(';TYPE:')) out.types[out.types.length - 1]!.push(raw.slice(6));
    const code = raw.split(';')[0]!.trim();
    if (code === '') continue;
    const [cmd, ...rest] = code.split(/\s+/);
    const words: Record<string, number> = {};
    for (const w of rest) words[w[0]!] = Number(w.slice(1));
    if (cmd === 'M82') relative = false;
    else if (cmd === 'M83') relative = true;
    else if (cmd === 'G92' && 'E' in words) e = words.E!;
    else if (cmd === 'G0' || cmd === 'G1') {
      if ('Z' in words) z = words.Z!;
      if ('F' in words) out.maxFeed = Math.max(out.maxFeed, words.F!);
      const hasXY = 'X' in words || 'Y' in words;
      let delta = 0;
      if ('E' in words) {
        delta = relative ? words.E! : words.E! - e;
        e = relative ? e + words.E! : words.E!;
      }
      if (!inBody) continue;
      out.totalE += delta;
      if (!hasXY && delta < 0) {
        out.retractions++;
        retractedAt = out.totalE - delta;
      } else if (!hasXY && delta > 0) {
        out.primes++;
        if (retractedAt !== null) out.primeBalance.push(out.totalE - retractedAt);
        retractedAt = null;
      } else if (hasXY && delta > 0) {
        out.extrusionZ.push({ z, layerZ });
      } else if (hasXY && retractedAt !== null) {
        out.retractedTravelZ.push(z);
      }
    }
  }
  return out;
}

function gcodeFor(
  overrides: Partial<Settings> = {},
  plan = smallPlan(),
): { gcode: string; settings: Settings; plan: PrintPlan } {
  const settings = defaults(overrides);
  const gcode = gcodeToString(plan, settings, estimatePlan(plan, settings), META);
  return { gcode, settings, plan };
}

test('layer markers, layer count and TYPE markers (BRIM written as SKIRT)', () => {
  const { gcode } = gcodeFor();
  const p = parse(gcode);
  assert.equal(p.layerCountHeader, 2);
  assert.equal(p.layers, 2);
  assert.deepEqual(p.types, [['SKIRT', 'WALL-OUTER', 'FILL'], ['WALL-OUTER']]);
  assert.match(
    gcode,
    /^;FLAVOR:Marlin\n;TIME:\d+\n;Filament used: [\d.]+m\n;Layer height: 0\.2\n;MINX:5\n;MINY:5\n;MINZ:0\n;MAXX:60\n;MAXY:40\.4\n;MAXZ:0\.4\n;Generated with Strata 0\.0\.0-test\n/,
  );
  assert.match(gcode, /;Estimated print time: (\d+m )?\d+s\n/);
});

test('absolute and relative E give the same total, equal to the plan filament and the estimate', () => {
  const abs = gcodeFor({ extruderMode: 'absolute', retractionExtraPrime: 0.3 });
  const rel = gcodeFor({ extruderMode: 'relative', retractionExtraPrime: 0.3 });
  const a = parse(abs.gcode);
  const r = parse(rel.gcode);
  const expected = smallPlanFilament(abs.settings);
  assert.ok(Math.abs(a.totalE - r.totalE) < 1e-4, `${a.totalE} vs ${r.totalE}`);
  assert.ok(Math.abs(a.totalE - expected) < 1e-4, `${a.totalE} vs ${expected}`);
  const estimate = estimatePlan(abs.plan, abs.settings);
  assert.ok(Math.abs(estimate.filamentMm - expected) < 1e-9);
  assert.match(abs.gcode, /\nM82 ; absolute extrusion\nG92 E0\n/);
  assert.match(rel.gcode, /\nM83 ; relative extrusion\nG92 E0\n/);
  // Absolute E restarts at each layer that follows extrusion.
  assert.match(abs.gcode, /;LAYER:1\n;Z:0\.4\n;HEIGHT:0\.2\n(.*\n)*?G92 E0\n/);
  // Relative E needs no resets in the body.
  assert.ok(!/G92/.test(rel.gcode.split(';LAYER_COUNT')[1]!));
});

test('retractions are balanced: each prime restores the retraction plus the extra prime', () => {
  for (const extruderMode of ['absolute', 'relative'] as const) {
    const { gcode, settings } = gcodeFor({ extruderMode, retractionExtraPrime: 0.2, retractionDistance: 4 });
    const p = parse(gcode);
    assert.equal(p.retractions, 2);
    assert.equal(p.primes, 2);
    for (const balance of p.primeBalance)
      assert.ok(Math.abs(balance - settings.retractionExtraPrime) < 1e-6, `${balance}`);
    assert.match(gcode, extruderMode === 'relative' ? /\nG1 F2700 E-4\n/ : /\nG1 F2700 E[\d.]+\n/);
  }
});

test('retraction off: no E-only moves at all', () => {
  const p = parse(gcodeFor({ retractionEnabled: false }).gcode);
  assert.equal(p.retractions, 0);
  assert.equal(p.primes, 0);
});

test('z-hop lifts during the retracted travel and comes back down before printing', () => {
  const { gcode } = gcodeFor();
  const p = parse(gcode);
  assert.ok(p.extrusionZ.length > 0);
  for (const { z, layerZ } of p.extrusionZ) assert.equal(z, layerZ);
  assert.ok(p.retractedTravelZ.includes(0.6), `hop travel at ${p.retractedTravelZ}`);
  assert.ok(p.retractedTravelZ.includes(0.4), 'layer-change travel without hop at the new layer Z');
  // Order: retract, lift, travel, lower, prime.
  assert.match(
    gcode,
    /G1 F2700 E[\d.]+\nG0 F300 Z0\.6\nG0 F9000 X25 Y35\nG0 X40 Y40\nG0 F300 Z0\.2\nG1 F2700 E[\d.]+\n/,
  );
});

test('placeholders are replaced by settings and derived values; unknown ones are rejected', () => {
  const startGcode =
    'M190 S{firstLayerBedTemperature}\nM109 S{firstLayerNozzleTemperature}\n; plate {buildPlateWidth} x {buildPlateLength}, {layerCount} layers, bed {heatedBed}, top {maxZ}\n; [not a placeholder]';
  const { gcode } = gcodeFor({
    startGcode,
    nozzleTemperature: 215,
    firstLayerNozzleTemperature: null,
    firstLayerBedTemperature: 65,
  });
  assert.match(gcode, /\nM190 S65\nM109 S215\n; plate 220 x 220, 2 layers, bed 1, top 0\.4\n; \[not a placeholder\]\n/);
  assert.ok(!/\{\w+\}/.test(gcode));

  const plan = smallPlan();
  const bad = defaults({ startGcode: 'G28\nM104 S{foo}' });
  const chunks: string[] = [];
  assert.throws(
    () => writeGcode(plan, bad, estimatePlan(plan, bad), (c) => chunks.push(c), META),
    (err: unknown) =>
      err instanceof StrataError &&
      err.code === 'BAD_SETTING' &&
      err.message === 'startGcode line 2: unknown placeholder {foo}',
  );
  assert.equal(chunks.length, 0, 'nothing written before the check');
  const badEnd = defaults({ endGcode: 'M84 {nope}' });
  assert.throws(() => gcodeFor({ endGcode: badEnd.endGcode }), /endGcode line 1: unknown placeholder \{nope\}/);
  assert.throws(
    () => gcodeFor({ startGcode: '; walls {wallCount}' }),
    /startGcode line 1: placeholder \{wallCount\} has no value/,
  );
});

test('heat-up is written only when the start template does not handle temperatures', () => {
  const withPlaceholders = gcodeFor().gcode;
  const beforeStart = withPlaceholders.split('G90 ; absolute positioning')[0]!;
  assert.ok(!/M10[49]|M1[49]0/.test(beforeStart));
  const bare = gcodeFor({ startGcode: 'G28', firstLayerNozzleTemperature: 210, bedTemperature: 55 }).gcode;
  assert.match(bare, /\nM140 S55\nM104 S210\nM190 S55\nM109 S210\nG28\nM82/);
  const rrf = gcodeFor({ startGcode: 'G28', gcodeFlavor: 'reprap', nozzleTemperature: 205, heatedBed: false }).gcode;
  assert.match(rrf, /\nG10 P0 S205 R205\nG10 P0 S205 R205\nT0\nM116 P0\nG28\n/);
  assert.ok(!/M1[49]0/.test(rrf.split(';LAYER_COUNT')[0]!));
});

test('the extrusion mode command follows the start G-code whatever it says', () => {
  const { gcode } = gcodeFor({ extruderMode: 'relative', startGcode: 'M82\nG28' });
  assert.match(gcode, /\nM82\nG28\nM83 ; relative extrusion\n/);
});

test('temperature and fan changes are written at layer starts only when they change', () => {
  const { gcode } = gcodeFor();
  const layer0 = gcode.split(';LAYER:0\n')[1]!.split(';TYPE')[0]!;
  const layer1 = gcode.split(';LAYER:1\n')[1]!.split(';TYPE')[0]!;
  assert.ok(!/M104/.test(layer0), 'first-layer temperature already set by the start G-code');
  assert.match(layer0, /\nM107\n/);
  assert.match(layer1, /\nM104 S195\n/);
  assert.match(layer1, /\nM106 S255\n/);
  assert.ok(!/M140/.test(layer0 + layer1));
  assert.equal(gcode.match(/^M10[67]/gm)!.length - (gcode.match(/M106 S0 ; fan off/g)?.length ?? 0), 2);
});

test('flavours: FLAVOR line, fan scale, acceleration command', () => {
  const accel = { acceleration: 1500 };
  const marlin = gcodeFor(accel).gcode;
  assert.match(marlin, /^;FLAVOR:Marlin\n/);
  assert.match(marlin, /\nM204 P1500 T1500\n;LAYER_COUNT:2\n/);
  const klipper = gcodeFor({ ...accel, gcodeFlavor: 'klipper' }).gcode;
  assert.match(klipper, /^;FLAVOR:Klipper\n/);
  assert.match(klipper, /\nM204 S1500\n/);
  assert.match(klipper, /\nM106 S255\n/);
  const reprap = gcodeFor({ ...accel, gcodeFlavor: 'reprap' }).gcode;
  assert.match(reprap, /^;FLAVOR:RepRap\n/);
  assert.match(reprap, /\nM106 S0\n/);
  assert.match(reprap, /\nM106 S1\n/);
  assert.match(reprap, /\nG10 P0 S195 R195\n/);
  assert.ok(!/M204/.test(gcodeFor().gcode), 'default acceleration: firmware keeps its own');
});

test('numbers are compact and feed rates modal, whole and capped at maxSpeed', () => {
  const plan = smallPlan();
  (plan.layers[0]!.steps[5] as ExtrudeStep).speed = 500;
  const { gcode } = gcodeFor({ maxSpeed: 100 }, plan);
  const body = gcode.split(';LAYER_COUNT')[1]!.split(';LAYER:1\n')[1]!.split(';TIME_ELAPSED')[0]!;
  let lastF = -1;
  for (const line of body.split('\n')) {
    if (!/^G[01] /.test(line)) continue;
    for (const word of line.split(' ').slice(1)) {
      const axis = word[0]!;
      const value = word.slice(1);
      assert.ok(!/\.\d*0$/.test(value) && !/\.$/.test(value), `trailing zero in ${line}`);
      if (axis === 'X' || axis === 'Y' || axis === 'Z') assert.match(value, /^-?\d+(\.\d{1,3})?$/);
      if (axis === 'E') assert.match(value, /^-?\d+(\.\d{1,5})?$/);
      if (axis === 'F') {
        assert.match(value, /^\d+$/);
        assert.notEqual(Number(value), lastF, `repeated F in ${line}`);
        assert.ok(Number(value) <= 6000, `F over maxSpeed in ${line}`);
        lastF = Number(value);
      }
    }
  }
  assert.match(gcode, /\nG1 F6000 X60 E/);
  // Unchanged axes are omitted: the third wall corner moves only Y.
  assert.match(body, /\nG1 Y30 E[\d.]+\n/);
});

/** A plan big enough to need many chunks. */
function bigPlan(): PrintPlan {
  const layers: LayerPlan[] = [];
  for (let l = 0; l < 20; l++) {
    const steps: LayerPlan['steps'] = [];
    for (let k = 0; k < 40; k++) {
      const pts: Pt[] = [];
      for (let i = 0; i < 100; i++) {
        const a = (i / 100) * 2 * Math.PI;
        pts.push(pt(100 + (5 + k * 0.4) * Math.cos(a), 100 + (5 + k * 0.4) * Math.sin(a)));
      }
      steps.push(travel([pts[0]!], k % 5 === 0, 0.2));
      steps.push(extrude(k === 0 ? 'WALL-OUTER' : 'WALL-INNER', pts, true, 0.2, 50));
    }
    layers.push({ index: l, z: 0.2 * (l + 1), height: 0.2, fan: l === 0 ? 0 : 1, steps });
  }
  return { layers, objects: [], bounds: { minX: 75, minY: 75, minZ: 0, maxX: 125, maxY: 125, maxZ: 4 } };
}

test('deterministic output; chunked streaming equals the string version', () => {
  const plan = bigPlan();
  const settings = defaults({ extruderMode: 'relative' });
  const estimate = estimatePlan(plan, settings);
  const chunks: string[] = [];
  writeGcode(plan, settings, estimate, (c) => chunks.push(c), META);
  const whole = gcodeToString(plan, settings, estimate, META);
  assert.ok(chunks.length > 3, `${chunks.length} chunks`);
  assert.equal(chunks.join(''), whole);
  for (const c of chunks.slice(0, -1))
    assert.ok(c.length >= CHUNK_BYTES && c.length < CHUNK_BYTES + 200 && c.endsWith('\n'));
  assert.equal(gcodeToString(plan, settings, estimatePlan(plan, settings), META), whole);
  const p = parse(whole);
  assert.equal(p.layers, 20);
  const abs = parse(gcodeToString(plan, { ...settings, extruderMode: 'absolute' }, estimate, META));
  assert.ok(Math.abs(p.totalE - abs.totalE) < 1e-4);
  assert.ok(Math.abs(p.totalE - estimate.filamentMm) < 1e-3);
});

test('date and comments from meta go in the header; TIME_ELAPSED adds up the layer estimates', () => {
  const plan = smallPlan();
  const settings = defaults();
  const estimate = estimatePlan(plan, settings);
  const gcode = gcodeToString(plan, settings, estimate, {
    generator: 'Strata 1.2.3',
    date: '2024-01-02',
    comments: ['model: cube.stl'],
  });
  assert.match(gcode, /\n;Generated with Strata 1\.2\.3\n;Date: 2024-01-02\n/);
  assert.match(gcode, /\n;model: cube\.stl\n/);
  const elapsed = [...gcode.matchAll(/;TIME_ELAPSED:([\d.]+)/g)].map((m) => Number(m[1]));
  assert.equal(elapsed.length, 2);
  assert.ok(Math.abs(elapsed[1]! - estimate.printTimeSeconds) < 1e-3);
  assert.match(gcode, new RegExp(`;TIME:${Math.round(estimate.printTimeSeconds)}\\n`));
});

test('a step with its own fan sets it, and the layer fan comes back after', () => {
  const plan = smallPlan();
  const l1 = plan.layers[1];
  const steps = l1.steps.filter((s) => s.kind === 'extrude') as ExtrudeStep[];
  steps[0].fan = 0.5;
  const s = defaults();
  const text = gcodeToString(plan, s, estimatePlan(plan, s), META);
  const body = text.slice(text.indexOf(';LAYER:1'));
  const fans = body.split('\n').filter((l) => /^M10[67]\b/.test(l));
  assert.deepEqual(fans.slice(0, 3), ['M106 S255', 'M106 S128', 'M106 S255']);
});
