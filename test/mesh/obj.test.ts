import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '#strata/errors.js';
import { parseObj } from '#strata/mesh/obj.js';

function throwsStrata(fn: () => unknown, code: string, re?: RegExp): void {
  assert.throws(fn, (e: unknown) => {
    assert.ok(e instanceof StrataError, `expected StrataError, got ${String(e)}`);
    assert.equal(e.code, code, e.message);
    if (re) assert.match(e.message, re);
    return true;
  });
}

const CUBE = `# unit cube, quads, v/vt/vn
mtllib cube.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vt 0 0
vn 0 0 1
o Cube
usemtl grey
s off
f 1/1/1 4/1/1 3/1/1 2/1/1
f 5//1 6//1 7//1 8//1
f 1/1 2/1 6/1 5/1
f 2 3 7 6
f -5 -1 -2 -6
f 4 1 5 8
`;

test('OBJ: v, f in all index forms, quads fan-triangulated into 12 triangles on 8 vertices', () => {
  const objs = parseObj(CUBE, 'cube');
  assert.equal(objs.length, 1);
  assert.equal(objs[0].name, 'Cube');
  assert.equal(objs[0].mesh.indices.length / 3, 12);
  assert.equal(objs[0].mesh.positions.length / 3, 8);
});

test('OBJ: negative indices are relative to the vertices read so far', () => {
  const [o] = parseObj('v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nf -4 -3 -1\n');
  assert.equal(o.mesh.indices.length, 6);
  const p = Array.from(o.mesh.positions);
  assert.deepEqual(p.slice(0, 9), [0, 0, 0, 1, 0, 0, 0, 1, 0]);
  assert.deepEqual(p.slice(9), [5, 5, 5]);
});

test('OBJ: o and g split objects; empty groups are skipped; vertices are shared file-wide', () => {
  const text = `v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\ng empty\no A\nf 1 2 3\ng B\nf 1 2 4\nf 2 3 4\ng\ng C\n`;
  const objs = parseObj(text, 'm');
  assert.deepEqual(
    objs.map((o) => o.name),
    ['A', 'B'],
  );
  assert.equal(objs[0].mesh.indices.length, 3);
  assert.equal(objs[1].mesh.indices.length, 6);
  assert.equal(objs[1].mesh.positions.length / 3, 4); // only the vertices B uses
});

test('OBJ: unnamed faces use the given name; bytes input, CRLF and comments work', () => {
  const bytes = new TextEncoder().encode('v 0 0 0\r\nv 1 0 0 # x\r\nv 0 1 0\r\n\r\nf 1 2 3 # tri\r\n');
  const objs = parseObj(bytes, 'tri');
  assert.equal(objs[0].name, 'tri');
  assert.equal(objs[0].mesh.indices.length, 3);
});

test('OBJ errors name the line', () => {
  throwsStrata(() => parseObj('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n'), 'BAD_FILE', /line 4: .*vertex 9/);
  throwsStrata(() => parseObj('v 0 0 0\nf 0 1 1\n'), 'BAD_FILE', /line 2/);
  throwsStrata(() => parseObj('v 0 0 0\nf -2 1 1\n'), 'BAD_FILE', /before the first vertex/);
  throwsStrata(() => parseObj('v 0 0\n'), 'BAD_FILE', /line 1: a vertex needs 3/);
  throwsStrata(() => parseObj('v 0 zero 0\n'), 'BAD_FILE', /not a number/);
  throwsStrata(() => parseObj('v 0 0 0\nv 1 0 0\nf 1 2\n'), 'BAD_FILE', /at least 3/);
  throwsStrata(() => parseObj('v 0 0 0\nf a b c\n'), 'BAD_FILE', /not a valid vertex index/);
  throwsStrata(() => parseObj('v 0 0 0\nv 1 0 0\nv 0 1 0\n'), 'EMPTY_MODEL');
  throwsStrata(() => parseObj(''), 'EMPTY_MODEL');
  throwsStrata(() => parseObj('v 1e999 0 0\n'), 'BAD_FILE');
});
