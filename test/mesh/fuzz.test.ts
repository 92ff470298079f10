/**
 * Robustness: truncated and corrupted inputs must either parse or throw StrataError — never a
 * TypeError, a RangeError or a hang.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { strToU8, zipSync } from 'fflate';
import { StrataError } from '#strata/errors.js';
import { loadModelBytes } from '#strata/mesh/load.js';
import { prepareMesh } from '#strata/mesh/prepare.js';
import { MODELS_DIR } from '../e2e/models-dir.js';

const MODELS = MODELS_DIR;

function survives(bytes: Uint8Array, name: string): void {
  try {
    for (const o of loadModelBytes(bytes, name)) prepareMesh(o.mesh);
  } catch (e) {
    if (!(e instanceof StrataError)) assert.fail(`${name}: ${String(e)}`);
    assert.ok(!e.message.includes('\n'), e.message);
  }
}

function mutations(src: Uint8Array, name: string, rounds: number, seed: number): void {
  const rnd = (n: number): number => {
    seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
    return seed % n;
  };
  for (let cut = 0; cut < src.length; cut += Math.max(1, Math.floor(src.length / 97)))
    survives(src.subarray(0, cut), name);
  for (let r = 0; r < rounds; r++) {
    const b = src.slice();
    const flips = 1 + rnd(8);
    for (let k = 0; k < flips; k++) b[rnd(b.length)] = rnd(256);
    survives(b, name);
  }
}

const model3mf = `<?xml version="1.0"?>
<model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"><resources>
<object id="1" name="t"><mesh><vertices><vertex x="0" y="0" z="0"/><vertex x="1" y="0" z="0"/><vertex x="0" y="1" z="0"/><vertex x="0" y="0" z="1"/></vertices>
<triangles><triangle v1="0" v2="2" v3="1"/><triangle v1="0" v2="1" v3="3"/><triangle v1="0" v2="3" v3="2"/><triangle v1="1" v2="2" v3="3"/></triangles></mesh></object>
<object id="2"><components><component objectid="1" transform="1 0 0 0 1 0 0 0 1 5 0 0"/></components></object>
</resources><build><item objectid="2"/><item objectid="1"/></build></model>`;

test('binary STL survives truncation and corruption', () => {
  mutations(new Uint8Array(readFileSync(join(MODELS, 'CalibrationCube.stl'))), 'c.stl', 300, 1);
});

test('ASCII STL survives truncation and corruption', () => {
  mutations(new Uint8Array(readFileSync(join(MODELS, 'HollowCalibrationCube.stl'))).subarray(0, 3000), 'h.stl', 300, 2);
});

test('OBJ survives truncation and corruption', () => {
  const obj =
    'o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvn 0 0 1\nf 1/1/1 3/1/1 2/1/1\nf 1//1 2//1 4//1\ng b\nf -4 -1 -2\nf 2 3 4\n';
  mutations(strToU8(obj), 'm.obj', 500, 3);
});

test('3MF (deflated and stored) survives truncation and corruption', () => {
  mutations(zipSync({ '3D/3dmodel.model': strToU8(model3mf) }, { level: 6 }), 'd.3mf', 400, 4);
  mutations(zipSync({ '3D/3dmodel.model': strToU8(model3mf) }, { level: 0 }), 's.3mf', 400, 5);
});
