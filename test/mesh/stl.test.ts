import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gunzipSync } from 'node:zlib';
import { StrataError } from '#strata/errors.js';
import { parseStl } from '#strata/mesh/stl.js';
import type { Mesh } from '#strata/mesh/types.js';
import { MODELS_DIR } from '../e2e/models-dir.js';

const MODELS = MODELS_DIR;
const read = (f: string): Uint8Array => new Uint8Array(readFileSync(join(MODELS, f)));

function size(mesh: Mesh): number[] {
  const p = mesh.positions;
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < p.length; i++) {
    lo[i % 3] = Math.min(lo[i % 3], p[i]);
    hi[i % 3] = Math.max(hi[i % 3], p[i]);
  }
  return hi.map((h, k) => h - lo[k]);
}

function assertSize(mesh: Mesh, expected: number[], tol = 0.06): void {
  const s = size(mesh);
  for (let k = 0; k < 3; k++) assert.ok(Math.abs(s[k] - expected[k]) < tol, `axis ${k}: ${s[k]} vs ${expected[k]}`);
}

function throwsStrata(fn: () => unknown, code?: string, re?: RegExp): void {
  assert.throws(fn, (e: unknown) => {
    assert.ok(e instanceof StrataError, `expected StrataError, got ${String(e)}`);
    if (code) assert.equal(e.code, code, e.message);
    if (re) assert.match(e.message, re);
    assert.ok(!e.message.includes('\n'), 'one-line message');
    return true;
  });
}

// Triangle counts and bounding-box sizes from the shared models' SOURCES.md.
const SHARED: [string, number, number[]][] = [
  ['CalibrationCube.stl', 136, [20, 20, 20]],
  ['HollowCalibrationCube.stl', 160, [20, 20, 20]],
  ['HoleTest.stl', 16126, [62.3, 60.4, 5.0]],
  ['Overhang.stl', 3280, [52.5, 12.0, 32.1]],
  ['SupportTest.stl', 3242, [41.2, 41.3, 20.0]],
  ['BridgeTest.stl', 10090, [86.4, 45.6, 20.2]],
  ['spot.stl', 5856, [37.7, 68.7, 67.6]],
  ['stanford-bunny.stl', 69451, [77.9, 60.3, 77.2]],
];

for (const [file, triangles, bbox] of SHARED) {
  test(`STL ${file}: ${triangles} triangles, ${bbox.join(' × ')} mm`, () => {
    const objs = parseStl(read(file), 'x');
    assert.equal(objs.length, 1);
    assert.equal(objs[0].mesh.indices.length / 3, triangles);
    assertSize(objs[0].mesh, bbox);
  });
}

test('STL 3DBenchy (binary, starts like any binary): 225154 triangles, 60 × 31 × 48, welded to 112565 vertices', () => {
  const bytes = new Uint8Array(gunzipSync(readFileSync(join(MODELS, '3DBenchy.stl.gz'))));
  const [o] = parseStl(bytes, 'benchy');
  assert.equal(o.name, 'benchy');
  assert.equal(o.mesh.indices.length / 3, 225154);
  assert.equal(o.mesh.positions.length / 3, 112565);
  assertSize(o.mesh, [60.0, 31.0, 48.0]);
});

test('ASCII STL keeps the solid name; binary uses the given name', () => {
  assert.equal(parseStl(read('HollowCalibrationCube.stl'), 'hc')[0].name, 'OpenSCAD_Model');
  assert.equal(parseStl(read('CalibrationCube.stl'), 'cube')[0].name, 'cube');
});

function binaryStl(tris: number[][], header = ''): Uint8Array {
  const b = new Uint8Array(84 + 50 * tris.length);
  b.set(new TextEncoder().encode(header.slice(0, 80)));
  const dv = new DataView(b.buffer);
  dv.setUint32(80, tris.length, true);
  tris.forEach((t, i) => t.forEach((v, k) => dv.setFloat32(84 + 50 * i + 12 + 4 * k, v, true)));
  return b;
}

const TET = [
  [0, 0, 0, 0, 1, 0, 1, 0, 0],
  [0, 0, 0, 0, 0, 1, 0, 1, 0],
  [0, 0, 0, 1, 0, 0, 0, 0, 1],
  [1, 0, 0, 0, 1, 0, 0, 0, 1],
];

test('binary STL whose header begins with "solid" is read as binary (size decides)', () => {
  const [o] = parseStl(binaryStl(TET, 'solid tetra exported by some CAD'));
  assert.equal(o.mesh.indices.length, 12);
  assert.equal(o.mesh.positions.length, 12); // 4 welded vertices
});

test('binary STL: fewer than 50 trailing bytes are tolerated, more are an error', () => {
  const b = binaryStl(TET);
  const padded = new Uint8Array(b.length + 10);
  padded.set(b);
  assert.equal(parseStl(padded)[0].mesh.indices.length, 12);
  const big = new Uint8Array(b.length + 120);
  big.set(b);
  throwsStrata(() => parseStl(big), 'BAD_FILE', /size mismatch/);
});

test('truncated binary STL throws BAD_FILE naming the triangle count', () => {
  const b = binaryStl(TET);
  throwsStrata(() => parseStl(b.subarray(0, b.length - 7)), 'BAD_FILE', /header says 4 triangles/);
  throwsStrata(() => parseStl(b.subarray(0, 60)), 'BAD_FILE', /too short/);
  throwsStrata(() => parseStl(new Uint8Array(0)), 'BAD_FILE');
});

test('hostile binary STL: huge triangle count in a small file', () => {
  const b = binaryStl(TET);
  new DataView(b.buffer).setUint32(80, 0xffffffff, true);
  throwsStrata(() => parseStl(b), 'BAD_FILE', /4294967295 triangles/);
});

test('binary STL with NaN coordinates throws BAD_MESH', () => {
  const t = TET.map((r) => r.slice());
  t[2][4] = NaN;
  throwsStrata(() => parseStl(binaryStl(t)), 'BAD_MESH', /triangle 2/);
});

test('binary STL with zero triangles throws EMPTY_MODEL', () => {
  throwsStrata(() => parseStl(binaryStl([])), 'EMPTY_MODEL');
});

const enc = (s: string): Uint8Array => new TextEncoder().encode(s);

function asciiFacet(v: number[]): string {
  return `facet normal 0 0 1\n outer loop\n vertex ${v[0]} ${v[1]} ${v[2]}\n vertex ${v[3]} ${v[4]} ${v[5]}\n vertex ${v[6]} ${v[7]} ${v[8]}\n endloop\nendfacet\n`;
}

test('ASCII STL: several solids become several objects', () => {
  const text = `solid first\n${TET.map(asciiFacet).join('')}endsolid first\nsolid second\n${asciiFacet([5, 5, 5, 6, 5, 5, 5, 6, 5])}endsolid second\n`;
  const objs = parseStl(enc(text), 'multi');
  assert.deepEqual(
    objs.map((o) => o.name),
    ['first', 'second'],
  );
  assert.equal(objs[0].mesh.indices.length, 12);
  assert.equal(objs[1].mesh.indices.length, 3);
});

test('ASCII STL: CRLF, tabs, odd spacing, exponent numbers, no endsolid name, unnamed solid', () => {
  const text =
    'solid\r\n\tfacet   normal 0.0E+00 0 -1e0\r\n  outer\tloop\r\n' +
    '   vertex 1.5e1 -0 +2\r\nvertex 1E-3   2.5E+0 0\r\n\t\tvertex -3.25 4 5e-1\r\n endloop\r\n  endfacet\r\nendsolid\r\n';
  const [o] = parseStl(enc(text), 'odd');
  assert.equal(o.name, 'odd');
  assert.deepEqual(Array.from(o.mesh.positions), [15, 0, 2, 0.0010000000474974513, 2.5, 0, -3.25, 4, 0.5]);
});

test('ASCII STL: a quad facet is fan-triangulated', () => {
  const text =
    'solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid q\n';
  assert.equal(parseStl(enc(text))[0].mesh.indices.length, 6);
});

test('ASCII STL errors: truncated facet, bad number, stray token, empty', () => {
  const good = `solid a\n${asciiFacet([0, 0, 0, 1, 0, 0, 0, 1, 0])}endsolid a\n`;
  const cut = good.slice(0, good.indexOf('endloop'));
  throwsStrata(() => parseStl(enc(cut)), 'BAD_FILE', /ends inside a facet/);
  throwsStrata(
    () => parseStl(enc(good.slice(0, good.indexOf('1 0 0') + 2))),
    'BAD_FILE',
    /line 5: the file ends where a vertex coordinate was expected/,
  );
  throwsStrata(
    () => parseStl(enc(good.replace('vertex 1 0 0', 'vertex 1 zero 0'))),
    'BAD_FILE',
    /"zero" is not a number/,
  );
  throwsStrata(() => parseStl(enc(good.replace('outer loop', 'outer loop banana'))), 'BAD_FILE', /unexpected "banana"/);
  throwsStrata(() => parseStl(enc(good.replace('vertex 0 1 0\n', ''))), 'BAD_FILE', /2 vertices/);
  throwsStrata(() => parseStl(enc('solid empty\nendsolid empty\n')), 'EMPTY_MODEL');
  throwsStrata(() => parseStl(enc('solid x\nvertex 1 2 3\n')), 'BAD_FILE', /outside a facet/);
});

test('garbage bytes throw StrataError, never a TypeError', () => {
  let seed = 12345;
  const rnd = (): number => {
    seed = (Math.imul(seed, 1103515245) + 12345) >>> 0;
    return seed >>> 24;
  };
  for (const n of [1, 10, 83, 84, 85, 134, 500, 5000]) {
    const b = new Uint8Array(n);
    for (let i = 0; i < n; i++) b[i] = rnd();
    throwsStrata(() => parseStl(b));
  }
  throwsStrata(() => parseStl(enc('solid '.padEnd(300, '\u0001'))));
});
