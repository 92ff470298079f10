import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gunzipSync } from 'node:zlib';
import { strToU8, zipSync } from 'fflate';
import { StrataError } from '#strata/errors.js';
import { prepareMesh } from '#strata/mesh/prepare.js';
import { parseStl } from '#strata/mesh/stl.js';
import { parse3mf } from '#strata/mesh/threemf.js';
import type { Mesh } from '#strata/mesh/types.js';
import { MODELS_DIR } from '../e2e/models-dir.js';

const MODELS = MODELS_DIR;

function throwsStrata(fn: () => unknown, code: string, re?: RegExp): void {
  assert.throws(fn, (e: unknown) => {
    assert.ok(e instanceof StrataError, `expected StrataError, got ${String(e)}`);
    assert.equal(e.code, code, e.message);
    if (re) assert.match(e.message, re);
    assert.ok(!e.message.includes('\n'));
    return true;
  });
}

function bbox(mesh: Mesh): { min: number[]; max: number[] } {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < mesh.positions.length; i++) {
    min[i % 3] = Math.min(min[i % 3], mesh.positions[i]);
    max[i % 3] = Math.max(max[i % 3], mesh.positions[i]);
  }
  return { min, max };
}

function close(actual: number[], expected: number[], tol = 1e-4): void {
  actual.forEach((v, i) =>
    assert.ok(Math.abs(v - expected[i]) <= tol, `[${i}] ${v} vs ${expected[i]} (${actual} vs ${expected})`),
  );
}

const RELS = `<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
 <Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>`;

function make3mf(model: string, extra: Record<string, string> = {}, rels: string | null = RELS): Uint8Array {
  const files: Record<string, Uint8Array> = { '3D/3dmodel.model': strToU8(model) };
  if (rels !== null) files['_rels/.rels'] = strToU8(rels);
  for (const [k, v] of Object.entries(extra)) files[k] = strToU8(v);
  return zipSync(files);
}

/** A 10 mm cube (unit cube scaled by `s`) as a 3MF <object>. */
function cubeObject(id: number, name: string, s = 1): string {
  const v: string[] = [];
  for (let i = 0; i < 8; i++)
    v.push(`<vertex x="${(i & 1) * s}" y="${((i >> 1) & 1) * s}" z="${((i >> 2) & 1) * s}"/>`);
  const faces = [
    [0, 2, 3],
    [0, 3, 1],
    [4, 5, 7],
    [4, 7, 6],
    [0, 1, 5],
    [0, 5, 4],
    [2, 6, 7],
    [2, 7, 3],
    [0, 4, 6],
    [0, 6, 2],
    [1, 3, 7],
    [1, 7, 5],
  ];
  const t = faces.map(([a, b, c]) => `<triangle v1="${a}" v2="${b}" v3="${c}"/>`);
  return `<object id="${id}" name="${name}" type="model"><mesh><vertices>${v.join('')}</vertices><triangles>${t.join('')}</triangles></mesh></object>`;
}

function model(resources: string, build: string, unit = 'millimeter', extraNs = ''): string {
  return `<?xml version="1.0" encoding="UTF-8"?>
<model unit="${unit}" xml:lang="en-US" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"${extraNs}>
 <metadata name="Title">test &amp; co</metadata>
 <!-- a comment with <tags> inside -->
 <resources>${resources}</resources>
 <build>${build}</build>
</model>`;
}

test('3DBenchy.3mf equals 3DBenchy.stl: triangle count, bounding box, prepared report', () => {
  const [fromMf, ...rest] = parse3mf(new Uint8Array(readFileSync(join(MODELS, '3DBenchy.3mf'))), 'benchy');
  assert.equal(rest.length, 0);
  assert.equal(fromMf.name, '3DBenchy');
  const [fromStl] = parseStl(new Uint8Array(gunzipSync(readFileSync(join(MODELS, '3DBenchy.stl.gz')))), 'benchy');
  assert.equal(fromMf.mesh.indices.length / 3, 225154);
  assert.equal(fromMf.mesh.indices.length, fromStl.mesh.indices.length);
  const a = bbox(fromMf.mesh);
  const b = bbox(fromStl.mesh);
  assert.deepEqual(a, b);
  close([a.max[0] - a.min[0], a.max[1] - a.min[1], a.max[2] - a.min[2]], [60.0, 31.0, 48.0], 0.01);
  const ra = prepareMesh(fromMf.mesh).report;
  const rb = prepareMesh(fromStl.mesh).report;
  assert.equal(ra.vertices, rb.vertices);
  assert.equal(ra.openEdges, 0);
  assert.equal(ra.degenerateRemoved, 8);
  assert.ok(Math.abs(ra.volume - rb.volume) < 1e-6);
});

test('3MF units convert to mm', () => {
  const cases: [string, number][] = [
    ['micron', 0.001],
    ['millimeter', 1],
    ['centimeter', 10],
    ['inch', 25.4],
    ['foot', 304.8],
    ['meter', 1000],
  ];
  for (const [unit, mm] of cases) {
    const [o] = parse3mf(make3mf(model(cubeObject(1, 'c', 2), '<item objectid="1"/>', unit)));
    const { min, max } = bbox(o.mesh);
    close(min, [0, 0, 0]);
    close(max, [2 * mm, 2 * mm, 2 * mm], 1e-4 * mm);
  }
  throwsStrata(
    () => parse3mf(make3mf(model(cubeObject(1, 'c'), '<item objectid="1"/>', 'furlong'))),
    'BAD_FILE',
    /unknown unit "furlong"/,
  );
});

test('3MF: every build item is one object with its transform (row-major m00..m32, translation last)', () => {
  const build =
    '<item objectid="1" transform="1 0 0 0 1 0 0 0 1 100 50 0"/>' +
    // 90° about Z: x' = -y, y' = x (row vectors: p·M with rows (0 1 0), (-1 0 0), (0 0 1)), then +(10, 0, 5).
    '<item objectid="1" transform="0 1 0 -1 0 0 0 0 1 10 0 5"/>' +
    '<item objectid="2"/>';
  const objs = parse3mf(make3mf(model(cubeObject(1, 'cube', 10) + cubeObject(2, '', 1), build, 'millimeter')), 'file');
  assert.equal(objs.length, 3);
  assert.deepEqual(
    objs.map((o) => o.name),
    ['cube', 'cube (2)', 'file 3'],
  );
  close(bbox(objs[0].mesh).min, [100, 50, 0]);
  close(bbox(objs[0].mesh).max, [110, 60, 10]);
  close(bbox(objs[1].mesh).min, [0, 0, 5]);
  close(bbox(objs[1].mesh).max, [10, 10, 15]);
  // The transform applied to the corner (10, 0, 0) gives (10, 10, 5).
  const p = objs[1].mesh.positions;
  let found = false;
  for (let i = 0; i < p.length; i += 3) if (p[i] === 10 && p[i + 1] === 10 && p[i + 2] === 5) found = true;
  assert.ok(found);
  for (const o of objs) assert.ok(prepareMesh(o.mesh).report.volume > 0, 'rotation keeps outward normals');
});

test('3MF: translations scale with the unit', () => {
  const [o] = parse3mf(
    make3mf(model(cubeObject(1, 'c', 1), '<item objectid="1" transform="1 0 0 0 1 0 0 0 1 2 0 0"/>', 'centimeter')),
  );
  close(bbox(o.mesh).min, [20, 0, 0]);
  close(bbox(o.mesh).max, [30, 10, 10]);
});

test('3MF: nested components compose their transforms; a mirror keeps the volume positive', () => {
  const resources =
    cubeObject(1, 'leaf', 1) +
    '<object id="2" name="pair"><components>' +
    '<component objectid="1"/>' +
    '<component objectid="1" transform="1 0 0 0 1 0 0 0 1 5 0 0"/>' +
    '</components></object>' +
    '<object id="3" name="assembly"><components>' +
    '<component objectid="2" transform="2 0 0 0 2 0 0 0 2 0 0 1"/>' +
    '<component objectid="1" transform="-1 0 0 0 1 0 0 0 1 0 0 0"/>' +
    '</components></object>';
  const [o] = parse3mf(make3mf(model(resources, '<item objectid="3" transform="1 0 0 0 1 0 0 0 1 0 100 0"/>')));
  assert.equal(o.name, 'assembly');
  assert.equal(o.mesh.indices.length / 3, 36);
  // pair scaled ×2 and lifted 1: x 0..2 and 10..12; mirrored leaf: x -1..0. All shifted +100 in y.
  close(bbox(o.mesh).min, [-1, 100, 0]);
  close(bbox(o.mesh).max, [12, 102, 3]);
  const r = prepareMesh(o.mesh).report;
  close([r.volume], [8 + 8 + 1], 1e-6);
  assert.equal(r.openEdges, 0);
});

test('3MF: production-extension parts (p:path) are followed', () => {
  const prod = ' xmlns:p="http://schemas.microsoft.com/3dmanufacturing/production/2015/06"';
  const root = model(
    '<object id="5" name="wrapper"><components><component p:path="/3D/Objects/part.model" objectid="1" transform="1 0 0 0 1 0 0 0 1 0 0 7"/></components></object>',
    '<item objectid="5"/>',
    'millimeter',
    prod,
  );
  const part = model(cubeObject(1, 'inner', 3), '');
  const [o] = parse3mf(make3mf(root, { '3D/Objects/part.model': part }));
  close(bbox(o.mesh).min, [0, 0, 7]);
  close(bbox(o.mesh).max, [3, 3, 10]);
});

test('3MF: prefixed core namespace, CRLF, BOM, and extension elements are handled', () => {
  const xml =
    '\ufeff<?xml version="1.0"?>\r\n<c:model xmlns:c="http://schemas.microsoft.com/3dmanufacturing/core/2015/02" ' +
    'xmlns:s="http://schemas.microsoft.com/3dmanufacturing/slice/2015/07" unit="millimeter">\r\n<c:resources>\r\n' +
    '<s:slicestack id="9"><s:slice ztop="1"><s:vertices><s:vertex x="99" y="99"/></s:vertices></s:slice></s:slicestack>\r\n' +
    cubeObject(1, 'x', 1).replace(/<(\/?)(object|mesh|vertices|vertex|triangles|triangle)/g, '<$1c:$2') +
    '</c:resources><c:build><c:item objectid="1"/></c:build></c:model>';
  const [o] = parse3mf(make3mf(xml));
  assert.equal(o.mesh.indices.length / 3, 12);
  close(bbox(o.mesh).max, [1, 1, 1]);
});

test('3MF without _rels/.rels falls back to 3D/3dmodel.model', () => {
  const [o] = parse3mf(make3mf(model(cubeObject(1, 'c'), '<item objectid="1"/>'), {}, null));
  assert.equal(o.mesh.indices.length / 3, 12);
});

test('3MF errors: not a zip, damaged zip, bad XML, missing objects, cycles, DOCTYPE, deep nesting', () => {
  throwsStrata(() => parse3mf(strToU8('solid x')), 'BAD_FILE', /zip/);
  const good = make3mf(model(cubeObject(1, 'c'), '<item objectid="1"/>'));
  throwsStrata(() => parse3mf(good.subarray(0, good.length - 30)), 'BAD_FILE');
  const damaged = good.slice();
  for (let i = 40; i < 200; i++) damaged[i] ^= 0x5a;
  throwsStrata(() => parse3mf(damaged), 'BAD_FILE');
  throwsStrata(() => parse3mf(zipSync({ 'readme.txt': strToU8('hi') })), 'BAD_FILE', /no 3D model part/);

  const xml = model(cubeObject(1, 'c'), '<item objectid="1"/>');
  throwsStrata(() => parse3mf(make3mf(xml.slice(0, xml.length / 2))), 'BAD_FILE', /truncated|ends inside/);
  throwsStrata(() => parse3mf(make3mf(xml.replace('</mesh>', '</mesj>'))), 'BAD_FILE', /does not close/);
  throwsStrata(() => parse3mf(make3mf(model(cubeObject(1, 'c'), '<item objectid="7"/>'))), 'BAD_FILE', /object 7/);
  throwsStrata(() => parse3mf(make3mf(xml.replace('v3="3"', 'v3="8"'))), 'BAD_FILE', /vertex 8/);
  throwsStrata(() => parse3mf(make3mf(xml.replace('x="1"', 'x="1,5"'))), 'BAD_FILE', /finite numbers/);
  throwsStrata(() => parse3mf(make3mf(xml.replace('v2="2"', 'v2="-2"'))), 'BAD_FILE', /v1, v2 and v3/);
  throwsStrata(
    () => parse3mf(make3mf(model(cubeObject(1, 'c'), '<item objectid="1" transform="1 0 0"/>'))),
    'BAD_FILE',
    /12 numbers/,
  );
  throwsStrata(() => parse3mf(make3mf(model(cubeObject(1, 'c'), ''))), 'EMPTY_MODEL');
  throwsStrata(() => parse3mf(make3mf('<notamodel/>')), 'BAD_FILE', /root element/);
  throwsStrata(() => parse3mf(make3mf('<!DOCTYPE model [<!ENTITY a "aaaa">]>' + xml)), 'BAD_FILE', /DOCTYPE/);
  throwsStrata(
    () => parse3mf(make3mf(xml.replace('<metadata', `${'<a>'.repeat(100)}${'</a>'.repeat(100)}<metadata`))),
    'LIMIT_EXCEEDED',
    /nested/,
  );

  const cycle =
    '<object id="1"><components><component objectid="2"/></components></object>' +
    '<object id="2"><components><component objectid="1"/></components></object>';
  throwsStrata(() => parse3mf(make3mf(model(cycle, '<item objectid="1"/>'))), 'BAD_FILE', /contains itself/);
});

test('3MF: exponential component instancing is refused before allocating', () => {
  let res = cubeObject(1, 'c');
  for (let id = 2; id <= 30; id++) {
    res += `<object id="${id}"><components><component objectid="${id - 1}"/><component objectid="${id - 1}"/></components></object>`;
  }
  throwsStrata(() => parse3mf(make3mf(model(res, '<item objectid="30"/>'))), 'LIMIT_EXCEEDED', /triangles/);
});

test('3MF: an entry that claims to inflate beyond the limit is refused before inflating', () => {
  const zip = make3mf(model(cubeObject(1, 'c'), '<item objectid="1"/>'));
  // Patch the uncompressed size of every central-directory entry to 2 GiB.
  const dv = new DataView(zip.buffer, zip.byteOffset, zip.byteLength);
  for (let i = 0; i + 46 <= zip.length; i++) {
    if (dv.getUint32(i, true) === 0x02014b50) dv.setUint32(i + 24, 0x80000000, true);
  }
  throwsStrata(() => parse3mf(zip), 'LIMIT_EXCEEDED', /inflate/);
});
