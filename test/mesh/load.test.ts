import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { strToU8, zipSync } from 'fflate';
import { StrataError } from '#strata/errors.js';
import { detectFormat, loadModelBytes, toMeshObjects } from '#strata/mesh/load.js';
import { MODELS_DIR } from '../e2e/models-dir.js';

const MODELS = MODELS_DIR;
const read = (f: string): Uint8Array => new Uint8Array(readFileSync(join(MODELS, f)));

const OBJ = 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n';
const ASCII =
  'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n';

test('detectFormat: zip magic, binary size, extension, text sniffing', () => {
  assert.equal(detectFormat(read('3DBenchy.3mf')), '3mf');
  assert.equal(detectFormat(read('3DBenchy.3mf'), 'wrong.stl'), '3mf');
  assert.equal(detectFormat(read('CalibrationCube.stl')), 'stl');
  assert.equal(detectFormat(read('CalibrationCube.stl'), 'misnamed.obj'), 'stl');
  assert.equal(detectFormat(read('HollowCalibrationCube.stl')), 'stl');
  assert.equal(detectFormat(strToU8(OBJ)), 'obj');
  assert.equal(detectFormat(strToU8('# exported\nmtllib a.mtl\no x\n' + OBJ)), 'obj');
  assert.equal(detectFormat(strToU8('anything'), 'Model.OBJ'), 'obj');
  assert.throws(
    () => detectFormat(strToU8('hello world')),
    (e: unknown) => e instanceof StrataError && e.code === 'UNSUPPORTED_FORMAT',
  );
  assert.throws(
    () => detectFormat(new Uint8Array(1000).fill(7)),
    (e: unknown) => e instanceof StrataError && e.code === 'UNSUPPORTED_FORMAT',
  );
});

test('loadModelBytes names objects after the file', () => {
  const [o] = loadModelBytes(read('CalibrationCube.stl'), '/some/dir/CalibrationCube.stl');
  assert.equal(o.name, 'CalibrationCube');
  assert.equal(o.mesh.indices.length / 3, 136);
  const objs = loadModelBytes(strToU8(OBJ), 'C:\\models\\tet.obj');
  assert.equal(objs[0].name, 'tet');
  assert.equal(loadModelBytes(read('3DBenchy.3mf'), '3DBenchy.3mf')[0].mesh.indices.length / 3, 225154);
});

test('toMeshObjects dispatches on the kind of input', () => {
  const stl = read('CalibrationCube.stl');
  assert.equal(toMeshObjects(stl)[0].mesh.indices.length / 3, 136);
  assert.equal(
    toMeshObjects(stl.buffer.slice(stl.byteOffset, stl.byteOffset + stl.byteLength))[0].mesh.indices.length / 3,
    136,
  );
  assert.equal(toMeshObjects(OBJ)[0].mesh.indices.length / 3, 4);
  assert.equal(toMeshObjects(ASCII)[0].name, 't');
  const raw = { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0], indices: [0, 1, 2] };
  assert.equal(toMeshObjects(raw)[0].mesh.indices.length, 3);
  const mesh = { positions: new Float32Array(raw.positions), indices: new Uint32Array(raw.indices) };
  assert.equal(toMeshObjects(mesh)[0].mesh.positions.length, 9);
  assert.equal(toMeshObjects({ name: 'named', mesh })[0].name, 'named');
  const geometry = {
    isBufferGeometry: true,
    attributes: { position: { array: new Float32Array(raw.positions), itemSize: 3 } },
  };
  const three = { isObject3D: true, isMesh: true, name: 'tm', geometry, children: [] };
  assert.equal(toMeshObjects(three)[0].name, 'tm');
  const all = toMeshObjects([stl, OBJ, raw, three, [mesh]]);
  assert.equal(all.length, 5);
  const zip = zipSync({ 'x.txt': strToU8('x') });
  assert.throws(
    () => toMeshObjects(zip),
    (e: unknown) => e instanceof StrataError && e.code === 'BAD_FILE',
  );
});

test('toMeshObjects refuses what it cannot use with UNSUPPORTED_FORMAT', () => {
  for (const bad of [null, undefined, 42, true, 'hello', {}, { foo: 1 }, [1, 2, 3], new Map(), () => 1]) {
    assert.throws(
      () => toMeshObjects(bad),
      (e: unknown) => e instanceof StrataError && e.code === 'UNSUPPORTED_FORMAT' && !e.message.includes('\n'),
      String(bad),
    );
  }
});
