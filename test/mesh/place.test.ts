import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '#strata/errors.js';
import { mergeObjects, placeModels, type ModelInput, type PlaceOptions } from '#strata/mesh/place.js';
import type { Mesh, MeshObject } from '#strata/mesh/types.js';

/** An axis-aligned box from (x0,y0,z0) to (x1,y1,z1) as 8 vertices / 12 triangles. */
function box(x0: number, y0: number, z0: number, x1: number, y1: number, z1: number): Mesh {
  const p: number[] = [];
  for (let i = 0; i < 8; i++) p.push(i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0);
  const f = [
    0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5,
  ];
  return { positions: new Float32Array(p), indices: new Uint32Array(f) };
}

function bounds(m: Mesh): number[][] {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < m.positions.length; i++) {
    lo[i % 3] = Math.min(lo[i % 3], m.positions[i]);
    hi[i % 3] = Math.max(hi[i % 3], m.positions[i]);
  }
  return [lo, hi];
}

const BED: PlaceOptions = { center: true, bedWidth: 220, bedLength: 220, bedHeight: 250, originAtCenter: false };

/** One model of one object, placed: the placed mesh and the translation. */
function placeOnBed(mesh: Mesh, opts: PlaceOptions): { mesh: Mesh; offset: [number, number, number] } {
  const r = placeModels([{ name: 'the model', objects: [{ name: 'm', mesh }] }], opts);
  return { mesh: r.objects[0].mesh, offset: r.offsets[0] };
}

test('mergeObjects concatenates meshes and offsets indices', () => {
  const objs: MeshObject[] = [
    { name: 'a', mesh: box(0, 0, 0, 1, 1, 1) },
    { name: 'b', mesh: box(10, 0, 0, 12, 1, 1) },
  ];
  const m = mergeObjects(objs);
  assert.equal(m.positions.length, 48);
  assert.equal(m.indices.length, 72);
  assert.equal(m.indices[36], 8);
  assert.deepEqual(bounds(m), [
    [0, 0, 0],
    [12, 1, 1],
  ]);
  assert.equal(mergeObjects([]).indices.length, 0);
});

test('placeOnBed centres on the bed and drops to z = 0', () => {
  const { mesh, offset } = placeOnBed(box(-10, -5, 3, 10, 5, 13), BED);
  assert.deepEqual(bounds(mesh), [
    [100, 105, 0],
    [120, 115, 10],
  ]);
  assert.deepEqual(offset, [110, 110, -3]);
});

test('placeOnBed with originAtCenter centres on (0, 0)', () => {
  const { mesh } = placeOnBed(box(50, 60, -2, 70, 80, 8), { ...BED, originAtCenter: true });
  assert.deepEqual(bounds(mesh), [
    [-10, -10, 0],
    [10, 10, 10],
  ]);
});

test('placeOnBed without center keeps XY and still drops to z = 0', () => {
  const { mesh, offset } = placeOnBed(box(30, 40, 5, 50, 60, 25), { ...BED, center: false });
  assert.deepEqual(bounds(mesh), [
    [30, 40, 0],
    [50, 60, 20],
  ]);
  assert.deepEqual(offset, [0, 0, -5]);
});

function doesNotFit(fn: () => unknown, re: RegExp): void {
  assert.throws(fn, (e: unknown) => {
    assert.ok(e instanceof StrataError);
    assert.equal(e.code, 'DOES_NOT_FIT');
    assert.match(e.message, re);
    return true;
  });
}

test('too wide, too deep or too tall: DOES_NOT_FIT naming the size, the volume and the axis', () => {
  doesNotFit(
    () => placeOnBed(box(0, 0, 0, 250, 30, 48), BED),
    /^the model is 250\.0 × 30\.0 × 48\.0 mm and does not fit the 220 × 220 × 250 mm build volume \(250\.0 mm wide in X/,
  );
  doesNotFit(() => placeOnBed(box(0, 0, 0, 10, 221, 10), BED), /221\.0 mm deep in Y/);
  doesNotFit(() => placeOnBed(box(0, 0, 0, 10, 10, 300), BED), /300\.0 mm tall in Z, the volume 250 mm/);
});

test('without centring, a model partly off the plate is refused, saying which side and by how much', () => {
  doesNotFit(
    () => placeOnBed(box(-30, 10, 0, 10, 20, 5), { ...BED, center: false }),
    /^the model leaves the bed by 30\.0 mm past the left edge \(X -30\.0 to 10\.0 mm, the bed 0 to 220 mm\)/,
  );
  doesNotFit(
    () => placeOnBed(box(10, 200, 0, 20, 240, 5), { ...BED, center: false }),
    /20\.0 mm past the back edge \(Y 200\.0 to 240\.0 mm/,
  );
  // a 20 mm cube centred on the origin is 10 mm off at the left and at the front, and does fit the bed's size
  doesNotFit(
    () => placeOnBed(box(-10, -10, 0, 10, 10, 20), { ...BED, center: false }),
    /10\.0 mm past the left edge .* and 10\.0 mm past the front edge/,
  );
  // With an origin at the centre, (-30..10) is on a 220 mm plate.
  assert.doesNotThrow(() => placeOnBed(box(-30, 10, 0, 10, 20, 5), { ...BED, center: false, originAtCenter: true }));
});

test('a model exactly the bed size fits', () => {
  assert.doesNotThrow(() => placeOnBed(box(0, 0, 0, 220, 220, 250), BED));
});

test('empty model and nonsense bed sizes are refused', () => {
  assert.throws(
    () => placeOnBed({ positions: new Float32Array(0), indices: new Uint32Array(0) }, BED),
    (e: unknown) => e instanceof StrataError && e.code === 'EMPTY_MODEL',
  );
  assert.throws(
    () => placeOnBed(box(0, 0, 0, 1, 1, 1), { ...BED, bedWidth: -1 }),
    (e: unknown) => e instanceof StrataError && e.code === 'BAD_SETTING',
  );
  assert.throws(
    () => placeOnBed(box(0, 0, 0, 1, 1, 1), { ...BED, bedHeight: NaN }),
    (e: unknown) => e instanceof StrataError && e.code === 'BAD_SETTING',
  );
});

const model = (name: string, ...meshes: Mesh[]): ModelInput => ({
  name,
  objects: meshes.map((mesh, i) => ({ name: `${name} ${i}`, mesh })),
});

function footprint(m: Mesh): { x0: number; y0: number; x1: number; y1: number } {
  const [lo, hi] = bounds(m);
  return { x0: lo[0], y0: lo[1], x1: hi[0], y1: hi[1] };
}

test('several models are arranged around the bed centre, spacing apart, inside the bed', () => {
  // five 20 mm cubes all at the same place, and one long bar
  const models = [0, 1, 2, 3, 4].map((i) => model(`cube${i}`, box(0, 0, 0, 20, 20, 20)));
  models.push(model('bar', box(-5, 0, 3, 95, 10, 13)));
  const r = placeModels(models, { ...BED, spacing: 6 });
  const fps = r.objects.map((o) => footprint(o.mesh));
  for (let i = 0; i < fps.length; i++) {
    const a = fps[i];
    assert.ok(
      a.x0 >= -1e-4 && a.y0 >= -1e-4 && a.x1 <= 220 + 1e-4 && a.y1 <= 220 + 1e-4,
      `inside the bed: ${JSON.stringify(a)}`,
    );
    for (let j = i + 1; j < fps.length; j++) {
      const b = fps[j];
      const gapX = Math.max(b.x0 - a.x1, a.x0 - b.x1);
      const gapY = Math.max(b.y0 - a.y1, a.y0 - b.y1);
      assert.ok(Math.max(gapX, gapY) >= 6 - 1e-4, `models ${i} and ${j} are at least 6 mm apart (${gapX}, ${gapY})`);
    }
  }
  // packed around the centre: the group's bounding box is centred and compact
  const gx0 = Math.min(...fps.map((f) => f.x0)),
    gx1 = Math.max(...fps.map((f) => f.x1));
  const gy0 = Math.min(...fps.map((f) => f.y0)),
    gy1 = Math.max(...fps.map((f) => f.y1));
  assert.ok(Math.abs((gx0 + gx1) / 2 - 110) < 1e-3 && Math.abs((gy0 + gy1) / 2 - 110) < 1e-3);
  assert.ok((gx1 - gx0) * (gy1 - gy0) < 2 * (100 * 10 + 5 * 26 * 26), `compact: ${gx1 - gx0} × ${gy1 - gy0}`);
  // every model dropped to z = 0, and the same input gives the same arrangement
  for (const o of r.objects) assert.equal(bounds(o.mesh)[0][2], 0);
  assert.deepEqual(placeModels(models, { ...BED, spacing: 6 }).offsets, r.offsets);
  // a wider spacing moves them further apart
  const wide = placeModels(models, { ...BED, spacing: 20 }).objects.map((o) => footprint(o.mesh));
  const span = (fs: typeof fps) =>
    (Math.max(...fs.map((f) => f.x1)) - Math.min(...fs.map((f) => f.x0))) *
    (Math.max(...fs.map((f) => f.y1)) - Math.min(...fs.map((f) => f.y0)));
  assert.ok(span(wide) > span(fps), `${span(wide)} > ${span(fps)}`);
});

test("a model's objects keep their places relative to each other", () => {
  const r = placeModels(
    [model('pair', box(0, 0, 0, 10, 10, 10), box(30, 0, 5, 40, 10, 15)), model('other', box(0, 0, 0, 10, 10, 10))],
    BED,
  );
  const [a, b] = r.objects.map((o) => bounds(o.mesh));
  assert.equal(b[0][0] - a[0][0], 30);
  assert.equal(b[0][2] - a[0][2], 5, 'the model is dropped as a whole, not each object');
});

test('models that cannot all fit together are refused, naming the count and the spacing', () => {
  const big = [0, 1, 2].map((i) => model(`m${i}`, box(0, 0, 0, 120, 120, 10)));
  doesNotFit(() => placeModels(big, BED), /^the 3 models do not fit on the 220 × 220 mm bed together, 6 mm apart/);
});

test('without centring, each model keeps its XY (overlaps are resolved by the plate, print-setup.ts)', () => {
  const r = placeModels([model('a', box(10, 10, 2, 30, 30, 12)), model('b', box(20, 20, 0, 40, 40, 10))], {
    ...BED,
    center: false,
  });
  assert.deepEqual(bounds(r.objects[0].mesh), [
    [10, 10, 0],
    [30, 30, 10],
  ]);
  assert.deepEqual(bounds(r.objects[1].mesh), [
    [20, 20, 0],
    [40, 40, 10],
  ]);
});

test('rotation and scale are applied before placing (quarter turns exact)', () => {
  const bar = box(0, 0, 0, 40, 10, 5);
  const turned = placeModels([model('bar', bar)], {
    ...BED,
    transform: { upAxis: 'z', rotate: [0, 0, 90], scale: [1, 1, 1] },
  }).objects[0].mesh;
  assert.deepEqual(bounds(turned), [
    [105, 90, 0],
    [115, 130, 5],
  ]);
  const scaled = placeModels([model('bar', bar)], {
    ...BED,
    transform: { upAxis: 'z', rotate: [0, 0, 0], scale: [2, 1, 3] },
  }).objects[0].mesh;
  assert.deepEqual(bounds(scaled), [
    [70, 105, 0],
    [150, 115, 15],
  ]);
  // Y-up input: its +Y becomes +Z
  const yUp = placeModels([model('bar', bar)], {
    ...BED,
    transform: { upAxis: 'y', rotate: [0, 0, 0], scale: [1, 1, 1] },
  }).objects[0].mesh;
  const [lo, hi] = bounds(yUp);
  assert.deepEqual([hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]], [40, 5, 10]);
  // a rotation about X keeps the winding (outward normals, positive volume)
  const tilted = placeModels([model('bar', bar)], {
    ...BED,
    transform: { upAxis: 'z', rotate: [30, 0, 0], scale: [1, 1, 1] },
  }).objects[0].mesh;
  assert.ok(volume(tilted) > 0 && Math.abs(volume(tilted) - 2000) < 0.01, String(volume(tilted)));
  // too big after scaling
  doesNotFit(
    () => placeModels([model('bar', bar)], { ...BED, transform: { upAxis: 'z', rotate: [0, 0, 0], scale: [6, 1, 1] } }),
    /^bar is 240\.0 × 10\.0 × 5\.0 mm/,
  );
});

function volume(m: Mesh): number {
  const p = m.positions,
    f = m.indices;
  let v = 0;
  for (let t = 0; t < f.length; t += 3) {
    const a = f[t] * 3,
      b = f[t + 1] * 3,
      c = f[t + 2] * 3;
    v +=
      p[a] * (p[b + 1] * p[c + 2] - p[b + 2] * p[c + 1]) -
      p[a + 1] * (p[b] * p[c + 2] - p[b + 2] * p[c]) +
      p[a + 2] * (p[b] * p[c + 1] - p[b + 1] * p[c]);
  }
  return v / 6;
}

test('the skirt or brim around the models must fit on the bed too', () => {
  const skirt = { mm: 3.4, what: 'skirt' };
  assert.doesNotThrow(() => placeModels([model('m', box(0, 0, 0, 213, 20, 5))], { ...BED, margin: skirt }));
  doesNotFit(
    () => placeModels([model('m', box(0, 0, 0, 215, 20, 5))], { ...BED, margin: skirt }),
    /215\.0 mm wide in X \(221\.8 mm with its skirt\), the bed 220 mm/,
  );
  doesNotFit(
    () => placeModels([model('m', box(2, 50, 0, 22, 70, 5))], { ...BED, center: false, margin: skirt }),
    /^m leaves the bed by 1\.4 mm past the left edge \(X 2\.0 to 22\.0 mm with its 3\.4 mm skirt, the bed 0 to 220 mm\)/,
  );
  // arranged models keep their skirt on the bed
  const r = placeModels([model('a', box(0, 0, 0, 100, 100, 5)), model('b', box(0, 0, 0, 100, 100, 5))], {
    ...BED,
    spacing: 6,
    margin: skirt,
  });
  for (const o of r.objects) {
    const [lo, hi] = bounds(o.mesh);
    assert.ok(lo[0] >= 3.4 - 1e-3 && hi[0] <= 220 - 3.4 + 1e-3 && lo[1] >= 3.4 - 1e-3 && hi[1] <= 220 - 3.4 + 1e-3);
  }
});
