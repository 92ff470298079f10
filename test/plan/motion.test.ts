/**
 * Wipe, coasting and z-hop speed in the move expansion (moves.ts), the G-code they make (move-writer.ts)
 * and the estimate (estimate.ts).
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Pt } from '#strata/geometry/types.js';
import { SCHEMA, SETTING_KEYS, type Settings } from '#strata/settings/schema.js';
import { gcodeToString } from '#strata/gcode/writer.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { estimatePlan } from '#strata/plan/estimate.js';
import { walkPlan, WIPE_SPEED_FACTOR, type MoveSink } from '#strata/plan/moves.js';
import type { ExtrudeStep, PlanStep, PrintPlan } from '#strata/plan/types.js';

function settings(overrides: Partial<Settings> = {}): Settings {
  const values: Record<string, unknown> = {};
  for (const key of SETTING_KEYS) values[key] = SCHEMA[key].default;
  return { ...(values as Settings), ...overrides };
}

const pt = (xMm: number, yMm: number): Pt => ({ x: Math.round(xMm * 1000), y: Math.round(yMm * 1000) });
const line = (points: Pt[], closed = false): ExtrudeStep => ({
  kind: 'extrude',
  feature: 'WALL-OUTER',
  points,
  closed,
  width: 0.4,
  height: 0.2,
  speed: 40,
  flow: 1,
});

function plan(steps: PlanStep[]): PrintPlan {
  return {
    layers: [{ index: 0, z: 0.2, height: 0.2, fan: 0, steps }],
    objects: [],
    bounds: { minX: 0, minY: 0, minZ: 0, maxX: 50, maxY: 50, maxZ: 0.2 },
  };
}

/** An L of 10 + 10 mm, a retracting travel away, a second line. */
function lPlan(zHop = 0): PrintPlan {
  return plan([
    line([pt(10, 10), pt(20, 10), pt(20, 20)]),
    { kind: 'travel', points: [pt(40, 40)], retract: true, zHop, speed: 150 },
    line([pt(40, 40), pt(45, 40)]),
  ]);
}

type Move = { kind: string; x?: number; y?: number; z?: number; length?: number; filament?: number; speed?: number };

function record(p: PrintPlan, s: Settings): Move[] {
  const moves: Move[] = [];
  const sink: MoveSink = {
    layerStart() {},
    layerEnd() {},
    zMove: (z, _d, speed) => moves.push({ kind: 'z', z, speed }),
    travel: (x, y, length, speed) => moves.push({ kind: 'travel', x, y, length, speed }),
    extrudeStart() {},
    extrude: (x, y, length, filament, speed) => moves.push({ kind: 'extrude', x, y, length, filament, speed }),
    extrudeZ: (x, y, z, length, filament) => moves.push({ kind: 'extrudeZ', x, y, z, length, filament }),
    arc: (x, y, _cx, _cy, _cw, length, filament) => moves.push({ kind: 'arc', x, y, length, filament }),
    retract: (filament, speed) => moves.push({ kind: 'retract', filament, speed }),
    wipe: (x, y, length, filament, speed) => moves.push({ kind: 'wipe', x, y, length, filament, speed }),
    prime: (filament, speed) => moves.push({ kind: 'prime', filament, speed }),
    objectStart() {},
    objectEnd() {},
  };
  walkPlan(p, s, sink);
  return moves;
}

const sum = (moves: Move[], kind: string, key: 'filament' | 'length') =>
  moves.filter((m) => m.kind === kind).reduce((a, m) => a + m[key]!, 0);
const near = (a: number, b: number, eps = 1e-9) => assert.ok(Math.abs(a - b) <= eps, `${a} ≉ ${b}`);

test('wipe: back along the path just printed, for wipeDistance, retracting the rest of the retraction on the way', () => {
  const s = settings({ wipeDistance: 3, retractBeforeWipe: 40, retractionDistance: 5 });
  const moves = record(lPlan(), s);
  const i = moves.findIndex((m) => m.kind === 'retract');
  // 40 % on the spot, then the wipe from (20, 20) down the second leg of the L to (20, 17)
  near(moves[i]!.filament!, 2);
  const wipes = moves.filter((m) => m.kind === 'wipe');
  assert.ok(wipes.length >= 1);
  for (const w of wipes) {
    assert.equal(w.x, 20000, 'on the path (x = 20)');
    assert.ok(w.y! >= 17000 - 1e-6 && w.y! <= 20000);
  }
  near(sum(moves, 'wipe', 'length'), 3);
  near(wipes[wipes.length - 1]!.y!, 17000, 1e-6);
  near(sum(moves, 'wipe', 'filament'), 3);
  // nothing more is retracted after the wipe, and the prime gives back all 5 mm
  assert.equal(moves.filter((m) => m.kind === 'retract').length, 1);
  near(sum(moves, 'prime', 'filament'), 5);
  // the travel starts at the wipe's end
  const travel = moves.find((m) => m.kind === 'travel' && m.x === 40000)!;
  near(travel.length!, Math.hypot(20, 23), 1e-6);
  // 80 % of the travel speed unless the retraction would outrun retractionSpeed: 45 × 3 / 3 = 45 mm/s
  near(wipes[0]!.speed!, Math.min(150 * WIPE_SPEED_FACTOR, (45 * 3) / 3));
});

test('wipe: round the corner of the path, and a path shorter than the wipe retracts the rest at its end', () => {
  const s = settings({ wipeDistance: 14, retractionDistance: 4 });
  const moves = record(lPlan(), s);
  const wipes = moves.filter((m) => m.kind === 'wipe');
  assert.deepEqual(
    wipes.map((w) => [w.x, w.y]),
    [
      [20000, 10000],
      [16000, 10000],
    ],
  );
  near(sum(moves, 'wipe', 'filament'), 4);
  // the L is 20 mm: all 14 mm wiped. A 5 mm line can only wipe 5: 5/14 of the retraction on the way, the rest after
  const short = plan([
    line([pt(10, 10), pt(15, 10)]),
    { kind: 'travel', points: [pt(40, 40)], retract: true, zHop: 0, speed: 150 },
    line([pt(40, 40), pt(45, 40)]),
  ]);
  const m2 = record(short, s);
  near(sum(m2, 'wipe', 'length'), 5);
  near(sum(m2, 'wipe', 'filament'), (4 * 5) / 14);
  near(sum(m2, 'retract', 'filament') + sum(m2, 'wipe', 'filament'), 4);
  near(sum(m2, 'prime', 'filament'), 4);
});

test('wipe with firmware retraction: plain moves, then G10; E stays balanced in the G-code', () => {
  const s = settings({ wipeDistance: 2, firmwareRetraction: true });
  const gcode = gcodeToString(lPlan(), s, estimatePlan(lPlan(), s), { generator: 'test' });
  const body = gcode.slice(gcode.indexOf(';LAYER:0'));
  const g10 = body.indexOf('\nG10\n');
  assert.ok(g10 > 0);
  const before = body.slice(0, g10).trim().split('\n');
  assert.match(before[before.length - 1]!, /^G1 (F\d+ )?(X20 )?Y18$/, 'the wipe, without E, just before G10');
  assert.ok(body.indexOf('\nG11\n') > g10);
});

test('coasting: the last coastingVolume / (width × height) mm of an extrusion before a retraction is a plain move ending where the travel starts', () => {
  // 0.04 mm³ over 0.4 × 0.2 mm: 0.5 mm
  const s = settings({ coastingVolume: 0.04, coastingMinVolume: 0 });
  const moves = record(lPlan(), s);
  const k = moves.findIndex((m) => m.kind === 'retract');
  const coast = moves[k - 1]!;
  assert.equal(coast.kind, 'travel');
  assert.deepEqual([coast.x, coast.y], [20000, 20000], 'ends at the path end');
  near(coast.length!, 0.5);
  assert.equal(coast.speed, 40, "at the extrusion's speed");
  const cut = moves[k - 2]!;
  assert.equal(cut.kind, 'extrude');
  near(cut.y!, 19500, 1e-6);
  const perMm = (0.4 * 0.2) / (Math.PI * 0.875 * 0.875);
  const plain = record(lPlan(), settings());
  // the volume removed is the coasting volume, from the first extrusion only (the second has no retraction after it)
  near((sum(plain, 'extrude', 'filament') - sum(moves, 'extrude', 'filament')) * Math.PI * 0.875 * 0.875, 0.04, 1e-9);
  near(cut.filament!, 9.5 * perMm, 1e-9);
  // the travel after starts at the path end
  const travel = moves[k + 1]!;
  assert.equal(travel.kind, 'travel');
  near(travel.length!, Math.hypot(20, 20), 1e-6);
});

test('coasting keeps off paths shorter than twice the coasted length or under coastingMinVolume', () => {
  const shortPlan = () =>
    plan([
      line([pt(10, 10), pt(10.8, 10)]),
      { kind: 'travel', points: [pt(40, 40)], retract: true, zHop: 0, speed: 150 },
    ]);
  // 0.5 mm coast on a 0.8 mm line: would leave less than half
  const m1 = record(shortPlan(), settings({ coastingVolume: 0.04, coastingMinVolume: 0 }));
  assert.equal(m1.filter((m) => m.kind === 'extrude').length, 1);
  near(m1.find((m) => m.kind === 'extrude')!.x!, 10800);
  // the L is 20 mm × 0.4 × 0.2 = 1.6 mm³: a minimum of 2 mm³ leaves it whole
  const m2 = record(lPlan(), settings({ coastingVolume: 0.04, coastingMinVolume: 2 }));
  assert.ok(!m2.some((m) => m.kind === 'travel' && m.length! < 1));
  // no coasting before a travel that does not retract
  const noRetract = plan([
    line([pt(10, 10), pt(20, 10)]),
    { kind: 'travel', points: [pt(40, 40)], retract: false, zHop: 0, speed: 150 },
  ]);
  assert.ok(
    !record(noRetract, settings({ coastingVolume: 0.04, coastingMinVolume: 0 })).some(
      (m) => m.kind === 'travel' && m.length! < 1,
    ),
  );
});

test('coasting on a closed loop ends at its start point', () => {
  const loop = plan([
    line([pt(10, 10), pt(20, 10), pt(20, 20), pt(10, 20)], true),
    { kind: 'travel', points: [pt(40, 40)], retract: true, zHop: 0, speed: 150 },
  ]);
  const moves = record(loop, settings({ coastingVolume: 0.08, coastingMinVolume: 0 }));
  const k = moves.findIndex((m) => m.kind === 'retract');
  assert.deepEqual([moves[k - 1]!.x, moves[k - 1]!.y], [10000, 10000]);
  near(moves[k - 1]!.length!, 1);
});

test('z-hop moves Z at zHopSpeed (capped at maxSpeedZ); unset, at the standalone Z speed', () => {
  const hops = (s: Settings) => {
    const gcode = gcodeToString(lPlan(0.4), s, estimatePlan(lPlan(0.4), s), { generator: 'test' });
    return gcode.split('\n').filter((l) => /^G0 .*Z0\.6$/.test(l) || /^G0 .*Z0\.2$/.test(l));
  };
  assert.ok(hops(settings()).some((l) => l.includes('F300')));
  const fast = hops(settings({ zHopSpeed: 12 }));
  assert.ok(fast.length >= 2);
  const gcode = gcodeToString(
    lPlan(0.4),
    settings({ zHopSpeed: 12 }),
    estimatePlan(lPlan(0.4), settings({ zHopSpeed: 12 })),
    { generator: 'test' },
  );
  assert.match(gcode, /G0 F720 Z0\.6\n/);
  const capped = gcodeToString(
    lPlan(0.4),
    settings({ zHopSpeed: 12, maxSpeedZ: 8 }),
    estimatePlan(lPlan(0.4), settings({ zHopSpeed: 12, maxSpeedZ: 8 })),
    { generator: 'test' },
  );
  assert.match(capped, /G0 F480 Z0\.6\n/);
  // a faster hop takes less time
  near(
    estimatePlan(lPlan(0.4), settings()).printTimeSeconds >
      estimatePlan(lPlan(0.4), settings({ zHopSpeed: 12 })).printTimeSeconds
      ? 1
      : 0,
    1,
  );
});

test('wipe and coasting: the G-code parses back balanced (Marlin and Klipper, absolute and relative E) and the estimate counts the moves', () => {
  for (const gcodeFlavor of ['marlin', 'klipper'] as const) {
    for (const extruderMode of ['absolute', 'relative'] as const) {
      const s = settings({
        gcodeFlavor,
        extruderMode,
        wipeDistance: 2,
        retractBeforeWipe: 20,
        coastingVolume: 0.04,
        coastingMinVolume: 0,
        zHop: 0.4,
      });
      const p = lPlan(0.4);
      const est = estimatePlan(p, s);
      const parsed = parseGcode(gcodeToString(p, s, est, { generator: 'test' }));
      assert.equal(parsed.balance.unbalanced, 0, `${gcodeFlavor} ${extruderMode}`);
      // the end G-code's retraction is left pending: everything before it was primed
      assert.equal(
        parsed.balance.retractions,
        2,
        'the retraction spread over the wipe counts once (and the end G-code one)',
      );
      near(parsed.e.retracted - parsed.balance.trailingMm, 5, 2e-5);
      near(parsed.e.primed, 5, 2e-5);
      const plain = estimatePlan(p, settings({ gcodeFlavor, extruderMode, zHop: 0.4 }));
      // the wipe is timed: more or less than the plain retraction (Marlin's planner runs the wipe on from the
      // extrusion through a junction, where a retraction on the spot stops the head first)
      assert.ok(
        Math.abs(est.printTimeSeconds - plain.printTimeSeconds) > 0.005,
        `the wipe is timed (${est.printTimeSeconds} against ${plain.printTimeSeconds} s)`,
      );
      assert.ok(Math.abs(est.printTimeSeconds - plain.printTimeSeconds) < 1, 'a little');
      near(plain.filamentMm - est.filamentMm, 0.04 / (Math.PI * 0.875 * 0.875), 1e-9);
    }
  }
});
