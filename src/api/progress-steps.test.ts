import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { Slicer } from './slicer.js';

const cube = readFileSync(fileURLToPath(new URL('../../examples/calibration-cube.stl', import.meta.url)));

test('progressSteps: finer progress on one thread, the same G-code', async () => {
  const slicer = new Slicer({ threads: 1 });
  const seen = (into: number[]) => ({ onProgress: (p: { stage: string; fraction: number }) => p.stage === 'slicing' && into.push(p.fraction) });
  const one: number[] = [], ten: number[] = [];
  const a = await slicer.slice(cube, seen(one));
  const b = await slicer.slice(cube, { ...seen(ten), progressSteps: 10 });
  assert.ok(a.gcode === b.gcode, 'identical G-code');
  assert.equal(one.length, 1);
  assert.equal(ten.length, 10);
  assert.ok(ten.every((f, i) => i === 0 || f > ten[i - 1]), 'progress grows');
});

test('progressSteps: a slice cancelled between steps stops with CANCELLED', async () => {
  const controller = new AbortController();
  const slicer = new Slicer({ threads: 1 });
  await assert.rejects(
    slicer.slice(cube, { progressSteps: 20, signal: controller.signal, onProgress: (p) => p.fraction > 0.1 && controller.abort() }),
    (e: Error & { code?: string }) => e.code === 'CANCELLED',
  );
});
