import { test } from 'node:test';
import assert from 'node:assert/strict';
import { weld } from '#strata/mesh/weld.js';

test('welding numbers vertices in the order triangles first use them, however many are distinct (the table grows)', () => {
  for (const [corners, range] of [
    [9, 3],
    [60_000, 40],
    [60_000, 100_000],
  ] as const) {
    let s = 7;
    const next = () => (s = (s * 48271) % 2147483647) % range;
    const p = new Float32Array(corners * 3);
    for (let i = 0; i < p.length; i++) p[i] = next();
    // every tenth triangle repeats its first corner as its second
    for (let t = 0; t < corners / 3; t += 10) p.copyWithin(9 * t + 3, 9 * t, 9 * t + 3);
    const w = weld(p, null);
    const seen = new Map<string, number>();
    const ids: number[] = [];
    for (let v = 0; v < corners; v++) {
      const k = `${p[3 * v]},${p[3 * v + 1]},${p[3 * v + 2]}`;
      if (!seen.has(k)) seen.set(k, seen.size);
      ids.push(seen.get(k)!);
    }
    assert.equal(w.positions.length, 3 * seen.size, `${corners} corners`);
    assert.deepEqual([...w.indices], ids);
    for (const [k, id] of seen)
      assert.equal(`${w.positions[3 * id]},${w.positions[3 * id + 1]},${w.positions[3 * id + 2]}`, k);
  }
});
