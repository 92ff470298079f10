import { test } from 'node:test';
import assert from 'node:assert/strict';
import { countSet, gridAround } from './grid.js';
import { createSectioner, meshSection, rasterizeSection, sectionSpans } from './section.js';
import { dilateSpans, erodeSpans, spansArea, spansBoolean, spansContain } from './spans.js';
import { boxMesh, dropTriangles, flipMesh } from './synthetic-print.js';

const near = (a: number, b: number, tol: number, what = '') =>
  assert.ok(Math.abs(a - b) <= tol, `${what} ${a} is not within ${tol} of ${b}`);

function signedArea(s: ReturnType<typeof meshSection>): number {
  let a = 0;
  for (let i = 0; i < s.count; i++) a += s.x0[i]! * s.y1[i]! - s.x1[i]! * s.y0[i]!;
  return a / 2;
}

test('a box section is a counter-clockwise rectangle', () => {
  const box = boxMesh(1, 2, 0, 21, 12, 5);
  const s = meshSection(box, 2.5);
  assert.equal(s.gapsClosed, 0);
  near(signedArea(s), 200, 1e-6, 'signed area');
  assert.equal(meshSection(box, 6).count, 0);
  // Vertices on the plane count as above it: a plane through the top face still cuts the walls, one through the
  // bottom face does not.
  near(signedArea(meshSection(box, 5)), 200, 1e-6, 'at the top face');
  assert.equal(meshSection(box, 0).count, 0);
  const sectioner = createSectioner(box);
  near(signedArea(sectioner.section(2.5)), 200, 1e-6, 'sectioner');
  assert.equal(sectioner.section(5.5).count, 0);
});

test('rasterised section area matches, with the nonzero rule for inward-facing meshes', () => {
  const box = boxMesh(0.013, 0.027, 0, 10.013, 5.027, 3);
  const grid = gridAround(0, 0, 10, 5, 0.05, 1);
  const cellArea = 0.05 * 0.05;
  const area = countSet(rasterizeSection(meshSection(box, 1), grid)) * cellArea;
  near(area, 50, 0.5, 'raster area');
  const flipped = meshSection(flipMesh(box), 1);
  near(signedArea(flipped), -50, 1e-4, 'flipped orientation');
  near(countSet(rasterizeSection(flipped, grid)) * cellArea, 50, 0.5, 'flipped raster');
  near(spansArea(sectionSpans(meshSection(box, 1), 0.05)), 50, 0.3, 'spans area');
});

test('an open mesh is closed, not leaked along scanlines', () => {
  // Drop the right (+x) face: every section is a U that must be closed across x = 10.
  const box = boxMesh(0, 0, 0, 10, 5, 3);
  const open = dropTriangles(box, (t) => t === 10 || t === 11);
  const s = meshSection(open, 1);
  assert.equal(s.gapsClosed, 1);
  assert.equal(
    s.synthetic.reduce((a, b) => a + b, 0),
    1,
  );
  const grid = gridAround(0, 0, 10, 5, 0.05, 3);
  near(countSet(rasterizeSection(s, grid)) * 0.0025, 50, 0.5, 'closed area');
  // Two separate boxes, each missing a face, stay two regions.
  const twoOpen = [
    dropTriangles(boxMesh(0, 0, 0, 4, 4, 2), (t) => t === 10),
    dropTriangles(boxMesh(6, 0, 0, 10, 4, 2), (t) => t === 4),
  ];
  const merged = mergeMeshes(twoOpen[0]!, twoOpen[1]!);
  const spans = sectionSpans(meshSection(merged, 1), 0.05);
  near(spansArea(spans), 32, 0.5, 'two boxes');
  assert.equal(spansContain(spans, 5, 2), false, 'the gap between the boxes stays empty');
});

test('a stray open flap is left out rather than joined across the part', () => {
  // A closed box plus one lone triangle inside it: the triangle's cut is an open segment far from anything.
  const box = boxMesh(0, 0, 0, 10, 10, 2);
  const flap = {
    positions: new Float32Array([2, 3, 0, 8, 3, 0, 5, 3, 2]),
    indices: new Uint32Array([0, 1, 2]),
  };
  const s = meshSection(mergeMeshes(box, flap), 1);
  assert.equal(s.chainsDropped, 1);
  near(spansArea(sectionSpans(s, 0.05)), 100, 0.5, 'box area');
});

test('span booleans, growing and shrinking', () => {
  const a = sectionSpans(meshSection(boxMesh(0, 0, 0, 10, 10, 1), 0.5), 0.05);
  const b = sectionSpans(meshSection(boxMesh(5, 5, 0, 15, 15, 1), 0.5), 0.05);
  near(spansArea(spansBoolean(a, b, 'union')), 175, 1, 'union');
  near(spansArea(spansBoolean(a, b, 'intersect')), 25, 0.5, 'intersect');
  near(spansArea(spansBoolean(a, b, 'subtract')), 75, 0.5, 'subtract');
  near(spansArea(erodeSpans(a, 1)), 64, 0.5, 'eroded');
  // Grown by r: the square, four side strips and four quarter discs.
  near(spansArea(dilateSpans(a, 1)), 100 + 40 + Math.PI, 0.6, 'dilated');
});

function mergeMeshes(a: { positions: Float32Array; indices: Uint32Array }, b: typeof a) {
  const positions = new Float32Array(a.positions.length + b.positions.length);
  positions.set(a.positions);
  positions.set(b.positions, a.positions.length);
  const offset = a.positions.length / 3;
  const indices = new Uint32Array(a.indices.length + b.indices.length);
  indices.set(a.indices);
  indices.set(
    b.indices.map((i) => i + offset),
    a.indices.length,
  );
  return { positions, indices };
}
