/**
 * The WebAssembly engine against the TypeScript one (the same Clipper2): every facade operation on real
 * layer sections and on random overlapping rings gives the same areas, within rounding.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as wasmEngine from '#strata/geometry/clipper-wasm.js';
import * as tsEngine from './clipper-ts.js';
import {
  area,
  clipOperations,
  difference,
  intersection,
  offset,
  union,
  type ClipOperations,
} from '#strata/geometry/clip.js';
import type { ExPolygon, Polyline, Pt } from '#strata/geometry/types.js';

/** A deterministic pseudo-random generator (so a failure can be replayed). */
function rng(seed: number): () => number {
  let s = seed >>> 0;
  return () => (s = (s * 1664525 + 1013904223) >>> 0) / 2 ** 32;
}

function star(cx: number, cy: number, r: number, n: number, rand: () => number): ExPolygon {
  const outer: Pt[] = [];
  for (let k = 0; k < n; k++) {
    const a = (2 * Math.PI * k) / n;
    const rr = r * (0.5 + rand());
    outer.push({ x: Math.round(cx + rr * Math.cos(a)), y: Math.round(cy + rr * Math.sin(a)) });
  }
  return { outer, holes: [] };
}

/** The facade's operations over each engine. */
const TS = clipOperations(tsEngine);
const WASM = clipOperations(wasmEngine);

function both<T>(f: (ops: ClipOperations) => T): { ts: T; wasm: T } {
  return { ts: f(TS), wasm: f(WASM) };
}

const length = (lines: readonly Polyline[]) =>
  lines.reduce((t, l) => t + l.slice(1).reduce((s, p, i) => s + Math.hypot(p.x - l[i].x, p.y - l[i].y), 0), 0);

test('booleans, offsets, strokes, line clipping and simplification agree between the two engines', async () => {
  const rand = rng(7);
  for (let round = 0; round < 40; round++) {
    const a = [star(50_000, 50_000, 20_000, 24, rand), star(62_000, 48_000, 15_000, 17, rand)];
    const b = [star(55_000, 60_000, 18_000, 31, rand)];
    const lines: Polyline[] = [];
    for (let k = 0; k < 10; k++)
      lines.push([
        { x: 20_000, y: 30_000 + k * 4000 },
        { x: 90_000, y: 35_000 + k * 4000 },
      ]);
    const cases: Array<[string, (o: ClipOperations) => number, number]> = [
      // the rings cross themselves: intersection points round to whole µm in their own ways
      ['union', (o) => area(o.union(a, b)), 1e-4],
      ['difference', (o) => area(o.difference(a, b)), 1e-4],
      ['intersection', (o) => area(o.intersection(a, b)), 1e-4],
      ['offset -800 miter', (o) => area(o.offset(a, -800)), 1e-4],
      ['offset +1200 round', (o) => area(o.offset(a, 1200, 'round')), 1e-6],
      ['stroke', (o) => area(o.strokeArea(lines, [b[0].outer], 400)), 1e-3],
      ['clip lines', (o) => length(o.clipLines(lines, a)), 5],
      ['clip lines outside', (o) => length(o.clipLinesOutside(lines, a)), 5],
      ['simplify', (o) => area(o.simplifyAreas(a, 50)), 1e-6],
    ];
    for (const [name, f, rel] of cases) {
      const { ts, wasm } = both(f);
      // rel ≥ 1: an absolute tolerance (µm); else relative
      const tol = rel >= 1 ? rel : rel * Math.abs(ts);
      assert.ok(Math.abs(ts - wasm) <= tol, `${name} (round ${round}): TypeScript ${ts}, WebAssembly ${wasm}`);
    }
  }
});

test('results are read straight from the engine memory (the layouts checked at load hold for the pinned clipper2-wasm)', async () => {
  const { DIRECT } = await import('#strata/geometry/clipper-wasm.js');
  assert.equal(DIRECT, true);
});

test('the engine gives its results in whole micrometres, its crossing points too', async () => {
  const rand = rng(7);
  let points = 0;
  for (let t = 0; t < 50; t++) {
    // overlapping stars: their edges cross at points that are seldom whole
    const a = star(100000 + t * 7, 100000, 1250 + t, 9, rand),
      b = star(101500 + t * 3, 100300 + t, 1100 + 2 * t, 8, rand);
    for (const result of [union([a], [b]), intersection([a], [b]), difference([a], [b]), offset([a, b], 333)]) {
      for (const island of result) {
        for (const ring of [island.outer, ...island.holes]) {
          for (const p of ring) {
            points++;
            assert.ok(Number.isInteger(p.x) && Number.isInteger(p.y), `(${p.x}, ${p.y}) is not whole µm`);
          }
        }
      }
    }
  }
  assert.ok(points > 1000);
});
