import { test } from 'node:test';
import assert from 'node:assert/strict';
import { arrange, ARRANGE_GAP_MM, findSpot, footprintsOverlap, type Bed } from '#strata/mesh/arrange.js';

const bed: Bed = { center: [110, 110], width: 220, depth: 220 };

test('one object goes to the bed centre', () => {
  assert.deepEqual(arrange([{ width: 20, depth: 30 }], bed), [[110, 110]]);
});

test('several objects are arranged on the bed without overlap, with the gap between them', () => {
  const items = [
    { width: 60, depth: 40 },
    { width: 20, depth: 20 },
    { width: 80, depth: 80 },
    { width: 20, depth: 50 },
    { width: 35, depth: 35 },
    { width: 10, depth: 10 },
  ];
  const centres = arrange(items, bed);
  const placed = items.map((f, i) => ({ ...f, center: centres[i] }));
  assert.deepEqual(centres[2], [110, 110], 'the largest takes the centre');
  for (let i = 0; i < placed.length; i++) {
    const p = placed[i];
    assert.ok(p.center[0] - p.width / 2 >= 0 && p.center[0] + p.width / 2 <= 220, `x of ${i} on the bed`);
    assert.ok(p.center[1] - p.depth / 2 >= 0 && p.center[1] + p.depth / 2 <= 220, `y of ${i} on the bed`);
    for (let j = 0; j < i; j++) {
      const q = placed[j];
      const gapX = Math.abs(p.center[0] - q.center[0]) - (p.width + q.width) / 2;
      const gapY = Math.abs(p.center[1] - q.center[1]) - (p.depth + q.depth) / 2;
      assert.ok(Math.max(gapX, gapY) >= ARRANGE_GAP_MM - 1e-9, `${i} and ${j} apart: ${gapX}, ${gapY}`);
      assert.ok(!footprintsOverlap(p, q));
    }
  }
});

test('no free spot: findSpot says so, arrange falls back to the centre', () => {
  const big = { width: 200, depth: 200, center: [110, 110] as [number, number] };
  assert.equal(findSpot({ width: 50, depth: 50 }, [big], bed), null);
  const centres = arrange(
    [
      { width: 200, depth: 200 },
      { width: 50, depth: 50 },
    ],
    bed,
  );
  assert.deepEqual(centres[1], [110, 110]);
});
