/**
 * An abort reaches a custom shader's layer: a heavy shader spends seconds on each layer (within its step
 * budget), and an abort acts within a fraction of a second, not when the layer is done; one or more
 * threads. The G-code of a custom infill does not depend on where its layers are computed.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { Slicer } from '#strata/api/slicer.js';
import { loadCustomInfill } from '#strata/exports.js';
import { StrataError } from '#strata/errors.js';
import { HEAVY_SHADER } from '../shader/test-heavy-shader.js';

const CUBE = new Uint8Array(
  readFileSync(fileURLToPath(new URL('../../../examples/calibration-cube.stl', import.meta.url))),
);

/** Longest from abort to the rejection, ms (asked: 100; a loaded test machine takes more). */
const ABORT_MS = 1000;

for (const threads of [1, 2]) {
  test(`an abort during a heavy custom shader's layer stops the slice at once (${threads} thread${threads > 1 ? 's' : ''})`, {
    timeout: 120_000,
  }, async () => {
    await loadCustomInfill();
    const ac = new AbortController();
    let sliced = false;
    const slice = new Slicer({ threads, customInfill: { name: 'heavy', shader: HEAVY_SHADER } }).slice(CUBE, {
      signal: ac.signal,
      onProgress: (p) => (sliced ||= p.stage === 'slicing'),
    });
    slice.catch(() => {});
    // well into the first layers' shader work
    await new Promise((r) => setTimeout(r, 2500));
    const t0 = performance.now();
    ac.abort(new Error('stop'));
    await assert.rejects(slice, (e: unknown) => e instanceof StrataError && e.code === 'CANCELLED');
    const ms = performance.now() - t0;
    assert.ok(ms < ABORT_MS, `rejected ${Math.round(ms)} ms after the abort`);
    console.log(
      `abort to rejection with a heavy shader, ${threads} thread${threads > 1 ? 's' : ''}: ${Math.round(ms)} ms`,
    );
  });
}

test('a custom infill gives the same G-code in workers (slice) as on the calling thread (sliceSync)', async () => {
  await loadCustomInfill();
  const options = {
    threads: 1,
    customInfill: {
      name: 'hexagon',
      shader: 'vec4 cellular(vec3 p) { return vec4(floor(p.x / 3.0), floor(p.y / 3.0), 0.0, 1.0); }',
    },
  };
  const inWorkers = (await new Slicer(options).slice(CUBE)).gcode;
  const inline = new Slicer(options).sliceSync(CUBE).gcode;
  assert.ok(inWorkers === inline, 'the same G-code');
});
