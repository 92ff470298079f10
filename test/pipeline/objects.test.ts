import { test } from 'node:test';
import assert from 'node:assert/strict';
import { footprintHull, planObjects } from '#strata/pipeline/objects.js';

/** Every point inside or on the hull, and every hull vertex one of the points. */
function checkHull(xy: number[], hull: [number, number][]): void {
  const pts = new Set<string>();
  for (let i = 0; i < xy.length; i += 2)
    pts.add(`${Math.round(xy[i] * 1000) / 1000},${Math.round(xy[i + 1] * 1000) / 1000}`);
  for (const h of hull) assert.ok(pts.has(`${h[0]},${h[1]}`), `hull vertex ${h} is a point`);
  for (let i = 0; i < xy.length; i += 2) {
    for (let k = 0; k < hull.length; k++) {
      const a = hull[k],
        b = hull[(k + 1) % hull.length];
      const c = (b[0] - a[0]) * (xy[i + 1] - a[1]) - (b[1] - a[1]) * (xy[i] - a[0]);
      // vertices are rounded to the µm: a point may lie that far out
      assert.ok(c / Math.hypot(b[0] - a[0], b[1] - a[1]) >= -1e-3, `point ${xy[i]},${xy[i + 1]} outside edge ${k}`);
    }
  }
}

test('the footprint hull holds every vertex and is made of vertices (random clouds, a circle)', () => {
  let seed = 7;
  const rnd = () => (seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648;
  for (let run = 0; run < 5; run++) {
    const n = 2000;
    const positions = new Float32Array(3 * n);
    for (let v = 0; v < n; v++) {
      const r = run % 2 ? 40 : 40 * Math.sqrt(rnd());
      const t = rnd() * 2 * Math.PI;
      positions[3 * v] = 100 + r * Math.cos(t);
      positions[3 * v + 1] = 80 + r * Math.sin(t) * (run === 4 ? 0.2 : 1);
      positions[3 * v + 2] = rnd() * 10;
    }
    const indices = Uint32Array.from({ length: n }, (_, i) => i);
    const hull = footprintHull({ positions, indices });
    assert.ok(hull.length >= 3);
    const xy: number[] = [];
    for (let v = 0; v < n; v++) xy.push(positions[3 * v], positions[3 * v + 1]);
    checkHull(xy, hull);
  }
});

test('plan objects get safe, unique names and their footprint centre', () => {
  const square = {
    positions: new Float32Array([0, 0, 0, 10, 0, 0, 10, 10, 0, 0, 10, 5]),
    indices: new Uint32Array([0, 1, 2, 0, 2, 3]),
  };
  const objs = planObjects([
    { name: 'my cube', mesh: square },
    { name: 'my cube', mesh: square },
    { name: ';;', mesh: square },
  ]);
  assert.deepEqual(
    objs.map((o) => o.name),
    ['my_cube', 'my_cube_2', 'object'],
  );
  assert.deepEqual(objs[0].center, [5, 5]);
  assert.deepEqual(objs[0].polygon, [
    [0, 0],
    [10, 0],
    [10, 10],
    [0, 10],
  ]);
});
