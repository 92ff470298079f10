/**
 * The host and firmware features of the writer, parsed back from G-code written for hand-built plans:
 * M73 progress, object labels, firmware retraction, pressure advance, machine limits and thumbnails.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Pt } from '#strata/geometry/types.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { estimatePlan } from '#strata/plan/estimate.js';
import type { ExtrudeStep, LayerPlan, PlanObject, PrintPlan, TravelStep } from '#strata/plan/types.js';
import { SCHEMA, SETTING_KEYS, type Settings } from '#strata/settings/schema.js';
import { gcodeToString, type GcodeMeta } from '#strata/gcode/writer.js';
import { THUMBNAIL_LINE_CHARS } from '#strata/gcode/thumbnail-blocks.js';

const META: GcodeMeta = { generator: 'Strata test' };

function settings(overrides: Partial<Settings> = {}): Settings {
  const values: Record<string, unknown> = {};
  for (const key of SETTING_KEYS) values[key] = SCHEMA[key].default;
  return { ...(values as Settings), ...overrides };
}

const pt = (x: number, y: number): Pt => ({ x: Math.round(x * 1000), y: Math.round(y * 1000) });
const square = (x0: number, y0: number, side: number): Pt[] => [
  pt(x0, y0),
  pt(x0 + side, y0),
  pt(x0 + side, y0 + side),
  pt(x0, y0 + side),
];
const wall = (points: Pt[], object?: number): ExtrudeStep => ({
  kind: 'extrude',
  feature: 'WALL-OUTER',
  points,
  closed: true,
  width: 0.4,
  height: 0.2,
  speed: 30,
  flow: 1,
  ...(object === undefined ? {} : { object }),
});
const fill = (points: Pt[], object: number): ExtrudeStep => ({
  ...wall(points, object),
  feature: 'FILL',
  closed: false,
  speed: 60,
});
const go = (to: Pt, retract: boolean): TravelStep => ({
  kind: 'travel',
  points: [to],
  retract,
  zHop: retract ? 0.4 : 0,
  speed: 150,
});

/** Two 10 mm cubes' worth of layers: object 0 at x 20..30, object 1 at x 60..70, a skirt around both on layer 0. */
function twoObjectPlan(layers = 6): PrintPlan {
  const objects: PlanObject[] = [
    {
      name: 'left cube',
      center: [25, 25],
      polygon: [
        [20, 20],
        [30, 20],
        [30, 30],
        [20, 30],
      ],
    },
    {
      name: 'right cube',
      center: [65, 25],
      polygon: [
        [60, 20],
        [70, 20],
        [70, 30],
        [60, 30],
      ],
    },
  ];
  const out: LayerPlan[] = [];
  for (let i = 0; i < layers; i++) {
    const steps: LayerPlan['steps'] = [];
    if (i === 0) steps.push(go(pt(15, 15), false), wall(square(15, 15, 60)));
    for (const [k, x] of [
      [0, 20],
      [1, 60],
    ] as const) {
      steps.push(go(pt(x + 0.2, 20.2), true));
      steps.push(wall(square(x + 0.2, 20.2, 9.6), k));
      // an intra-object retracted travel, then a fill line
      steps.push(go(pt(x + 1, 21), true));
      steps.push(fill([pt(x + 1, 21), pt(x + 9, 29), pt(x + 9, 28), pt(x + 2, 21)], k));
    }
    out.push({ index: i, z: 0.2 * (i + 1), height: 0.2, fan: i === 0 ? 0 : 1, steps });
  }
  return { layers: out, objects, bounds: { minX: 15, minY: 15, minZ: 0.2, maxX: 75, maxY: 75, maxZ: 0.2 * layers } };
}

function write(plan: PrintPlan, s: Settings, meta = META): string {
  return gcodeToString(plan, s, estimatePlan(plan, s), meta);
}

const lines = (gcode: string) => gcode.split('\n');

test('M73: P never falls, R never rises, P100 R0 after the last layer, nothing extruded after it', () => {
  for (const flavor of ['marlin', 'klipper', 'reprap'] as const) {
    const s = settings({ gcodeFlavor: flavor, minLayerTime: 0 });
    const plan = twoObjectPlan(40);
    const gcode = write(plan, s);
    const m73 = lines(gcode)
      .map((l, i) => ({ i, m: /^M73 P(\d+) R(\d+)$/.exec(l) }))
      .filter((x) => x.m);
    assert.ok(m73.length >= 3, `${flavor}: M73 lines ${m73.length}`);
    for (let k = 1; k < m73.length; k++) {
      assert.ok(+m73[k]!.m![1]! >= +m73[k - 1]!.m![1]!, `${flavor}: P monotonic`);
      assert.ok(+m73[k]!.m![2]! <= +m73[k - 1]!.m![2]!, `${flavor}: R monotonic`);
    }
    const first = m73[0]!.m!;
    assert.equal(first[1], '0');
    const total = estimatePlan(plan, s).printTimeSeconds;
    assert.equal(+first[2]!, Math.ceil(total / 60), `${flavor}: R at the start is the whole estimate`);
    const last = m73[m73.length - 1]!;
    assert.deepEqual([last.m![1], last.m![2]], ['100', '0']);
    const after = lines(gcode)
      .slice(last.i + 1)
      .join('\n');
    // the end template only retracts: no positive E with an XY move after the 100 %
    const tail = parseGcode('G91\nM83\n' + after.replace(/^G90.*$/gm, ''));
    assert.equal(tail.e.extruded, 0, `${flavor}: extrusion after M73 P100`);
    const body = parseGcode(gcode);
    assert.ok(body.e.extruded > 0);
  }
});

test('M73 can be turned off', () => {
  const gcode = write(twoObjectPlan(), settings({ progressM73: false }));
  assert.ok(!/^M73/m.test(gcode));
});

/** The label blocks of the G-code: which object each extrusion, retraction and travel belongs to. */
function labelledMoves(gcode: string, start: RegExp, end: RegExp) {
  const text = lines(gcode);
  let open: string | null = null;
  let x = 0,
    y = 0,
    z = 0,
    zAtStart = 0,
    lastE = 0;
  const absolute = !/^M83\b/m.test(gcode);
  const inside = new Map<string, Array<[number, number]>>();
  const retractBalance = new Map<string, number>();
  const outsideExtrusions: Array<[number, number]> = [];
  let starts = 0,
    ends = 0;
  for (const l of text) {
    const s = start.exec(l);
    if (s) {
      assert.equal(open, null, `start ${s[1]} inside ${open}`);
      open = s[1]!;
      zAtStart = z;
      starts++;
      continue;
    }
    const e = end.exec(l);
    if (e) {
      assert.equal(e[1] ?? open, open, 'end matches start');
      assert.equal(z, zAtStart, 'a Z hop inside a block comes back down inside it');
      open = null;
      ends++;
      continue;
    }
    if (l.startsWith(';LAYER:')) assert.equal(open, null, 'no object open across a layer change');
    if (l.startsWith('G92 E0')) lastE = 0;
    const m = /^G[0-3] /.exec(l);
    if (!m) continue;
    const nx = /X(-?[\d.]+)/.exec(l),
      ny = /Y(-?[\d.]+)/.exec(l),
      ne = /E(-?[\d.]+)/.exec(l);
    if (nx) x = +nx[1]!;
    if (ny) y = +ny[1]!;
    if (/^G1 F\d+ E/.test(l) || /^G1 E/.test(l)) {
      // absolute E unless the value is negative (relative retraction); a retraction lowers E
      const value = +ne![1]!;
      const retracting = value < 0 || (absolute && value < lastE);
      if (absolute) lastE = value;
      if (open) retractBalance.set(open, (retractBalance.get(open) ?? 0) + (retracting ? 1 : -1));
      continue;
    }
    if (absolute && ne) lastE = +ne[1]!;
    const nz = /Z(-?[\d.]+)/.exec(l);
    if (nz) z = +nz[1]!;
    if (!ne || (!nx && !ny)) continue;
    if (open) {
      if (!inside.has(open)) inside.set(open, []);
      inside.get(open)!.push([x, y]);
    } else outsideExtrusions.push([x, y]);
  }
  assert.equal(open, null, 'every block closed');
  return { inside, retractBalance, outsideExtrusions, starts, ends };
}

const insideBox = ([x, y]: [number, number], poly: [number, number][]) => {
  const xs = poly.map((p) => p[0]),
    ys = poly.map((p) => p[1]);
  return (
    x >= Math.min(...xs) - 1e-6 &&
    x <= Math.max(...xs) + 1e-6 &&
    y >= Math.min(...ys) - 1e-6 &&
    y <= Math.max(...ys) + 1e-6
  );
};

test('Klipper labels: objects defined before the start G-code, START/END balanced per layer, moves inside their polygon', () => {
  const plan = twoObjectPlan();
  const gcode = write(plan, settings({ gcodeFlavor: 'klipper' }));
  const text = lines(gcode);
  const defines = text.filter((l) => l.startsWith('EXCLUDE_OBJECT_DEFINE'));
  assert.deepEqual(defines, [
    'EXCLUDE_OBJECT_DEFINE NAME=left_cube CENTER=25,25 POLYGON=[[20,20],[30,20],[30,30],[20,30]]',
    'EXCLUDE_OBJECT_DEFINE NAME=right_cube CENTER=65,25 POLYGON=[[60,20],[70,20],[70,30],[60,30]]',
  ]);
  assert.ok(
    text.indexOf(defines[1]!) < text.findIndex((l) => l.startsWith('G28')),
    'defined before the start template',
  );
  const r = labelledMoves(gcode, /^EXCLUDE_OBJECT_START NAME=(\S+)$/, /^EXCLUDE_OBJECT_END NAME=(\S+)$/);
  assert.equal(r.starts, 2 * plan.layers.length, 'one block per object per layer');
  assert.equal(r.ends, r.starts);
  const poly = { left_cube: plan.objects[0]!.polygon, right_cube: plan.objects[1]!.polygon };
  for (const [name, moves] of r.inside) {
    assert.ok(moves.length > 0);
    for (const p of moves)
      assert.ok(insideBox(p, poly[name as keyof typeof poly]), `${name}: ${p} outside its polygon`);
  }
  for (const [name, balance] of r.retractBalance)
    assert.equal(balance, 0, `${name}: retractions inside the block are primed inside it`);
  // only the skirt prints outside the blocks
  assert.ok(
    r.outsideExtrusions.length > 0 &&
      r.outsideExtrusions.every((p) => !insideBox(p, poly.left_cube) && !insideBox(p, poly.right_cube)),
  );
});

test('cancelling an object (dropping its blocks) leaves the other object and the E bookkeeping intact', () => {
  for (const extruderMode of ['absolute', 'relative'] as const) {
    const plan = twoObjectPlan();
    const gcode = write(plan, settings({ gcodeFlavor: 'klipper', extruderMode }));
    // what the firmware runs when left_cube is excluded: its blocks skipped (with absolute E, Klipper
    // keeps E continuous by offsetting, which a G92 to the last E skipped stands for here)
    const kept: string[] = [];
    let skipping = false;
    let lastE = '0';
    for (const l of lines(gcode)) {
      if (l === 'EXCLUDE_OBJECT_START NAME=left_cube') skipping = true;
      else if (l === 'EXCLUDE_OBJECT_END NAME=left_cube') {
        skipping = false;
        if (extruderMode === 'absolute') kept.push(`G92 E${lastE}`);
      } else if (!skipping) kept.push(l);
      const e = /^G[0-3] .*E(-?[\d.]+)/.exec(l);
      if (e && extruderMode === 'absolute') lastE = e[1]!;
      if (/^G92 E0/.test(l)) lastE = '0';
    }
    const full = parseGcode(gcode);
    const cancelled = parseGcode(kept.join('\n'));
    assert.equal(cancelled.balance.unbalanced, 0, `${extruderMode}: every retraction primed before extruding`);
    assert.equal(full.balance.unbalanced, 0);
    // the right cube and the skirt are printed as before: exactly the extrusion of the full file minus the left cube's
    const sumRight = (p: ReturnType<typeof parseGcode>) => {
      let e = 0;
      for (const layer of p.layers) {
        const t = layer.extrusions;
        for (let i = 0; i < t.count; i++) if (t.x1[i]! > 40) e += t.e[i]!;
      }
      return e;
    };
    assert.ok(Math.abs(sumRight(cancelled) - sumRight(full)) < 1e-3, `${extruderMode}: right cube unchanged`);
    const all = (p: ReturnType<typeof parseGcode>) =>
      p.layers.reduce((sum, l) => sum + l.extrusions.e.reduce((a, b) => a + b, 0), 0);
    assert.ok(all(cancelled) < all(full) * 0.75, `the left cube is gone: ${all(cancelled)} of ${all(full)}`);
  }
});

test('Marlin and RepRap labels: M486 T count, S index, S-1, and the Cancelobject comments', () => {
  const plan = twoObjectPlan(3);
  const marlin = write(plan, settings({ gcodeFlavor: 'marlin', labelObjects: 'firmware' }));
  assert.match(marlin, /^M486 T2$/m);
  const r = labelledMoves(marlin, /^M486 S(\d+)$/, /^M486 S-1$/);
  assert.equal(r.starts, 6);
  for (const [index, moves] of r.inside) for (const p of moves) assert.ok(insideBox(p, plan.objects[+index]!.polygon));
  const starts = marlin.match(/^; printing object (.+)$/gm)!;
  const stops = marlin.match(/^; stop printing object (.+)$/gm)!;
  assert.equal(starts.length, 6);
  assert.equal(stops.length, 6);
  assert.deepEqual([...new Set(starts)], ['; printing object left cube', '; printing object right cube']);
  const reprap = write(plan, settings({ gcodeFlavor: 'reprap', labelObjects: 'firmware' }));
  assert.match(reprap, /^M486 S1 A"right cube"$/m);
});

test('comment labels only, auto mode per flavour, off, and no objects', () => {
  const plan = twoObjectPlan(2);
  const comments = write(plan, settings({ gcodeFlavor: 'klipper', labelObjects: 'comments' }));
  assert.ok(!/EXCLUDE_OBJECT|M486/.test(comments));
  const r = labelledMoves(comments, /^; printing object (.+)$/, /^; stop printing object (.+)$/);
  assert.equal(r.starts, 4);
  for (const [name, moves] of r.inside)
    for (const p of moves) assert.ok(insideBox(p, plan.objects[name === 'left cube' ? 0 : 1]!.polygon));
  assert.match(
    write(plan, settings({ gcodeFlavor: 'klipper' })),
    /^EXCLUDE_OBJECT_START/m,
    'auto: firmware for Klipper',
  );
  const marlinAuto = write(plan, settings({ gcodeFlavor: 'marlin' }));
  assert.match(marlinAuto, /^; printing object left cube$/m, 'auto: comments for Marlin');
  assert.ok(!/M486/.test(marlinAuto));
  assert.ok(
    !/printing object|EXCLUDE_OBJECT|M486/.test(write(plan, settings({ gcodeFlavor: 'klipper', labelObjects: 'off' }))),
  );
  const anonymous = {
    ...plan,
    objects: [],
    layers: plan.layers.map((l) => ({
      ...l,
      steps: l.steps.map((s) => (s.kind === 'extrude' ? { ...s, object: undefined } : s)),
    })),
  };
  assert.ok(
    !/printing object|EXCLUDE_OBJECT|M486/.test(write(anonymous, settings({ gcodeFlavor: 'klipper' }))),
    'no objects, no labels',
  );
});

test('Klipper names: unsafe characters replaced, duplicates made unique ignoring case', () => {
  const plan = twoObjectPlan(1);
  plan.objects = [
    { ...plan.objects[0]!, name: 'Part #1 (copy)' },
    { ...plan.objects[1]!, name: 'part_1_copy' },
  ];
  const gcode = write(plan, settings({ gcodeFlavor: 'klipper' }));
  assert.match(gcode, /^EXCLUDE_OBJECT_DEFINE NAME=Part_1_copy CENTER/m);
  assert.match(gcode, /^EXCLUDE_OBJECT_DEFINE NAME=part_1_copy_2 CENTER/m);
});

test('firmware retraction: G10/G11 instead of E moves, the same filament as the estimate', () => {
  const plan = twoObjectPlan(3);
  const s = settings({ firmwareRetraction: true, retractionExtraPrime: 0.5 });
  const gcode = write(plan, s);
  const g10 = (gcode.match(/^G10$/gm) ?? []).length;
  assert.ok(g10 > 0);
  assert.equal((gcode.match(/^G11$/gm) ?? []).length, g10);
  const parsed = parseGcode(gcode);
  assert.equal(parsed.balance.firmwareRetractions, g10);
  assert.equal(parsed.balance.unbalanced, 0);
  // the body has no E-only moves; the end template's own retraction is the only one
  const body = gcode.slice(0, gcode.indexOf('M73 P100'));
  assert.ok(!/^G1 (F\d+ )?E/m.test(body.slice(body.indexOf(';LAYER:0'))));
  const est = estimatePlan(plan, s);
  const extruded = parsed.layers.reduce((sum, l) => sum + l.extrusions.e.reduce((a, b) => a + b, 0), 0);
  assert.ok(Math.abs(extruded - est.filamentMm) < 1e-3, `${extruded} vs ${est.filamentMm}`);
});

test('pressure advance in each flavour, and none when empty', () => {
  const plan = twoObjectPlan(1);
  assert.match(write(plan, settings({ pressureAdvance: 0.045 })), /^M900 K0\.045$/m);
  assert.match(
    write(plan, settings({ gcodeFlavor: 'klipper', pressureAdvance: 0.045 })),
    /^SET_PRESSURE_ADVANCE ADVANCE=0\.045$/m,
  );
  assert.match(write(plan, settings({ gcodeFlavor: 'reprap', pressureAdvance: 0.045 })), /^M572 D0 S0\.045$/m);
  assert.ok(!/M900|SET_PRESSURE_ADVANCE|M572/.test(write(plan, settings())));
});

test('machine limits written per flavour after the start template', () => {
  const plan = twoObjectPlan(1);
  const limits: Partial<Settings> = {
    machineLimits: 'write',
    maxSpeedX: 500,
    maxSpeedY: 400,
    maxSpeedZ: 12,
    maxSpeedE: 120,
    maxAccelerationX: 9000,
    maxAccelerationY: 8000,
    maxAccelerationZ: 500,
    maxAccelerationE: 10000,
    acceleration: 1500,
    travelAcceleration: 2000,
    retractAcceleration: 1250,
    cornerVelocity: 8,
  };
  const marlin = lines(write(plan, settings(limits)));
  const at = (l: string) => marlin.indexOf(l);
  for (const l of ['M201 X9000 Y8000 Z500 E10000', 'M203 X500 Y400 Z12 E120', 'M204 P1500 R1250 T2000', 'M205 X8 Y8']) {
    assert.ok(at(l) > marlin.findIndex((x) => x.startsWith('G28')), `${l} after the start template`);
  }
  const reprap = write(plan, settings({ ...limits, gcodeFlavor: 'reprap' }));
  assert.match(reprap, /^M203 X30000 Y24000 Z720 E7200$/m, 'RepRap feed rates in mm/min');
  assert.match(reprap, /^M566 X480 Y480$/m);
  assert.match(reprap, /^M204 P1500 T2000$/m);
  const klipper = write(plan, settings({ ...limits, gcodeFlavor: 'klipper' }));
  assert.match(klipper, /^SET_VELOCITY_LIMIT VELOCITY=400 ACCEL=1500 SQUARE_CORNER_VELOCITY=8$/m);
  assert.ok(
    !/^M201/m.test(write(plan, settings({ ...limits, machineLimits: 'estimate' }))),
    'estimate only: not written',
  );
});

test('thumbnail blocks carry the exact bytes, in lines of at most 78 base64 characters, before any command', () => {
  const data = new Uint8Array(500);
  for (let i = 0; i < data.length; i++) data[i] = (i * 37 + 11) & 255;
  const gcode = write(twoObjectPlan(1), settings(), {
    ...META,
    thumbnails: [
      { width: 16, height: 16, format: 'QOI', data: data.subarray(0, 100) },
      { width: 300, height: 300, format: 'PNG', data },
    ],
  });
  const blocks = [
    ...gcode.matchAll(/^; (thumbnail(?:_QOI|_JPG)?) begin (\d+)x(\d+) (\d+)\n((?:; [A-Za-z0-9+/=]+\n)+); \1 end$/gm),
  ];
  assert.equal(blocks.length, 2);
  const [qoi, png] = blocks;
  assert.equal(qoi![1], 'thumbnail_QOI');
  assert.equal(png![1], 'thumbnail');
  for (const [block, bytes] of [
    [qoi!, data.subarray(0, 100)],
    [png!, data],
  ] as const) {
    const body = block[5]!
      .split('\n')
      .filter(Boolean)
      .map((l) => l.slice(2));
    assert.ok(body.every((l) => l.length <= THUMBNAIL_LINE_CHARS));
    const text = body.join('');
    assert.equal(text.length, +block[4]!, 'declared length');
    assert.deepEqual(new Uint8Array(Buffer.from(text, 'base64')), bytes);
  }
  assert.ok(gcode.indexOf('; thumbnail end') < gcode.search(/^[GM]\d/m), 'thumbnails come before the first command');
});
