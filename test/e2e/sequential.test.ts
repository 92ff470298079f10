/**
 * Sequential printing, end to end from boxes made here and judged from the G-code text alone: each object's
 * extrusions (told apart by where they lie, and checked against the object labels) come in one run, in
 * print order; each object's Z starts at the first layer and rises to its top; Z goes down only between
 * objects, after a lift above everything printed before; no XY move passes over a finished object below its
 * top and nothing is extruded at the lifted Z; the layer count, markers, time stamps and host trailer agree;
 * the analyser parses it. The same checks run on the plate printed all at once must fail, so they measure
 * something. And the refusals: objects too close, an object other than the last too tall, a raft.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer, type ObjectOptions } from '#strata/api/slicer.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { StrataError } from '#strata/errors.js';
import { box, type Arrays } from './test-meshes.js';

const BASE = { threads: 1, center: false, infillPattern: 'lines', infillDensity: 15 } as const;
const FIRST_LAYER = 0.2;

interface Part {
  name: string;
  x0: number;
  y0: number;
  x1: number;
  y1: number;
  top: number;
}

const part = (name: string, x0: number, y0: number, size: number, top: number): Part => ({
  name,
  x0,
  y0,
  x1: x0 + size,
  y1: y0 + size,
  top,
});
const meshOf = (p: Part): Arrays => box(p.x0, p.y0, 0, p.x1, p.y1, p.top);

async function slice(parts: readonly Part[], options: Record<string, unknown> = {}) {
  const s = new Slicer({ ...BASE, ...options } as never);
  for (const p of parts) s.addObject(meshOf(p), { name: p.name } satisfies ObjectOptions);
  return s.slice();
}

/** A move of the G-code: where it ends, and whether it extruded. */
interface Move {
  line: number;
  x0: number;
  y0: number;
  x: number;
  y: number;
  z: number;
  extrudes: boolean;
  /** The object label open around it (comments mode), or null. */
  label: string | null;
}

/**
 * The moves of the layers (from the first layer marker to the last layer's time stamp: not the start and end
 * templates') of Marlin G-code with absolute E (M82, G92 E0 resets), and the object label comments.
 */
function movesOf(gcode: string): Move[] {
  const moves: Move[] = [];
  let x = NaN,
    y = NaN,
    z = NaN,
    e = 0;
  let label: string | null = null;
  const lines = gcode.split('\n');
  const from = lines.indexOf(';LAYER:0');
  let to = lines.length;
  while (to > 0 && !lines[to - 1].startsWith(';TIME_ELAPSED:')) to--;
  for (let i = from; i < to; i++) {
    const line = lines[i];
    const start = /^; printing object (.+)$/.exec(line);
    if (start) label = start[1];
    if (/^; stop printing object /.test(line)) label = null;
    const code = line.replace(/;.*$/, '').trim();
    if (/^G92\b/.test(code)) {
      const w = /\bE(-?[\d.]+)/.exec(code);
      if (w) e = Number(w[1]);
      continue;
    }
    if (!/^G[01]\b/.test(code)) continue;
    const word = (c: string) => {
      const m = new RegExp(`\\b${c}(-?[\\d.]+)`).exec(code);
      return m ? Number(m[1]) : undefined;
    };
    const nx = word('X') ?? x,
      ny = word('Y') ?? y,
      nz = word('Z') ?? z,
      ne = word('E') ?? e;
    const moved = nx !== x || ny !== y;
    moves.push({ line: i, x0: x, y0: y, x: nx, y: ny, z: nz, extrudes: moved && ne > e + 1e-9, label });
    x = nx;
    y = ny;
    z = nz;
    e = ne;
  }
  return moves;
}

/** The part a point lies in (its footprint grown by `margin` mm), or -1. */
function partAt(parts: readonly Part[], x: number, y: number, margin = 0.5): number {
  return parts.findIndex((p) => x >= p.x0 - margin && x <= p.x1 + margin && y >= p.y0 - margin && y <= p.y1 + margin);
}

/** Whether the segment passes over the rectangle (Liang–Barsky clip). */
function crosses(m: Move, p: Part, margin: number): boolean {
  let t0 = 0,
    t1 = 1;
  const dx = m.x - m.x0,
    dy = m.y - m.y0;
  for (const [q, r] of [
    [-dx, m.x0 - (p.x0 - margin)],
    [dx, p.x1 + margin - m.x0],
    [-dy, m.y0 - (p.y0 - margin)],
    [dy, p.y1 + margin - m.y0],
  ]) {
    if (q === 0) {
      if (r < 0) return false;
    } else {
      const t = r / q;
      if (q < 0) t0 = Math.max(t0, t);
      else t1 = Math.min(t1, t);
    }
  }
  return t1 >= t0;
}

/**
 * Everything wrong with the G-code as a sequential print of `parts` in the order `order` (indices), as
 * sentences; empty when it is right. Skirt extrusions (outside every part) are allowed before the first
 * object's second layer only.
 */
function sequentialProblems(gcode: string, parts: readonly Part[], order: readonly number[]): string[] {
  const problems: string[] = [];
  const moves = movesOf(gcode);
  const ext = moves.filter((m) => m.extrudes);
  // 1. attribution by place; skirt only at the very start
  const owner = ext.map((m) => partAt(parts, m.x, m.y));
  const firstObjectLayer2 = ext.findIndex((m, i) => owner[i] >= 0 && m.z > FIRST_LAYER + 1e-6);
  ext.forEach((m, i) => {
    if (owner[i] < 0 && (firstObjectLayer2 < 0 || i > firstObjectLayer2))
      problems.push(`line ${m.line + 1}: extrusion outside every part after the first layer`);
    if (owner[i] >= 0 && m.label !== null && m.label !== parts[owner[i]].name)
      problems.push(`line ${m.line + 1}: in ${parts[owner[i]].name} but labelled ${m.label}`);
  });
  // 2. the parts' extrusions in one run each, in order
  const runs: number[] = [];
  for (const o of owner) if (o >= 0 && runs[runs.length - 1] !== o) runs.push(o);
  if (runs.join() !== order.join())
    problems.push(
      `objects printed in runs ${runs.map((o) => parts[o].name).join(', ')}, not ${order.map((o) => parts[o].name).join(', ')} once each`,
    );
  // 3. each part's Z from the first layer up to its top, never down
  for (const o of order) {
    const zs = ext.filter((_, i) => owner[i] === o).map((m) => m.z);
    if (zs.length === 0) continue;
    if (Math.abs(zs[0] - FIRST_LAYER) > 1e-6)
      problems.push(`${parts[o].name} starts at Z ${zs[0]}, not ${FIRST_LAYER}`);
    if (Math.abs(zs[zs.length - 1] - parts[o].top) > 0.21)
      problems.push(`${parts[o].name} ends at Z ${zs[zs.length - 1]}, not at its top ${parts[o].top}`);
    for (let k = 1; k < zs.length; k++) {
      if (zs[k] < zs[k - 1] - 1e-6) {
        problems.push(`${parts[o].name}'s Z goes down from ${zs[k - 1]} to ${zs[k]}`);
        break;
      }
    }
  }
  // 4. after a part's last extrusion, no move over it below its top (plus a layer), no extrusion over it
  const lastLine = parts.map((_, o) => Math.max(-1, ...ext.filter((_, i) => owner[i] === o).map((m) => m.line)));
  let highest = 0;
  let drops = 0;
  for (let i = 0; i < moves.length; i++) {
    const m = moves[i];
    const prevZ = i > 0 ? moves[i - 1].z : NaN;
    if (m.z < prevZ - 1e-6) {
      drops++;
      // Z goes down only straight down (no XY), onto the next part, from above everything printed
      if (m.x !== m.x0 || m.y !== m.y0) problems.push(`line ${m.line + 1}: Z goes down while moving in XY`);
      if (!(prevZ > highest))
        problems.push(`line ${m.line + 1}: Z goes down from ${prevZ}, not above the highest print so far (${highest})`);
      const below = partAt(parts, m.x, m.y, 2);
      if (below < 0 || lastLine[below] < m.line)
        problems.push(`line ${m.line + 1}: comes down at (${m.x}, ${m.y}) outside a part still to print`);
    }
    const moved = m.x !== m.x0 || m.y !== m.y0;
    if (moved && Number.isFinite(m.x0)) {
      parts.forEach((p, o) => {
        if (lastLine[o] >= 0 && lastLine[o] < m.line && crosses(m, p, 1) && m.z <= p.top + 0.2 + 1e-6) {
          problems.push(
            `line ${m.line + 1}: ${m.extrudes ? 'extrudes' : 'moves'} over finished ${p.name} at Z ${m.z} (its top ${p.top})`,
          );
        }
      });
    }
    if (m.extrudes && m.z > highest) highest = m.z;
    if (problems.length > 20) break;
  }
  if (drops !== order.length - 1) problems.push(`Z goes down ${drops} times, not ${order.length - 1}`);
  return problems;
}

/** The layer counts the file states: markers, LAYER_COUNT, time stamps, the host trailer. */
function layerCounts(gcode: string) {
  return {
    markers: (gcode.match(/^;LAYER:\d+$/gm) ?? []).length,
    declared: Number(/^;LAYER_COUNT:(\d+)$/m.exec(gcode)?.[1]),
    times: (gcode.match(/^;TIME_ELAPSED:/gm) ?? []).length,
    trailer: Number(/^; total layers count = (\d+)$/m.exec(gcode)?.[1]),
  };
}

// three parts 50 mm apart (more than the 45 mm clearance radius), of different heights, in a row
const A = part('A', 20, 90, 12, 6);
const B = part('B', 82, 90, 12, 10);
const C = part('C', 144, 90, 12, 4);

test('three parts print one at a time, each from its first layer to its top, lifting over the finished ones', async () => {
  const { gcode, stats } = await slice([A, B, C], { sequentialPrinting: true, zHop: 0 });
  assert.deepEqual(sequentialProblems(gcode, [A, B, C], [0, 1, 2]), []);
  // the end template starts above every object (B, 10 mm)
  const moves = movesOf(gcode);
  assert.ok(moves[moves.length - 1].z > 10, `the last move is at Z ${moves[moves.length - 1].z}`);
  // layers are numbered on through the print: every part's layers, counted everywhere the same
  const layers = Math.round(6 / 0.2) + Math.round(10 / 0.2) + Math.round(4 / 0.2);
  assert.deepEqual(layerCounts(gcode), { markers: layers, declared: layers, times: layers, trailer: layers });
  assert.equal(stats.layers, layers);
  const numbers = (gcode.match(/^;LAYER:(\d+)$/gm) ?? []).map((l) => Number(l.slice(7)));
  assert.deepEqual(
    numbers,
    numbers.map((_, i) => i),
    'consecutive layer numbers',
  );
  // progress only goes forward
  const percents = (gcode.match(/^M73 P(\d+)/gm) ?? []).map((l) => Number(l.slice(5)));
  assert.ok(
    percents.every((p, i) => i === 0 || p >= percents[i - 1]),
    'M73 never goes back',
  );
  // one skirt, at the start
  assert.equal((gcode.match(/^;TYPE:SKIRT$/gm) ?? []).length, 1);
  // the analyser reads it: the distinct print heights, up to the tallest part, with balanced retractions
  const g = parseGcode(gcode);
  assert.equal(g.layers.length, Math.round(10 / 0.2));
  assert.ok(Math.abs(g.layers[g.layers.length - 1].z - 10) < 1e-6);
  assert.ok(Math.abs(g.layers[0].z - FIRST_LAYER) < 1e-6);
});

test('the checks fail on the same parts printed all at once', async () => {
  const { gcode } = await slice([A, B, C], { zHop: 0 });
  const problems = sequentialProblems(gcode, [A, B, C], [0, 1, 2]);
  assert.ok(
    problems.some((p) => /in runs/.test(p)),
    problems.join('\n'),
  );
  assert.ok(
    problems.some((p) => /over finished/.test(p)) || problems.some((p) => /goes down/.test(p)) || problems.length > 0,
  );
});

test('a colour change at a height happens in every part that reaches it, with the first-layer temperature again at each part', async () => {
  const { gcode } = await slice([A, B, C], {
    sequentialPrinting: true,
    colorChangeAt: '5',
    firstLayerNozzleTemperature: 215,
    nozzleTemperature: 205,
  });
  // A (6 mm) and B (10 mm) reach 5 mm, C (4 mm) does not
  assert.equal((gcode.match(/^M600/gm) ?? []).length, 2);
  assert.equal((gcode.match(/^M104 S215$/gm) ?? []).length, 2, 'B and C start at the first-layer temperature');
});

test('the one part taller than the gantry prints last, whatever its place in the list', async () => {
  const tall = part('tall', 20, 90, 12, 25);
  const { gcode } = await slice([tall, B, C], { sequentialPrinting: true, zHop: 0 });
  assert.deepEqual(sequentialProblems(gcode, [tall, B, C], [1, 2, 0]), []);
});

test('an object other than the last taller than extruderClearanceHeight is refused, naming it', async () => {
  const tall = part('tall', 20, 90, 12, 25),
    taller = part('taller', 82, 90, 12, 30);
  await assert.rejects(
    slice([tall, taller, C], { sequentialPrinting: true }),
    (e: unknown) =>
      e instanceof StrataError &&
      e.code === 'DOES_NOT_FIT' &&
      /"tall" is 25 mm tall/.test(e.message) &&
      /extruderClearanceHeight \(20 mm\)/.test(e.message),
  );
  // a higher gantry takes them
  await slice([tall, taller, C], { sequentialPrinting: true, extruderClearanceHeight: 30 });
});

test('objects closer than extruderClearanceRadius are refused, naming both', async () => {
  const near = part('near', 50, 90, 12, 5);
  await assert.rejects(
    slice([A, near, C], { sequentialPrinting: true }),
    (e: unknown) =>
      e instanceof StrataError &&
      e.code === 'OVERLAPPING_OBJECTS' &&
      /objects "A" and "near" are closer than extruderClearanceRadius \(45 mm\)/.test(e.message) &&
      /18 mm apart/.test(e.message),
  );
  // a smaller head clears them; all at once there is nothing to check
  await slice([A, near, C], { sequentialPrinting: true, extruderClearanceRadius: 15 });
  await slice([A, near, C]);
});

test('a raft is refused with sequential printing', async () => {
  await assert.rejects(
    slice([A, C], { sequentialPrinting: true, adhesionType: 'raft' }),
    (e: unknown) => e instanceof StrataError && e.code === 'BAD_SETTING' && /raft/.test(e.message),
  );
});

test('arranged models are spaced by the clearance radius and pass the check', async () => {
  const s = new Slicer({ threads: 1, sequentialPrinting: true, extruderClearanceRadius: 35, gcodeFlavor: 'klipper' });
  const models = [box(0, 0, 0, 15, 15, 5), box(0, 0, 0, 20, 10, 8), box(0, 0, 0, 10, 10, 3)];
  const r = await s.slice(models);
  assert.ok(
    r.warnings.some((w) => /35 mm apart/.test(w)),
    r.warnings.join('\n'),
  );
  assert.equal(r.stats.layers, Math.round(5 / 0.2) + Math.round(8 / 0.2) + Math.round(3 / 0.2));
  // the footprints Klipper is told (EXCLUDE_OBJECT_DEFINE) lie at least the radius apart
  const rects = [...r.gcode.matchAll(/^EXCLUDE_OBJECT_DEFINE NAME=\S+ CENTER=\S+ POLYGON=(\S+)$/gm)].map((m) => {
    const pts = JSON.parse(m[1]) as [number, number][];
    return {
      x0: Math.min(...pts.map((p) => p[0])),
      x1: Math.max(...pts.map((p) => p[0])),
      y0: Math.min(...pts.map((p) => p[1])),
      y1: Math.max(...pts.map((p) => p[1])),
    };
  });
  assert.equal(rects.length, 3);
  for (let i = 0; i < 3; i++) {
    for (let j = i + 1; j < 3; j++) {
      const gap = Math.max(
        rects[j].x0 - rects[i].x1,
        rects[i].x0 - rects[j].x1,
        rects[j].y0 - rects[i].y1,
        rects[i].y0 - rects[j].y1,
      );
      assert.ok(gap >= 35 - 0.01, `objects ${i} and ${j} ${gap.toFixed(2)} mm apart`);
    }
  }
  // Z goes down twice: onto the second and the third model
  const zs = [...r.gcode.matchAll(/^G[01] [^;\n]*Z(\d+\.?\d*)/gm)].map((m) => Number(m[1]));
  const from = zs.indexOf(0.2);
  assert.equal(zs.slice(from, zs.lastIndexOf(3)).filter((z, i, a) => i > 0 && z < a[i - 1]).length, 2);
});
