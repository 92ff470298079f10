/**
 * Spiral vase mode end to end, on solid cylinders made here (a vase is sliced from a solid: only its outside
 * is printed): the plan's turns and the G-code read back as text and with the analyser's parser. After the
 * bottom layers every layer is one outer wall whose Z rises round the turn by one layer height and never
 * falls, with no travel, retraction or other feature; the flow ramps up on the first turn and down on the
 * flat finishing turn; settings the vase sets aside are reported; layers that are not one loop print flat and
 * are reported; and with the setting off the G-code is the same as without it.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer } from '#strata/api/slicer.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { parseArgs } from '#strata/cli/args.js';
import type { Mesh } from '#strata/mesh/types.js';
import type { ExtrudeStep, PrintPlan } from '#strata/plan/types.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { box } from './test-meshes.js';

/** A solid cylinder of radius r standing on the bed, h tall, n sides, centred at (cx, cy). Closed, facing outwards. */
function cylinder(r: number, h: number, n = 96, cx = 0, cy = 0): Mesh {
  const positions = [cx, cy, 0, cx, cy, h];
  const indices: number[] = [];
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n;
    positions.push(cx + r * Math.cos(a), cy + r * Math.sin(a), 0, cx + r * Math.cos(a), cy + r * Math.sin(a), h);
  }
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    const b0 = 2 + 2 * i,
      t0 = b0 + 1,
      b1 = 2 + 2 * j,
      t1 = b1 + 1;
    indices.push(0, b1, b0, 1, t0, t1, b0, b1, t1, b0, t1, t0);
  }
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices) };
}

/** A tube (a cylinder with a round hole through it). */
function tube(R: number, r: number, h: number, n = 96): Mesh {
  const positions: number[] = [];
  const ring = (radius: number, z: number) =>
    Array.from({ length: n }, (_, i) => {
      const a = (2 * Math.PI * i) / n;
      positions.push(radius * Math.cos(a), radius * Math.sin(a), z);
      return positions.length / 3 - 1;
    });
  const o0 = ring(R, 0),
    o1 = ring(R, h),
    i0 = ring(r, 0),
    i1 = ring(r, h);
  const indices: number[] = [];
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    indices.push(o0[i], o0[j], o1[j], o0[i], o1[j], o1[i]);
    indices.push(i0[j], i0[i], i1[i], i0[j], i1[i], i1[j]);
    indices.push(o1[i], o1[j], i1[j], o1[i], i1[j], i1[i]);
    indices.push(o0[j], o0[i], i0[i], o0[j], i0[i], i0[j]);
  }
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices) };
}

/**
 * A cup modelled hollow: an outer cylinder of radius R, h tall, with a round hole of radius r from its solid
 * floor (z = base) to the top, so every layer above the floor is a ring (an island with a hole). Closed,
 * facing outwards (the hole's wall faces the axis).
 */
function cup(R: number, r: number, base: number, h: number, n = 96): Mesh {
  const positions: number[] = [0, 0, 0, 0, 0, base];
  const ring = (radius: number, z: number) =>
    Array.from({ length: n }, (_, i) => {
      const a = (2 * Math.PI * i) / n;
      positions.push(radius * Math.cos(a), radius * Math.sin(a), z);
      return positions.length / 3 - 1;
    });
  const o0 = ring(R, 0),
    o1 = ring(R, h),
    f = ring(r, base),
    i1 = ring(r, h);
  const indices: number[] = [];
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    indices.push(o0[i], o0[j], o1[j], o0[i], o1[j], o1[i]); // outside
    indices.push(f[j], f[i], i1[i], f[j], i1[i], i1[j]); // the hole's wall
    indices.push(o1[i], o1[j], i1[j], o1[i], i1[j], i1[i]); // the rim
    indices.push(0, o0[j], o0[i]); // underneath
    indices.push(1, f[i], f[j]); // the floor inside
  }
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices) };
}

function join(a: Mesh, b: Mesh): Mesh {
  const offset = a.positions.length / 3;
  const indices = new Uint32Array(a.indices.length + b.indices.length);
  indices.set(a.indices);
  for (let k = 0; k < b.indices.length; k++) indices[a.indices.length + k] = b.indices[k] + offset;
  const positions = new Float32Array(a.positions.length + b.positions.length);
  positions.set(a.positions);
  positions.set(b.positions, a.positions.length);
  return { positions, indices };
}

const VASE = cylinder(15, 6);
/** 0.2 mm layers, four bottom layers (0.8 mm of bottom skin), the default. */
const BOTTOM = 4;

async function slice(
  mesh: Mesh,
  options: SliceOptions,
): Promise<{ plan: PrintPlan; gcode: string; warnings: string[] }> {
  const chunks: string[] = [];
  const { plan, warnings } = await new Slicer({ threads: 1, ...options }).slicePlan(mesh, {}, (c) => chunks.push(c));
  return { plan, gcode: chunks.join(''), warnings };
}

/** The G-code lines of each `;LAYER:n` block, by n (the end G-code left out). */
function layerBlocks(gcode: string): string[][] {
  const body = gcode.slice(0, gcode.lastIndexOf(';TIME_ELAPSED:'));
  const blocks: string[][] = [];
  let cur: string[] | null = null;
  for (const line of body.split('\n')) {
    const m = /^;LAYER:(\d+)$/.exec(line);
    if (m) blocks[Number(m[1])] = cur = [];
    else cur?.push(line);
  }
  return blocks;
}

function word(line: string, axis: string): number | undefined {
  const m = new RegExp(`\\s${axis}(-?[\\d.]+)`).exec(line);
  return m ? Number(m[1]) : undefined;
}

const FILAMENT_AREA = Math.PI * (1.75 / 2) ** 2;

test('spiral vase: after the bottom, one outer wall per layer rising round the turn by one layer height, with no travel or retraction', async () => {
  const { plan, gcode, warnings } = await slice(VASE, { spiralVase: true });
  assert.deepEqual(warnings, [], 'a single loop on every layer: nothing to report');
  const layers = plan.layers;
  assert.equal(layers.length, 30);
  for (const [i, layer] of layers.entries()) {
    assert.equal(!!layer.spiral, i >= BOTTOM, `layer ${i} spirals only above the bottom`);
    if (!layer.spiral) continue;
    const prev = layers[i - 1];
    const extrusions = layer.steps.filter((s): s is ExtrudeStep => s.kind === 'extrude');
    assert.ok(
      extrusions.every((s) => s.feature === 'WALL-OUTER'),
      'one outer wall, no infill or skin',
    );
    assert.equal(layer.steps.length - extrusions.length, i === BOTTOM ? 1 : 0, 'a travel only onto the first turn');
    // the turn: its rising steps in order, then (on the last layer) the flat finishing turn
    const rising = extrusions.filter((s) => s.z);
    const z: number[] = rising.flatMap((s, k) => [...s.z!].slice(k === 0 ? 0 : 1).map((v) => layer.z + v));
    for (let k = 1; k < z.length; k++)
      assert.ok(z[k] > z[k - 1], `layer ${i}: Z rises at every point of the turn (${k})`);
    assert.ok(Math.abs(z[0] - prev.z) < 1e-9, `layer ${i} starts at the previous layer's Z`);
    assert.ok(Math.abs(z[z.length - 1] - layer.z) < 1e-9, `layer ${i} ends at its own Z`);
    assert.ok(Math.abs(z[z.length - 1] - z[0] - layer.height) < 1e-9, 'the turn rises by one layer height');
    const flat = extrusions.filter((s) => !s.z);
    assert.equal(flat.length > 0, i === layers.length - 1, 'a flat finishing turn on the last layer only');
    // each turn starts where the previous one ended: same XY
    if (i > BOTTOM) {
      const prevEnd = prev.steps.at(-1) as ExtrudeStep;
      assert.deepEqual(rising[0].points[0], prevEnd.points.at(-1));
    }
  }

  // the G-code: Z never falls along the spiral, G1 carries Z on every spiral point, no travel, no retraction
  const blocks = layerBlocks(gcode);
  let lastZ = -Infinity;
  for (let i = BOTTOM + 1; i < blocks.length; i++) {
    for (const line of blocks[i]) {
      assert.ok(!/^G0\b/.test(line), `layer ${i}: no travel or Z move (${line})`);
      assert.ok(
        !/^G1[^;]*\sE-/.test(line) && !/^G1 F\d+ E[\d.]+$/.test(line) && !/^G1[0-1]\b/.test(line),
        `layer ${i}: no retraction or prime (${line})`,
      );
      if (/^;TYPE:/.test(line)) assert.equal(line, ';TYPE:WALL-OUTER');
      if (!/^G1\s/.test(line)) continue;
      const z = word(line, 'Z');
      const flatFinish = i === blocks.length - 1 && z === undefined;
      assert.ok(z !== undefined || flatFinish, `layer ${i}: a spiral G1 has Z (${line})`);
      if (z === undefined) continue;
      assert.ok(z >= lastZ, `Z never falls: ${z} after ${lastZ}`);
      lastZ = z;
    }
  }
  assert.equal(lastZ, 6, 'the spiral ends at the top');
  // no ;TYPE: other than the outer wall after the bottom
  const types = new Set(blocks.slice(BOTTOM).flatMap((b) => b.filter((l) => l.startsWith(';TYPE:'))));
  assert.deepEqual([...types], [';TYPE:WALL-OUTER']);

  // read back by the analyser: one layer per turn, at the turn's top, one layer height apart
  const parsed = parseGcode(gcode);
  assert.equal(parsed.layers.length, 30);
  for (const l of parsed.layers.slice(BOTTOM + 1)) {
    assert.ok(Math.abs(l.thickness - 0.2) < 1e-4, `layer ${l.index} is one layer height thick (${l.thickness})`);
    assert.ok(Math.abs(l.z - (l.index + 1) * 0.2) < 1e-4, `layer ${l.index} is at its turn's top (${l.z})`);
    assert.ok(l.zMax - l.zMin > 0.19, 'Z varies within the layer by about a layer height');
  }
  assert.equal(parsed.balance.unbalanced, 0);
});

test('spiral vase: flow of one wall along the turn, ramped up on the first turn and down on the flat finishing turn', async () => {
  const { gcode } = await slice(VASE, { spiralVase: true });
  // every extruding G1 of each layer: its filament, XY length and Z word (absolute E, from each G92 E0)
  type Move = { e: number; len: number; z: number | undefined };
  const byLayer: Move[][] = [];
  let layer = -1,
    x = NaN,
    y = NaN,
    e = 0;
  for (const line of gcode.split('\n')) {
    const m = /^;LAYER:(\d+)$/.exec(line);
    if (m) byLayer[(layer = Number(m[1]))] = [];
    if (line.startsWith('G92 E0')) e = 0;
    if (!/^G[01]\s/.test(line)) continue;
    const nx = word(line, 'X') ?? x,
      ny = word(line, 'Y') ?? y,
      ne = word(line, 'E');
    if (layer >= 0 && ne !== undefined && ne > e && (nx !== x || ny !== y))
      byLayer[layer].push({ e: ne - e, len: Math.hypot(nx - x, ny - y), z: word(line, 'Z') });
    if (ne !== undefined) e = ne;
    x = nx;
    y = ny;
  }
  const moves = (i: number) => byLayer[i];
  const perMm = (0.4 * 0.2) / FILAMENT_AREA; // one 0.4 mm line 0.2 mm high
  const sum = (ms: Array<{ e: number; len: number }>) =>
    ms.reduce((a, m) => ({ e: a.e + m.e, len: a.len + m.len }), { e: 0, len: 0 });
  const middle = sum(moves(15));
  assert.ok(
    Math.abs(middle.e / middle.len / perMm - 1) < 0.02,
    `a full turn lays one wall: ${(middle.e / middle.len).toFixed(5)} mm/mm, nominal ${perMm.toFixed(5)}`,
  );
  // the first turn: flow from 0 to 1, so half the filament, its first quarter an eighth of a full quarter's
  const first = moves(BOTTOM);
  const firstAll = sum(first);
  assert.ok(
    Math.abs(firstAll.e / (firstAll.len * perMm) - 0.5) < 0.03,
    `the first turn ramps up: ${(firstAll.e / (firstAll.len * perMm)).toFixed(3)} of a full turn`,
  );
  const quarter = sum(first.slice(0, Math.round(first.length / 4)));
  assert.ok(quarter.e / (quarter.len * perMm) < 0.2, 'little flow at its start');
  // the last layer: a full rising turn, then the flat finishing turn with half a turn's filament, ramping down
  const last = moves(29);
  const rising = sum(last.filter((m) => m.z !== undefined));
  const flat = last.filter((m) => m.z === undefined);
  const flatAll = sum(flat);
  assert.ok(Math.abs(rising.e / (rising.len * perMm) - 1) < 0.02);
  assert.ok(
    Math.abs(flatAll.e / (flatAll.len * perMm) - 0.5) < 0.03,
    `the finishing turn ramps down: ${(flatAll.e / (flatAll.len * perMm)).toFixed(3)}`,
  );
  const tail = sum(flat.slice(-Math.round(flat.length / 4)));
  assert.ok(tail.e / (tail.len * perMm) < 0.2, 'little flow at its end');
});

test('spiral vase: settings it sets aside are reported, defaults are not', async () => {
  const set: SliceOptions = {
    spiralVase: true,
    wallCount: 3,
    infillDensity: 25,
    topSkinThickness: 1,
    supportEnabled: true,
    ironingEnabled: true,
    scarfSeam: 'outer',
    retractOnLayerChange: true,
    zHop: 0.4,
  };
  const { plan, warnings } = await slice(VASE, set);
  const vase = warnings.filter((w) => w.startsWith('spiral vase:'));
  assert.equal(vase.length, 1, warnings.join('\n'));
  for (const key of [
    'wallCount = 3',
    'infillDensity = 25',
    'topSkinThickness = 1',
    'supportEnabled = true',
    'ironingEnabled = true',
    'scarfSeam = outer',
    'retractOnLayerChange = true',
    'zHop = 0.4',
  ]) {
    assert.ok(vase[0].includes(key), `${key} is named: ${vase[0]}`);
  }
  // and they are set aside: above the bottom the same turns as with the defaults (started elsewhere, as the
  // bottom ends elsewhere with its walls and infill as set)
  const plain = await slice(VASE, { spiralVase: true });
  const turns = (p: PrintPlan) =>
    p.layers.slice(BOTTOM + 1).map((l) => {
      let length = 0;
      for (const st of l.steps)
        if (st.kind === 'extrude')
          for (let k = 1; k < st.points.length; k++)
            length += Math.hypot(st.points[k].x - st.points[k - 1].x, st.points[k].y - st.points[k - 1].y);
      return {
        spiral: l.spiral,
        steps: l.steps.map((st) => (st.kind === 'extrude' ? st.feature : 'travel')).join(),
        mm: Math.round(length / 100) / 10,
      };
    });
  // the same turns, their lengths to a tenth of a millimetre (a turn starts where the bottom's last path ended)
  const mine = turns(plan),
    theirs = turns(plain.plan);
  assert.deepEqual(
    mine.map(({ spiral, steps }) => ({ spiral, steps })),
    theirs.map(({ spiral, steps }) => ({ spiral, steps })),
  );
  for (let k = 0; k < mine.length; k++)
    assert.ok(Math.abs(mine[k].mm - theirs[k].mm) <= 0.15, `turn ${k}: ${mine[k].mm} against ${theirs[k].mm} mm`);
  // one wall and settings the vase uses as they are: nothing to report
  const quiet = await slice(VASE, { spiralVase: true, wallCount: 1, infillDensity: 0, zHop: 0 });
  assert.deepEqual(quiet.warnings, []);
});

test('spiral vase off: the G-code is the same as without the setting', async () => {
  const without = await slice(VASE, {});
  const off = await slice(VASE, { spiralVase: false });
  assert.equal(off.gcode, without.gcode);
  assert.ok(without.plan.layers.every((l) => !l.spiral));
  // and on, it is not
  assert.notEqual((await slice(VASE, { spiralVase: true })).gcode, without.gcode);
});

test('spiral vase: layers that are not one loop (two islands, a hole) print flat and are reported; no bottom, a tiny model, arcs', async () => {
  // two cylinders: two islands on every layer, nothing spirals
  const two = await slice(join(cylinder(8, 3, 64, -12, 0), cylinder(8, 3, 64, 12, 0)), { spiralVase: true });
  assert.ok(two.plan.layers.every((l) => !l.spiral));
  assert.ok(
    two.warnings.some((w) => /^spiral vase: 11 layers between 4 and 14 .* print flat/.test(w)),
    two.warnings.join('\n'),
  );
  // a tube, a hole on every layer: the hole is dropped above the bottom, and the outside spirals
  const hollow = await slice(tube(12, 8, 3), { spiralVase: true });
  assert.ok(hollow.plan.layers.every((l, i) => !!l.spiral === i >= BOTTOM));
  assert.deepEqual(hollow.warnings, []);
  for (const l of hollow.plan.layers.slice(BOTTOM))
    assert.ok(l.steps.every((s) => s.kind === 'travel' || s.feature === 'WALL-OUTER'));

  // no bottom: the first layer is one flat loop, the spiral starts on the second
  const open = await slice(VASE, { spiralVase: true, bottomSkinThickness: 0 });
  assert.ok(!open.plan.layers[0].spiral && open.plan.layers.slice(1).every((l) => l.spiral));
  assert.ok(
    open.plan.layers[0].steps.every((s) => s.kind === 'travel' || s.feature === 'WALL-OUTER' || s.feature === 'SKIRT'),
  );
  // a model as thin as two layers, and one of a single layer: no turn above its bottom, or one
  for (const h of [0.2, 0.4, 1]) {
    const tiny = await slice(cylinder(10, h), { spiralVase: true });
    assert.equal(tiny.plan.layers.length, Math.round(h / 0.2));
    assert.equal(tiny.plan.layers.filter((l) => l.spiral).length, Math.max(0, Math.round(h / 0.2) - BOTTOM));
  }
  // arc fitting leaves the rising turns alone (an arc would drop their Z)
  const arcs = await slice(VASE, { spiralVase: true, arcFitting: true });
  for (const l of arcs.plan.layers.filter((l) => l.spiral))
    for (const s of l.steps) if (s.kind === 'extrude' && s.z) assert.equal(s.arcs, undefined);
  const arcBlocks = layerBlocks(arcs.gcode);
  assert.ok(
    arcBlocks.slice(BOTTOM, -1).every((b) => b.every((line) => !/^G[23]\s/.test(line))),
    'no arc on a turn',
  );
  assert.ok(
    arcBlocks.at(-1)!.every((line) => !/^G[23]\s/.test(line) || word(line, 'Z') === undefined),
    'arcs only on the flat finishing turn',
  );
});

test('spiral vase: the same G-code on one thread and two', async () => {
  const one = await slice(VASE, { spiralVase: true });
  const chunks: string[] = [];
  await new Slicer({ threads: 2, spiralVase: true }).sliceToSink(VASE, (c) => chunks.push(c));
  assert.equal(chunks.join(''), one.gcode);
});

test('spiral vase flags: --spiral-vase, --vase-mode and --spiralize, and their --no- forms', () => {
  for (const flag of ['--spiral-vase', '--vase-mode', '--spiralize']) {
    assert.equal(parseArgs(['slice', 'm.stl', flag]).settings.spiralVase, true, flag);
    assert.equal(parseArgs(['slice', 'm.stl', flag.replace('--', '--no-')]).settings.spiralVase, false);
  }
  assert.equal(parseArgs(['slice', 'm.stl', '--vase-mode=false']).settings.spiralVase, false);
});

test('spiral vase: a cup modelled hollow spirals on its outside like a solid cylinder, its hole dropped', async () => {
  const R = 15,
    r = 13.5,
    H = 6;
  const { plan, gcode, warnings } = await slice(cup(R, r, 1.2, H), { spiralVase: true });
  assert.deepEqual(warnings, [], 'the hole is not reported: it is dropped, as Cura drops it');
  const layers = plan.layers;
  assert.equal(layers.length, 30);
  // the bottom layers print as set (the floor and walls round the hole where there is one); above, turns
  for (const [i, layer] of layers.entries())
    assert.equal(!!layer.spiral, i >= BOTTOM, `layer ${i} spirals only above the bottom`);
  // the turns are the solid cylinder's: the same features and lengths, turn by turn
  const solid = await slice(cylinder(R, H), { spiralVase: true });
  const turnLengths = (p: PrintPlan) =>
    p.layers.slice(BOTTOM + 1).map((l) => {
      let length = 0;
      for (const st of l.steps)
        if (st.kind === 'extrude')
          for (let k = 1; k < st.points.length; k++)
            length += Math.hypot(st.points[k].x - st.points[k - 1].x, st.points[k].y - st.points[k - 1].y);
      return Math.round(length / 100) / 10;
    });
  assert.deepEqual(turnLengths(plan), turnLengths(solid.plan));

  // the G-code after the bottom: one outer wall, Z never falls, no travel, no retraction, and every point on
  // the outer surface (half a line inside radius R), none near the hole (radius r)
  const blocks = layerBlocks(gcode);
  // the axis: the middle of the turns' extent
  const xy: Array<[number, number]> = [];
  for (const b of blocks.slice(BOTTOM + 1))
    for (const line of b)
      if (/^G1\s/.test(line) && word(line, 'X') !== undefined && word(line, 'Y') !== undefined)
        xy.push([word(line, 'X')!, word(line, 'Y')!]);
  const xs = xy.map((p) => p[0]),
    ys = xy.map((p) => p[1]);
  const centre = { x: (Math.min(...xs) + Math.max(...xs)) / 2, y: (Math.min(...ys) + Math.max(...ys)) / 2 };
  let lastZ = -Infinity,
    points = 0;
  for (let i = BOTTOM + 1; i < blocks.length; i++) {
    for (const line of blocks[i]) {
      assert.ok(!/^G0\b/.test(line), `layer ${i}: no travel or Z move (${line})`);
      assert.ok(
        !/^G1[^;]*\sE-/.test(line) && !/^G1 F\d+ E[\d.]+$/.test(line) && !/^G1[0-1]\b/.test(line),
        `layer ${i}: no retraction or prime (${line})`,
      );
      if (/^;TYPE:/.test(line)) assert.equal(line, ';TYPE:WALL-OUTER');
      if (!/^G1\s/.test(line)) continue;
      const x = word(line, 'X'),
        y = word(line, 'Y'),
        z = word(line, 'Z');
      if (x !== undefined && y !== undefined) {
        const d = Math.hypot(x - centre.x, y - centre.y);
        assert.ok(
          Math.abs(d - (R - 0.2)) < 0.06,
          `layer ${i}: the wall follows the outer surface (${d.toFixed(3)} mm from the axis)`,
        );
        points++;
      }
      if (z === undefined) {
        assert.equal(i, blocks.length - 1, `layer ${i}: a spiral G1 has Z (${line})`);
        continue;
      }
      assert.ok(z >= lastZ, `Z never falls: ${z} after ${lastZ}`);
      lastZ = z;
    }
  }
  assert.ok(points > 25 * 90, `a point every side of every turn (${points})`);
  assert.equal(lastZ, H, 'the spiral ends at the top');
  const parsed = parseGcode(gcode);
  assert.equal(parsed.layers.length, 30);
  for (const l of parsed.layers.slice(BOTTOM + 1))
    assert.ok(Math.abs(l.thickness - 0.2) < 1e-4, `layer ${l.index} is one layer height thick`);
});

test('spiral vase: specks beside the main island are dropped with a warning; a second island of size keeps the layer flat', async () => {
  // a pin 0.8 mm square (0.64 mm²) beside the vase, as tall as it
  const pin = box(20, -0.4, 0, 20.8, 0.4, 6);
  const specks = await slice(join(VASE, pin), { spiralVase: true });
  assert.ok(
    specks.plan.layers.every((l, i) => !!l.spiral === i >= BOTTOM),
    'the vase spirals, the pin left out',
  );
  const w = specks.warnings.filter((m) => m.startsWith('spiral vase:'));
  assert.equal(w.length, 1, specks.warnings.join('\n'));
  assert.match(
    w[0],
    /^spiral vase: [\d.]+ mm² of islands smaller than 1 mm² beside the main one are left out on 26 layers between 4 and 29/,
  );
  // a 2 mm square post is an island of its own: those layers print flat, as before
  const post = await slice(join(VASE, box(20, -1, 0, 22, 1, 6)), { spiralVase: true });
  assert.ok(post.plan.layers.every((l) => !l.spiral));
  assert.ok(post.warnings.some((m) => m.includes('not one single wall loop')));
});
