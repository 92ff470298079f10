import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer } from '#strata/api/slicer.js';
import { StrataError } from '#strata/errors.js';

/** A closed axis-aligned box as raw arrays (outward-facing triangles). */
function box(
  x0: number,
  y0: number,
  z0: number,
  sx: number,
  sy: number,
  sz: number,
): { positions: Float32Array; indices: Uint32Array } {
  const v: number[] = [];
  for (const [x, y, z] of [
    [0, 0, 0],
    [1, 0, 0],
    [1, 1, 0],
    [0, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [1, 1, 1],
    [0, 1, 1],
  ])
    v.push(x0 + x * sx, y0 + y * sy, z0 + z * sz);
  const f = [
    0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7,
  ];
  return { positions: new Float32Array(v), indices: new Uint32Array(f) };
}

/** A minimal three.js-like scene graph (duck-typed): a Group holding two translated meshes. */
function threeGroup() {
  const geometry = (b: ReturnType<typeof box>) => ({
    isBufferGeometry: true,
    attributes: { position: { array: b.positions, itemSize: 3, count: b.positions.length / 3 } },
    index: { array: b.indices },
  });
  const at = (x: number, y: number, z: number) => ({
    position: { x, y, z },
    quaternion: { x: 0, y: 0, z: 0, w: 1 },
    scale: { x: 1, y: 1, z: 1 },
  });
  const a = {
    isMesh: true,
    isObject3D: true,
    geometry: geometry(box(0, 0, 0, 10, 10, 5)),
    ...at(0, 0, 0),
    children: [],
  };
  const b = {
    isMesh: true,
    isObject3D: true,
    geometry: geometry(box(0, 0, 0, 10, 10, 5)),
    ...at(30, 0, 0),
    children: [],
  };
  return { isGroup: true, isObject3D: true, children: [a, b], ...at(5, 5, 0) };
}

test('raw typed arrays slice to G-code with sensible stats', async () => {
  const { gcode, stats, warnings } = await new Slicer({ threads: 1 }).slice(box(0, 0, 0, 20, 20, 10));
  assert.equal(stats.layers, 50);
  assert.ok(stats.printTimeSeconds > 60 && stats.printTimeSeconds < 3600, `time ${stats.printTimeSeconds}`);
  assert.ok(stats.filamentGrams > 0.5 && stats.filamentGrams < 10, `grams ${stats.filamentGrams}`);
  assert.equal((gcode.match(/^;LAYER:\d+$/gm) ?? []).length, 50);
  assert.ok(Array.isArray(warnings));
  // centred on the Ender-3 bed (220 × 220)
  assert.ok(
    Math.abs(stats.bounds.minX + stats.bounds.maxX - 220) < 1 &&
      Math.abs(stats.bounds.minY + stats.bounds.maxY - 220) < 1,
  );
});

test('every mesh of a three.js group is printed, not only the first', async () => {
  const { stats } = await new Slicer({ threads: 1, adhesionType: 'none' }).slice(threeGroup());
  // two 10 mm boxes 30 mm apart (20 mm gap) kept together: 40 mm of X extent
  assert.ok(
    Math.abs(stats.bounds.maxX - stats.bounds.minX - 40) < 0.5,
    `x extent ${stats.bounds.maxX - stats.bounds.minX}`,
  );
});

test('setters chain, validate at once and getters read the resolved value', () => {
  const s = new Slicer().setLayerHeight(0.16).setInfillDensity(35).setInfillPattern('gyroid');
  assert.equal(s.getLayerHeight(), 0.16);
  assert.equal(s.getInfillDensity(), 35);
  assert.equal(s.getInfillPattern(), 'gyroid');
  assert.throws(() => s.setInfillDensity(-5), StrataError);
  assert.throws(() => s.setInfillPattern('nope' as never), StrataError);
  assert.equal(s.getInfillDensity(), 35, 'a rejected value leaves the old one');
  assert.equal(new Slicer({ printer: 'prusa-mk4' }).getBuildPlateWidth(), 250);
});

test('streaming to a sink gives the same text as slice(); progress reaches 1; options are not mutated', async () => {
  const opts = Object.freeze({ threads: 1, layerHeight: 0.2 });
  const s = new Slicer(opts);
  const whole = await s.slice(box(0, 0, 0, 10, 10, 4));
  const chunks: string[] = [];
  let last = 0;
  await s.sliceToSink(box(0, 0, 0, 10, 10, 4), (c) => chunks.push(c), { onProgress: (p) => (last = p.fraction) });
  assert.equal(chunks.join(''), whole.gcode);
  assert.equal(last, 1);
  assert.deepEqual(opts, { threads: 1, layerHeight: 0.2 });
});

test('an aborted signal cancels with a StrataError', async () => {
  const ac = new AbortController();
  ac.abort();
  await assert.rejects(
    new Slicer({ threads: 1 }).slice(box(0, 0, 0, 10, 10, 4), { signal: ac.signal }),
    (e: unknown) => e instanceof StrataError && e.code === 'CANCELLED',
  );
});

test('progress comes per layer on one thread, never goes back, and ends at 1', async () => {
  const seen: number[] = [];
  let slicing = 0;
  await new Slicer({ threads: 1 }).slice(box(0, 0, 0, 20, 20, 10), {
    onProgress: (p) => (seen.push(p.fraction), (slicing += p.stage === 'slicing' ? 1 : 0)),
  });
  assert.ok(slicing >= 50, `${slicing} progress steps while slicing 50 layers`);
  for (let i = 1; i < seen.length; i++) assert.ok(seen[i] >= seen[i - 1], `progress went back at step ${i}`);
  assert.equal(seen[seen.length - 1], 1);
});

for (const threads of [1, 2]) {
  test(`an abort mid-slice (${threads} thread${threads > 1 ? 's' : ''}) stops at once, rejecting with CANCELLED whose cause is the signal's reason`, async () => {
    const ac = new AbortController();
    const reason = new Error('user pressed Cancel');
    let after = 0;
    const slicing = new Slicer({ threads, supportEnabled: true }).slice(box(0, 0, 0, 30, 30, 12), {
      signal: ac.signal,
      onProgress: (p) => {
        if (ac.signal.aborted) after++;
        else if (p.fraction > 0.1) ac.abort(reason);
      },
    });
    await assert.rejects(
      slicing,
      (e: unknown) => e instanceof StrataError && e.code === 'CANCELLED' && e.cause === reason,
    );
    // the layer being computed when the abort came may still report; nothing after it
    assert.ok(after <= threads, `${after} progress reports after the abort`);
  });
}

test('a model larger than the bed, an empty input and garbage bytes are clear errors', async () => {
  await assert.rejects(
    new Slicer({ threads: 1 }).slice(box(0, 0, 0, 300, 10, 4)),
    (e: unknown) => e instanceof StrataError && e.code === 'DOES_NOT_FIT',
  );
  await assert.rejects(new Slicer({ threads: 1 }).slice({ positions: new Float32Array(0) }), StrataError);
  await assert.rejects(new Slicer({ threads: 1 }).slice(new Uint8Array([1, 2, 3, 4, 5])), StrataError);
});

test('a model floating above the bed is dropped onto it', async () => {
  const { stats } = await new Slicer({ threads: 1 }).slice(box(0, 0, 50, 10, 10, 4));
  assert.equal(stats.layers, 20);
  assert.equal(stats.bounds.minZ, 0.2);
});
