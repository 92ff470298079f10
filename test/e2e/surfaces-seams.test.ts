/**
 * Scarf seams and fuzzy skin, end to end on a tube made here (a round outside and a round hole), read back
 * from the G-code with the analyser's parser: the scarf's ramp rises while extruding over at least its length,
 * its flow grows along it, the loop closes over the ramp with the flow shrinking, and nothing goes below the
 * layer underneath; fuzzy walls stray from the smooth wall by up to the thickness while inner walls stay
 * smooth; both give the same bytes on every run and on 1 or 3 threads, and valid G1 X Y Z E moves in the
 * Marlin and Klipper flavours.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer } from '#strata/api/slicer.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { Feature } from '../../tools/analysis/feature-names.js';
import type { ExtrusionTable, GcodeLayer } from '../../tools/analysis/gcode-types.js';
import type { Mesh } from '#strata/mesh/types.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { SCARF_CLEARANCE_MM } from '#strata/plan/scarf.js';
import { skipWithoutModels, readModel } from './models.js';

/** A tube standing on the bed: outside radius `R`, hole radius `r`, `h` tall, `n` sides. Closed, facing outwards. */
function tube(R: number, r: number, h: number, n = 128): Mesh {
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
  const quad = (a: number, b: number, c: number, d: number) => indices.push(a, b, c, a, c, d);
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    quad(o0[i], o0[j], o1[j], o1[i]); // outside
    quad(i0[i], i1[i], i1[j], i0[j]); // hole, facing in
    quad(o0[i], i0[i], i0[j], o0[j]); // bottom
    quad(o1[i], o1[j], i1[j], i1[i]); // top
  }
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices) };
}

const R = 10,
  HOLE = 5;
const TUBE = tube(R, HOLE, 5);

async function slice(options: SliceOptions, input: unknown = TUBE): Promise<string> {
  return (await new Slicer({ threads: 1, ...options }).slice(input)).gcode;
}

interface Segment {
  x0: number;
  y0: number;
  x1: number;
  y1: number;
  z: number;
  e: number;
}

/** A feature's extrusions of a layer, in print order, cut into runs of end-to-end segments. */
function runsOf(t: ExtrusionTable, feature: number): Segment[][] {
  const runs: Segment[][] = [];
  let run: Segment[] = [];
  for (let i = 0; i < t.count; i++) {
    if (t.feature[i] !== feature) continue;
    const s = { x0: t.x0[i], y0: t.y0[i], x1: t.x1[i], y1: t.y1[i], z: t.z[i], e: t.e[i] };
    const last = run[run.length - 1];
    if (last && (Math.abs(last.x1 - s.x0) > 1e-3 || Math.abs(last.y1 - s.y0) > 1e-3)) {
      runs.push(run);
      run = [];
    }
    run.push(s);
  }
  if (run.length) runs.push(run);
  return runs;
}

const len = (s: Segment) => Math.hypot(s.x1 - s.x0, s.y1 - s.y0);
/** Filament per mm of a segment. */
const flow = (s: Segment) => s.e / len(s);
const median = (v: number[]) => [...v].sort((a, b) => a - b)[v.length >> 1];

/** The centre of the tube: the middle of the inner walls' extent on the layer. */
function centreOf(layer: GcodeLayer): [number, number] {
  const t = layer.extrusions;
  let minX = Infinity,
    maxX = -Infinity,
    minY = Infinity,
    maxY = -Infinity;
  for (let i = 0; i < t.count; i++) {
    if (t.feature[i] !== Feature.WallInner) continue;
    (minX = Math.min(minX, t.x1[i])),
      (maxX = Math.max(maxX, t.x1[i])),
      (minY = Math.min(minY, t.y1[i])),
      (maxY = Math.max(maxY, t.y1[i]));
  }
  return [(minX + maxX) / 2, (minY + maxY) / 2];
}

test('scarf seam: each wall loop starts on a ramp of at least the scarf length, Z and flow rising, and ends over it with the flow shrinking; nothing below the layer underneath', {
  timeout: 120_000,
}, async () => {
  const length = 20;
  const gcode = await slice({ scarfSeam: 'outer', scarfLength: length, scarfStartHeight: 10, scarfSteps: 10 });
  const parsed = parseGcode(gcode);
  const layers = parsed.layers;
  assert.ok(layers.length >= 20);
  let ramps = 0;
  for (let k = 1; k < layers.length; k++) {
    const layer = layers[k];
    const prevZ = layers[k - 1].z;
    const floor = prevZ + SCARF_CLEARANCE_MM - 5e-4;
    const t = layer.extrusions;
    for (let i = 0; i < t.count; i++)
      assert.ok(t.z[i] >= floor, `layer ${k}: an extrusion at Z ${t.z[i]} below ${floor}`);
    const tr = layer.travels;
    // where each move goes (the first starts at the layer below's Z)
    for (let i = 0; i < tr.count; i++) assert.ok(tr.z1[i] >= floor, `layer ${k}: a move to Z ${tr.z1[i]}`);
    // inner walls keep their plain seam with `outer`
    for (const run of runsOf(t, Feature.WallInner)) for (const s of run) assert.ok(Math.abs(s.z - layer.z) < 1e-4);
    const loops = runsOf(t, Feature.WallOuter);
    assert.equal(loops.length, 2, `layer ${k}: the outside and the hole, each one run`);
    for (const run of loops) {
      const top = run.findIndex((s) => s.z >= layer.z - 1e-4);
      assert.ok(top > 0, `layer ${k}: the loop starts below the layer's Z`);
      const ramp = run.slice(0, top + 1);
      const rampLength = ramp.reduce((a, s) => a + len(s), 0);
      assert.ok(rampLength >= length - 0.05, `layer ${k}: ramp ${rampLength.toFixed(2)} mm`);
      assert.ok(ramp.length >= 10, 'at least scarfSteps moves');
      const nominal = median(run.slice(top + 1, run.length - ramp.length).map(flow));
      const start = layer.z - layer.thickness * 0.9;
      assert.ok(
        Math.abs(ramp[0].z - start) < 0.02,
        `layer ${k}: the ramp starts 10 % of the layer above the one below (${ramp[0].z})`,
      );
      for (let j = 1; j < ramp.length; j++) {
        assert.ok(ramp[j].z >= ramp[j - 1].z - 1e-6, 'Z rises along the ramp');
        assert.ok(flow(ramp[j]) >= flow(ramp[j - 1]) - 0.03 * nominal, `flow grows along the ramp (${j})`);
      }
      assert.ok(
        flow(ramp[0]) < 0.25 * nominal && flow(ramp[ramp.length - 1]) > 0.9 * nominal,
        'from a little to the full bead',
      );
      // the loop closes over the ramp at the layer's Z, the flow shrinking: each point gets one bead in all
      const end = run.slice(run.length - ramp.length);
      for (let j = 0; j < ramp.length; j++) {
        assert.ok(
          Math.abs(end[j].x1 - ramp[j].x1) < 2e-3 && Math.abs(end[j].y1 - ramp[j].y1) < 2e-3,
          'over the ramp again',
        );
        assert.ok(Math.abs(end[j].z - layer.z) < 1e-4);
        if (j > 0) assert.ok(flow(end[j]) <= flow(end[j - 1]) + 0.03 * nominal, 'the flow shrinks');
        assert.ok(
          Math.abs(flow(end[j]) + flow(ramp[j]) - nominal) < 0.08 * nominal,
          `ramp and end make one bead (${j})`,
        );
      }
      assert.ok(flow(end[end.length - 1]) < 0.1 * nominal);
      ramps++;
    }
  }
  assert.ok(ramps >= 2 * 20);
  // the first layer has none: nothing under it to ramp from
  for (const run of runsOf(layers[0].extrusions, Feature.WallOuter))
    for (const s of run) assert.ok(Math.abs(s.z - layers[0].z) < 1e-4);
});

test('scarf seam `all`: inner walls ramp too; `scarfConditional` leaves a seam in a sharp corner plain', {
  timeout: 120_000,
}, async () => {
  const layerOf = (gcode: string) => parseGcode(gcode).layers[10];
  const below = (runs: Segment[][], z: number) => runs.filter((run) => run[0].z < z - 1e-4).length;
  const all = layerOf(await slice({ scarfSeam: 'all' }));
  assert.equal(
    below(runsOf(all.extrusions, Feature.WallInner), all.z),
    runsOf(all.extrusions, Feature.WallInner).length,
  );
  assert.ok(runsOf(all.extrusions, Feature.WallInner).length >= 2);
  // a square block: its aligned seam sits in a corner
  const box = tubeBox();
  const plain = layerOf(await slice({ scarfSeam: 'outer', scarfConditional: true }, box));
  assert.equal(below(runsOf(plain.extrusions, Feature.WallOuter), plain.z), 0, 'in a corner: no scarf');
  const scarfed = layerOf(await slice({ scarfSeam: 'outer' }, box));
  assert.equal(below(runsOf(scarfed.extrusions, Feature.WallOuter), scarfed.z), 1);
  // the round tube's seams are on smooth walls: a conditional scarf still ramps
  const round = layerOf(await slice({ scarfSeam: 'outer', scarfConditional: true }));
  assert.equal(below(runsOf(round.extrusions, Feature.WallOuter), round.z), 2);
});

/** A 20 × 20 × 5 mm block. */
function tubeBox(): Mesh {
  const s = 10,
    h = 5;
  const v = [
    [-s, -s, 0],
    [s, -s, 0],
    [s, s, 0],
    [-s, s, 0],
    [-s, -s, h],
    [s, -s, h],
    [s, s, h],
    [-s, s, h],
  ];
  const f = [
    [0, 2, 1],
    [0, 3, 2],
    [4, 5, 6],
    [4, 6, 7],
    [0, 1, 5],
    [0, 5, 4],
    [1, 2, 6],
    [1, 6, 5],
    [2, 3, 7],
    [2, 7, 6],
    [3, 0, 4],
    [3, 4, 7],
  ];
  return { positions: new Float32Array(v.flat()), indices: new Uint32Array(f.flat()) };
}

test('fuzzy skin: the outer wall strays in and out by up to the thickness, about a point distance apart; inner walls stay smooth; holes with `all`', {
  timeout: 120_000,
}, async () => {
  const thickness = 0.3,
    spacing = 0.8;
  const smooth = parseGcode(await slice({})).layers;
  const outer = parseGcode(
    await slice({ fuzzySkin: 'outer', fuzzySkinThickness: thickness, fuzzySkinPointDistance: spacing }),
  ).layers;
  const all = parseGcode(
    await slice({ fuzzySkin: 'all', fuzzySkinThickness: thickness, fuzzySkinPointDistance: spacing }),
  ).layers;
  assert.equal(outer.length, smooth.length);
  const mid = (R + HOLE) / 2;
  /** Distances from the axis of a feature's points on one side of the tube (the outside or the hole). */
  const radii = (layer: GcodeLayer, feature: number, outside: boolean) => {
    const [cx, cy] = centreOf(layer);
    const t = layer.extrusions;
    const out: number[] = [];
    for (let i = 0; i < t.count; i++) {
      if (t.feature[i] !== feature) continue;
      const d = Math.hypot(t.x1[i] - cx, t.y1[i] - cy);
      if (d > mid === outside) out.push(d);
    }
    return out;
  };
  const spread = (v: number[]) => Math.max(...v) - Math.min(...v);
  const mean = (v: number[]) => v.reduce((a, b) => a + b, 0) / v.length;
  for (let k = 1; k < smooth.length; k++) {
    const wall = mean(radii(smooth[k], Feature.WallOuter, true)); // the smooth outer wall's radius
    const rough = radii(outer[k], Feature.WallOuter, true);
    const dev = rough.map((d) => d - wall);
    assert.ok(
      Math.max(...dev) <= thickness + 0.02 && Math.min(...dev) >= -thickness - 0.02,
      `layer ${k}: within ±${thickness} mm of the smooth wall`,
    );
    assert.ok(
      Math.max(...dev) > 0.75 * thickness && Math.min(...dev) < -0.75 * thickness,
      `layer ${k}: out and in by about the thickness (${Math.min(...dev).toFixed(3)}…${Math.max(...dev).toFixed(3)})`,
    );
    const points = (2 * Math.PI * wall) / spacing;
    assert.ok(
      rough.length > 0.8 * points && rough.length < 1.25 * points,
      `layer ${k}: ${rough.length} points, about one per ${spacing} mm`,
    );
    for (const layers of [smooth, outer, all]) {
      assert.ok(
        spread(radii(layers[k], Feature.WallInner, true)) < 0.45,
        'the inner wall round the outside stays a circle (its loops 0.4 mm apart)',
      );
      for (const ring of [radii(layers[k], Feature.WallInner, true).filter((d) => d > wall - 0.6)])
        assert.ok(spread(ring) < 0.03, `layer ${k}: inner wall smooth`);
    }
    assert.ok(spread(radii(outer[k], Feature.WallOuter, false)) < 0.03, `layer ${k}: outer: the hole stays smooth`);
    assert.ok(
      spread(radii(all[k], Feature.WallOuter, false)) > 1.5 * thickness,
      `layer ${k}: all: the hole is fuzzy too`,
    );
  }
  // the first layer stays smooth
  assert.ok(spread(radii(outer[0], Feature.WallOuter, true)) < 0.03);
});

test('both on: the same bytes on every run, on 1 and 3 threads; Marlin and Klipper write G1 X Y Z E moves', {
  timeout: 300_000,
}, async () => {
  const options: SliceOptions = { scarfSeam: 'all', fuzzySkin: 'all' };
  const one = await slice(options);
  assert.equal(await slice(options), one, 'run to run');
  assert.equal((await new Slicer({ ...options, threads: 3 }).slice(TUBE)).gcode, one, 'threads 1 vs 3');
  for (const gcodeFlavor of ['marlin', 'klipper'] as const) {
    const gcode = await slice({ ...options, gcodeFlavor });
    const zMoves = gcode.split('\n').filter((l) => /^G1 .*Z/.test(l) && / E/.test(l));
    assert.ok(zMoves.length > 100, `${gcodeFlavor}: extrusions that move Z`);
    for (const l of zMoves)
      assert.match(
        l,
        /^G1(?: F\d+(?:\.\d+)?)?(?: X-?\d+(?:\.\d+)?)?(?: Y-?\d+(?:\.\d+)?)? Z\d+(?:\.\d+)? E-?\d+(?:\.\d+)?$/,
        `${gcodeFlavor}: ${l}`,
      );
    assert.ok(
      zMoves.every((l) => / [XY]/.test(l)),
      'each moves in XY too',
    );
    const parsed = parseGcode(gcode);
    assert.equal(parsed.balance.unbalanced, 0, `${gcodeFlavor}: retractions and primes balance`);
  }
});

const skip = skipWithoutModels();

test('HoleTest with both on: the same bytes on 1 and 3 threads', { skip, timeout: 300_000 }, async () => {
  const bytes = readModel('HoleTest.stl');
  const options: SliceOptions = { scarfSeam: 'all', fuzzySkin: 'outer' };
  const one = await slice(options, bytes);
  assert.equal((await new Slicer({ ...options, threads: 3 }).slice(bytes)).gcode, one);
  assert.match(one, /\nG1 [^\n]*Z[^\n]* E/);
});
