import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { Slicer } from '#strata/api/slicer.js';
import { StrataError } from '#strata/errors.js';
import { loadCustomInfill } from '#strata/infill/registry.js';

const cube = readFileSync(new URL('../../../examples/calibration-cube.stl', import.meta.url));

/** An overhanging T (a bar on a post) as raw arrays, so support has something to hold. */
function tee(): { positions: Float32Array; indices: Uint32Array } {
  const boxes = [
    [0, 0, 0, 6, 6, 10],
    [-12, 0, 10, 30, 6, 3],
  ];
  const v: number[] = [];
  const f: number[] = [];
  for (const [x0, y0, z0, sx, sy, sz] of boxes) {
    const o = v.length / 3;
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
      v.push(x0! + x! * sx!, y0! + y! * sy!, z0! + z! * sz!);
    for (const i of [
      0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7,
    ])
      f.push(o + i);
  }
  return { positions: new Float32Array(v), indices: new Uint32Array(f) };
}

test('sliceSync returns at once (no promise) the G-code slice() gives, for any thread count asked', async () => {
  for (const options of [
    {},
    { threads: 4, infillPattern: 'gyroid' as const },
    { adhesionType: 'raft' as const, infillPattern: 'lightning' as const },
  ]) {
    const slicer = new Slicer(options);
    const sync = slicer.sliceSync(cube);
    assert.equal(typeof sync.gcode, 'string');
    assert.equal(sync.stats.threads, 1);
    const async = await slicer.slice(cube);
    assert.equal(sync.gcode, async.gcode, JSON.stringify(options));
    assert.equal(sync.stats.layers, async.stats.layers);
    assert.deepEqual(sync.warnings, async.warnings);
  }
});

test('sliceSync: support (the two-phase pipeline) and several objects as the async slice', async () => {
  const slicer = new Slicer({ supportEnabled: true, supportType: 'tree' });
  const input = [tee(), cube];
  const sync = slicer.sliceSync(input);
  assert.match(sync.gcode, /;TYPE:SUPPORT/);
  assert.equal(sync.gcode, (await slicer.slice(input)).gcode);
});

test('sliceSync: a custom infill shader needs its compiler loaded (the Node entry loads it), then slices as the async slice', async () => {
  const shader = 'vec4 cellular(vec3 p) { return vec4(floor(p.x / 4.0), floor(p.y / 4.0), 0.0, 1.0); }';
  const slicer = new Slicer({ customInfill: { name: 'squares', shader } });
  // this file imports the API without the Node entry, as a browser bundle does: nothing is loaded yet
  assert.throws(() => slicer.sliceSync(cube), /needs the shader compiler loaded first: await loadCustomInfill\(\)/);
  await loadCustomInfill();
  assert.equal(slicer.sliceSync(cube).gcode, (await slicer.slice(cube)).gcode);
});

test('sliceSync: an aborted signal stops it with CANCELLED; bad input throws as slice() rejects', async () => {
  const ac = new AbortController();
  ac.abort(new Error('stop'));
  assert.throws(
    () => new Slicer().sliceSync(cube, { signal: ac.signal }),
    (e) => e instanceof StrataError && e.code === 'CANCELLED',
  );
  const bad = new Uint8Array([1, 2, 3]);
  let asyncError: unknown;
  await new Slicer().slice(bad).catch((e) => (asyncError = e));
  assert.throws(
    () => new Slicer().sliceSync(bad),
    (e) => e instanceof StrataError && e.message === (asyncError as Error).message,
  );
});

test('sliceSync reports progress up to 1', () => {
  let last = 0;
  new Slicer().sliceSync(cube, { onProgress: (p) => (last = p.fraction) });
  assert.equal(last, 1);
});
