/**
 * Objects with settings of their own, modifiers, negative volumes, support blockers and enforcers, layer
 * ranges and overlapping objects, sliced end to end from meshes made here and judged from the G-code alone:
 * the infill density inside and outside a box (the FILL lines' filament over the box's area and the layer
 * height), extrusion inside a hole, support under an overhang, filament totals, object labels.
 *
 * The measurement is tested first, on a plain slice at two densities, so the bars cannot pass by measuring
 * nothing.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer, type ObjectOptions } from '#strata/api/slicer.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { Feature } from '../../tools/analysis/feature-names.js';
import type { ParsedGcode } from '../../tools/analysis/gcode-types.js';
import { StrataError } from '#strata/errors.js';
import { box, join, type Arrays } from './test-meshes.js';

const BASE = { threads: 1, center: false, adhesionType: 'none', infillPattern: 'lines' } as const;
const FILAMENT_AREA = (Math.PI * 1.75 * 1.75) / 4;

interface Rect {
  x0: number;
  y0: number;
  x1: number;
  y1: number;
}

/** Length of the segment inside the rectangle (Liang–Barsky). */
function clipLength(ax: number, ay: number, bx: number, by: number, r: Rect): number {
  let t0 = 0,
    t1 = 1;
  const dx = bx - ax,
    dy = by - ay;
  for (const [p, q] of [
    [-dx, ax - r.x0],
    [dx, r.x1 - ax],
    [-dy, ay - r.y0],
    [dy, r.y1 - ay],
  ]) {
    if (p === 0) {
      if (q < 0) return 0;
    } else {
      const t = q / p;
      if (p < 0) t0 = Math.max(t0, t);
      else t1 = Math.min(t1, t);
    }
  }
  return t1 > t0 ? (t1 - t0) * Math.hypot(dx, dy) : 0;
}

/** The layer printed at Z (within half a layer). */
function layerAt(g: ParsedGcode, z: number) {
  const l = g.layers.find((x) => Math.abs(x.z - z) < 0.1);
  assert.ok(l, `a layer at Z ${z}`);
  return l;
}

/** Filament (mm³) of the features inside the rectangle on the layer at Z. */
function volumeIn(g: ParsedGcode, z: number, r: Rect, features: readonly number[]): number {
  const t = layerAt(g, z).extrusions;
  let v = 0;
  for (let i = 0; i < t.count; i++) {
    if (!features.includes(t.feature[i])) continue;
    const len = Math.hypot(t.x1[i] - t.x0[i], t.y1[i] - t.y0[i]);
    if (len === 0) continue;
    v += (t.e[i] * FILAMENT_AREA * clipLength(t.x0[i], t.y0[i], t.x1[i], t.y1[i], r)) / len;
  }
  return v;
}

/** Sparse infill density (%) in the rectangle on the layer at Z, 0.2 mm layers. */
function densityIn(g: ParsedGcode, z: number, r: Rect): number {
  return (100 * volumeIn(g, z, r, [Feature.Fill])) / ((r.x1 - r.x0) * (r.y1 - r.y0) * 0.2);
}

/** Every extrusion's filament (mm³) in the rectangle on the layer at Z. */
function anyIn(g: ParsedGcode, z: number, r: Rect): number {
  const all: number[] = Object.values(Feature);
  return volumeIn(g, z, r, all);
}

async function slice(input: unknown, options: Record<string, unknown> = {}) {
  const r = await new Slicer({ ...BASE, ...options } as never).slice(input);
  return { ...r, g: parseGcode(r.gcode) };
}

async function sliceObjects(
  objects: Array<[Arrays, ObjectOptions]>,
  options: Record<string, unknown> = {},
  threads = 1,
) {
  const s = new Slicer({ ...BASE, threads, ...options } as never);
  for (const [mesh, o] of objects) s.addObject(mesh, o);
  const r = await s.slice();
  return { ...r, g: parseGcode(r.gcode) };
}

const within = (got: number, want: number, tol: number, what: string) =>
  assert.ok(Math.abs(got - want) <= tol, `${what}: ${got.toFixed(1)} %, expected ${want} ± ${tol}`);

// a 40 × 20 × 10 mm bar at (50..90, 50..70); its left and right halves' middles, clear of walls
const BAR = box(50, 50, 0, 90, 70, 10);
const LEFT: Rect = { x0: 54, y0: 54, x1: 66, y1: 66 };
const RIGHT: Rect = { x0: 74, y0: 54, x1: 86, y1: 66 };
const MID_Z = 5;

test('the density measurement reads what a plain slice sets', async () => {
  for (const density of [15, 60]) {
    const { g } = await slice(BAR, { infillDensity: density });
    within(densityIn(g, MID_Z, LEFT), density, density * 0.15 + 1, `left at ${density} %`);
    within(densityIn(g, MID_Z, RIGHT), density, density * 0.15 + 1, `right at ${density} %`);
  }
});

test('a modifier gives its region its own infill density; outside it the object keeps its own', async () => {
  const { g, warnings } = await sliceObjects([
    [
      BAR,
      {
        settings: { infillDensity: 15 },
        volumes: [{ type: 'modifier', mesh: box(70, 40, -1, 100, 80, 20), settings: { infillDensity: 80 } }],
      },
    ],
  ]);
  within(densityIn(g, MID_Z, LEFT), 15, 4, 'outside the modifier');
  within(densityIn(g, MID_Z, RIGHT), 80, 12, 'inside the modifier');
  // the modifier itself is not printed: nothing beyond the part
  assert.ok(g.extents && g.extents.max[0] <= 90.01 && g.extents.max[2] <= 10.01, JSON.stringify(g.extents));
  assert.deepEqual(
    warnings.filter((w) => /modifier/.test(w)),
    [],
  );
});

test('a modifier that changes the walls gets walls of its own round its region', async () => {
  const { g } = await sliceObjects([
    [BAR, { volumes: [{ type: 'modifier', mesh: box(70, 40, -1, 100, 80, 20), settings: { wallCount: 4 } }] }],
  ]);
  const walls = (r: Rect) => volumeIn(g, MID_Z, r, [Feature.WallOuter, Feature.WallInner]);
  // along the bar's long side, in a strip 3 mm deep: 2 walls on the left, 4 on the right
  const left = walls({ x0: 55, y0: 49, x1: 65, y1: 53 }),
    right = walls({ x0: 75, y0: 49, x1: 85, y1: 53 });
  assert.ok(right > 1.7 * left, `walls on the right ${right.toFixed(2)} mm³, left ${left.toFixed(2)} mm³`);
});

test('a negative volume leaves its hole, with walls round it', async () => {
  const { g } = await sliceObjects([[BAR, { volumes: [{ type: 'negative', mesh: box(66, 56, -1, 74, 64, 11) }] }]]);
  assert.equal(anyIn(g, MID_Z, { x0: 67, y0: 57, x1: 73, y1: 63 }), 0, 'nothing printed inside the hole');
  assert.ok(
    volumeIn(g, MID_Z, { x0: 64, y0: 54, x1: 67, y1: 66 }, [Feature.WallOuter, Feature.WallInner]) > 0.5,
    'walls along the hole',
  );
  assert.ok(g.extents && Math.abs(g.extents.max[2] - 10) < 0.01, JSON.stringify(g.extents));
});

test('a layer range gets its settings on its layers only', async () => {
  const { g } = await sliceObjects([
    [BAR, { settings: { infillDensity: 15 }, layerRanges: [{ fromZ: 4, toZ: 6, settings: { infillDensity: 60 } }] }],
  ]);
  within(densityIn(g, 5, LEFT), 60, 9, 'inside the range');
  within(densityIn(g, 3, LEFT), 15, 4, 'below the range');
  within(densityIn(g, 7.6, LEFT), 15, 4, 'above the range');
});

test('two objects keep their own densities, and each is labelled', async () => {
  const { g, gcode } = await sliceObjects([
    [box(40, 50, 0, 60, 70, 10), { name: 'dense', settings: { infillDensity: 40 } }],
    [box(80, 50, 0, 100, 70, 10), { name: 'light', settings: { infillDensity: 15 } }],
  ]);
  within(densityIn(g, MID_Z, { x0: 44, y0: 54, x1: 56, y1: 66 }), 40, 6, 'dense');
  within(densityIn(g, MID_Z, { x0: 84, y0: 54, x1: 96, y1: 66 }), 15, 4, 'light');
  assert.match(gcode, /printing object dense/);
  assert.match(gcode, /printing object light/);
});

test('overlapping objects with the same settings print once: no more filament than their union', async () => {
  const a = box(50, 50, 0, 70, 70, 20),
    b = box(60, 50, 0, 80, 70, 20);
  const two = await slice([a, b]);
  const union = await slice(box(50, 50, 0, 80, 70, 20));
  const mm = (r: { stats: { filamentMm: number } }) => r.stats.filamentMm;
  assert.ok(
    mm(two) <= mm(union) * 1.01,
    `two overlapping cubes ${mm(two).toFixed(0)} mm of filament, their union ${mm(union).toFixed(0)} mm`,
  );
  assert.ok(
    two.warnings.some((w) => /print as one object/.test(w)),
    two.warnings.join('\n'),
  );
});

test('overlapping objects with different settings are refused, naming both', async () => {
  await assert.rejects(
    sliceObjects([
      [box(50, 50, 0, 70, 70, 10), { name: 'left', settings: { infillDensity: 40 } }],
      [box(60, 50, 0, 80, 70, 10), { name: 'right', settings: { infillDensity: 10 } }],
    ]),
    (e: unknown) =>
      e instanceof StrataError &&
      e.code === 'OVERLAPPING_OBJECTS' &&
      /"left"/.test(e.message) &&
      /"right"/.test(e.message),
  );
});

// a pillar with a shelf reaching out to each side from 6 mm up
const SHELVES = join(box(60, 55, 0, 70, 65, 8), box(45, 55, 6, 85, 65, 8));
const UNDER_LEFT: Rect = { x0: 47, y0: 56, x1: 57, y1: 64 };
const UNDER_RIGHT: Rect = { x0: 73, y0: 56, x1: 83, y1: 64 };
const supportUnder = (g: ParsedGcode, r: Rect) => volumeIn(g, 3, r, [Feature.Support, Feature.SupportInterface]);

test('a support blocker keeps support from its overhang while the other overhang is held', async () => {
  const plain = await sliceObjects([[SHELVES, { settings: { supportEnabled: true } }]]);
  assert.ok(
    supportUnder(plain.g, UNDER_LEFT) > 1 && supportUnder(plain.g, UNDER_RIGHT) > 1,
    'both shelves held without a blocker',
  );
  const blocked = await sliceObjects([
    [
      SHELVES,
      { settings: { supportEnabled: true }, volumes: [{ type: 'support-blocker', mesh: box(40, 50, 0, 58, 70, 10) }] },
    ],
  ]);
  assert.equal(supportUnder(blocked.g, UNDER_LEFT), 0, 'no support under the blocked shelf');
  assert.ok(supportUnder(blocked.g, UNDER_RIGHT) > 1, 'the other shelf still held');
});

test('a support enforcer holds its overhang with support otherwise off', async () => {
  const { g } = await sliceObjects([
    [SHELVES, { volumes: [{ type: 'support-enforcer', mesh: box(72, 50, 0, 90, 70, 10) }] }],
  ]);
  assert.equal(supportUnder(g, UNDER_LEFT), 0, 'support stays off outside the enforcer');
  assert.ok(supportUnder(g, UNDER_RIGHT) > 1, 'the enforced shelf is held');
});

test("with several objects each object's support prints inside its label", async () => {
  const { gcode } = await sliceObjects([
    [SHELVES, { name: 'shelves', settings: { supportEnabled: true } }],
    [box(100, 55, 0, 110, 65, 8), { name: 'block' }],
  ]);
  let inside: string | null = null;
  let supportLines = 0;
  for (const line of gcode.split('\n')) {
    const start = /^; printing object (\S+)/.exec(line);
    if (start) inside = start[1];
    else if (/^; stop printing object/.test(line)) inside = null;
    else if (/^;TYPE:SUPPORT/.test(line)) {
      supportLines++;
      assert.equal(inside, 'shelves', 'support printed inside the label of the object it holds');
    }
  }
  assert.ok(supportLines > 5);
});

test('objects with modifiers give the same G-code on one thread and on three', async () => {
  const objects: Array<[Arrays, ObjectOptions]> = [
    [
      BAR,
      {
        settings: { infillDensity: 15, supportEnabled: true },
        volumes: [
          { type: 'modifier', mesh: box(70, 40, -1, 100, 80, 20), settings: { infillDensity: 80, wallCount: 3 } },
          { type: 'negative', mesh: box(66, 56, 2, 74, 64, 11) },
        ],
      },
    ],
  ];
  const one = await sliceObjects(objects, {}, 1);
  const three = await sliceObjects(objects, {}, 3);
  assert.equal(one.gcode.replace(/^;.*time.*$/gm, ''), three.gcode.replace(/^;.*time.*$/gm, ''));
});

test('settings that cannot vary where they are given are refused, one clear error each', () => {
  const s = new Slicer({ threads: 1 });
  const bad = (o: ObjectOptions, re: RegExp) =>
    assert.throws(
      () => s.addObject(BAR, o),
      (e: unknown) =>
        e instanceof StrataError && e.code !== undefined && re.test(e.message) && !e.message.includes('\n'),
    );
  bad(
    { name: 'a', settings: { nozzleTemperature: 210 } },
    /object "a": nozzleTemperature is the same for the whole print/,
  );
  bad(
    { name: 'b', volumes: [{ type: 'modifier', mesh: box(0, 0, 0, 1, 1, 1), settings: { topSkinThickness: 2 } }] },
    /topSkinThickness may vary per object but not inside one/,
  );
  bad({ name: 'c', settings: { infillDensity: 140 } }, /infillDensity = 140 is not allowed/);
  bad(
    { name: 'd', settings: { infillDensty: 40 } as never },
    /unknown object "d" setting "infillDensty" \(did you mean "infillDensity"\?\)/,
  );
  bad(
    { name: 'e', layerRanges: [{ fromZ: 1, toZ: 2, settings: { supportEnabled: true } }] },
    /supportEnabled may vary per object but not inside one/,
  );
});

test('a saved project slices to the same G-code, also when the print turned and scaled its models', async () => {
  const options = { ...BASE, center: true, rotateZ: 90, scale: 1.5 };
  const s = new Slicer(options as never).addObject(BAR, {
    settings: { infillDensity: 25 },
    volumes: [{ type: 'modifier', mesh: box(70, 40, -1, 100, 80, 20), settings: { infillDensity: 70 } }],
  });
  const direct = await s.slice();
  const project = await s.saveProject();
  const again = await new Slicer({ threads: 1 }).slice(project);
  assert.equal(again.gcode, direct.gcode);
  assert.ok(
    again.warnings.every((w) => !/ignored/.test(w)),
    again.warnings.join('\n'),
  );
});
