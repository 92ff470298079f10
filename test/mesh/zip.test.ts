/**
 * Hostile archives: a 3MF is refused before it unpacks to more than the model needs, and only the
 * parts the build refers to are unpacked at all.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Deflate, deflateSync, strToU8 } from 'fflate';
import { StrataError } from '#strata/errors.js';
import { parse3mf } from '#strata/mesh/threemf.js';
import { MAX_INFLATE_RATIO, MIN_RATIO_CHECK_BYTES, ZipArchive } from '#strata/mesh/zip.js';

interface RawEntry {
  name: string;
  /** Packed bytes as stored. */
  data: Uint8Array;
  method: 0 | 8;
  /** The unpacked size the archive declares (may lie). */
  size: number;
}

/** A zip archive written field by field, so declared sizes can lie. */
function zip(entries: RawEntry[]): Uint8Array {
  const locals: Uint8Array[] = [];
  const centrals: Uint8Array[] = [];
  let offset = 0;
  for (const e of entries) {
    const name = strToU8(e.name);
    const lh = new Uint8Array(30 + name.length);
    const l = new DataView(lh.buffer);
    l.setUint32(0, 0x04034b50, true);
    l.setUint16(4, 20, true);
    l.setUint16(8, e.method, true);
    l.setUint32(18, e.data.length, true);
    l.setUint32(22, e.size, true);
    l.setUint16(26, name.length, true);
    lh.set(name, 30);
    const ch = new Uint8Array(46 + name.length);
    const c = new DataView(ch.buffer);
    c.setUint32(0, 0x02014b50, true);
    c.setUint16(6, 20, true);
    c.setUint16(10, e.method, true);
    c.setUint32(20, e.data.length, true);
    c.setUint32(24, e.size, true);
    c.setUint16(28, name.length, true);
    c.setUint32(42, offset, true);
    ch.set(name, 46);
    locals.push(lh, e.data);
    centrals.push(ch);
    offset += lh.length + e.data.length;
  }
  const cdSize = centrals.reduce((n, c) => n + c.length, 0);
  const end = new Uint8Array(22);
  const d = new DataView(end.buffer);
  d.setUint32(0, 0x06054b50, true);
  d.setUint16(8, entries.length, true);
  d.setUint16(10, entries.length, true);
  d.setUint32(12, cdSize, true);
  d.setUint32(16, offset, true);
  const parts = [...locals, ...centrals, end];
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  let o = 0;
  for (const p of parts) {
    out.set(p, o);
    o += p.length;
  }
  return out;
}

const deflated = (name: string, text: string): RawEntry => {
  const raw = strToU8(text);
  return { name, data: deflateSync(raw), method: 8, size: raw.length };
};

/** Raw DEFLATE of `mib` MiB of spaces (packs ~1000×), streamed so the test stays small. */
function spaces(mib: number): Uint8Array {
  const parts: Uint8Array[] = [];
  const d = new Deflate({ level: 1 }, (c) => parts.push(c));
  const chunk = new Uint8Array(1 << 20).fill(32);
  for (let i = 0; i < mib; i++) d.push(chunk, i === mib - 1);
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  let o = 0;
  for (const p of parts) {
    out.set(p, o);
    o += p.length;
  }
  return out;
}

const MODEL = `<?xml version="1.0"?><model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"><resources>
<object id="1" name="tet"><mesh><vertices><vertex x="0" y="0" z="0"/><vertex x="10" y="0" z="0"/><vertex x="0" y="10" z="0"/><vertex x="0" y="0" z="10"/></vertices>
<triangles><triangle v1="0" v2="2" v3="1"/><triangle v1="0" v2="1" v3="3"/><triangle v1="0" v2="3" v3="2"/><triangle v1="1" v2="2" v3="3"/></triangles></mesh></object>
</resources><build><item objectid="1"/></build></model>`;

const RELS = `<?xml version="1.0"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
<Relationship Target="/3D/3dmodel.model" Id="r0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>`;

function refused(fn: () => unknown, code: string, re: RegExp): void {
  assert.throws(fn, (e: unknown) => {
    assert.ok(e instanceof StrataError, String(e));
    assert.equal(e.code, code, e.message);
    assert.match(e.message, re);
    assert.ok(!e.message.includes('\n'));
    return true;
  });
}

const BOMB = spaces(8);

test('a part claiming more than the budget is refused before anything is inflated', () => {
  const bytes = zip([
    deflated('_rels/.rels', RELS),
    { name: '3D/3dmodel.model', data: BOMB, method: 8, size: 1 << 30 },
  ]);
  const before = process.memoryUsage().rss;
  refused(
    () => parse3mf(bytes),
    'LIMIT_EXCEEDED',
    /3D\/3dmodel\.model unpacks to 1024 MiB, more than the 512 MiB left of the 512 MiB budget; raise inflateBudget/,
  );
  assert.ok(process.memoryUsage().rss - before < 64 * 1024 * 1024, 'no gigabyte was allocated');
  // raising the budget is not enough for a part that packs ~1000×
  refused(() => parse3mf(bytes, 'm', { maxInflatedBytes: 2 * 1024 ** 3 }), 'LIMIT_EXCEEDED', /refused as a zip bomb/);
});

test('a part that packs implausibly well is refused as a zip bomb, within the budget', () => {
  const size = 100 * 1024 * 1024;
  assert.ok(size > MIN_RATIO_CHECK_BYTES && size > MAX_INFLATE_RATIO * BOMB.length);
  const bytes = zip([{ name: '3D/3dmodel.model', data: BOMB, method: 8, size }]);
  refused(() => parse3mf(bytes), 'LIMIT_EXCEEDED', /claims to unpack .* into 100 MiB .*: refused as a zip bomb/);
});

test('a part that unpacks to more than it declares stops within a few slices', () => {
  const bytes = zip([{ name: '3D/3dmodel.model', data: BOMB, method: 8, size: 64 * 1024 }]);
  refused(
    () => parse3mf(bytes),
    'BAD_FILE',
    /zip archive is damaged \(3D\/3dmodel\.model unpacks to more than the 65536 bytes it declares\)/,
  );
  // and less than it declares is damage too
  const short = deflated('3D/3dmodel.model', MODEL);
  refused(
    () => parse3mf(zip([{ ...short, size: short.size + 10 }])),
    'BAD_FILE',
    /unpacks to \d+ bytes, not the \d+ it declares/,
  );
});

test('only the parts the build refers to are inflated: an unreferenced bomb costs nothing', () => {
  const bytes = zip([
    deflated('_rels/.rels', RELS),
    deflated('3D/3dmodel.model', MODEL),
    { name: '3D/unused.model', data: BOMB, method: 8, size: 1 << 30 },
    { name: 'Metadata/thumbnail.png', data: BOMB, method: 8, size: 1 << 30 },
  ]);
  const objects = parse3mf(bytes);
  assert.equal(objects.length, 1);
  assert.equal(objects[0].mesh.indices.length, 12);
  const archive = new ZipArchive(bytes, { maxBytes: 1 << 20, setting: 'inflateBudget' });
  assert.equal(archive.entries.size, 4);
  assert.equal(archive.unpackedBytes, 0, 'opening reads the directory only');
});

test('the budget counts every part read, and a small budget names the setting to raise', () => {
  const bytes = zip([deflated('_rels/.rels', RELS), deflated('3D/3dmodel.model', MODEL)]);
  assert.equal(parse3mf(bytes).length, 1);
  refused(
    () => parse3mf(bytes, 'm', { maxInflatedBytes: 600 }),
    'LIMIT_EXCEEDED',
    /more than the \d+ bytes left of the 600 bytes budget; raise inflateBudget/,
  );
});

test('stored parts, encrypted parts and unknown methods', () => {
  const raw = strToU8(MODEL);
  assert.equal(parse3mf(zip([{ name: '3D/3dmodel.model', data: raw, method: 0, size: raw.length }])).length, 1);
  refused(
    () => parse3mf(zip([{ name: '3D/3dmodel.model', data: raw, method: 0, size: raw.length + 1 }])),
    'BAD_FILE',
    /stored part .* has two sizes/,
  );
  const odd = zip([{ name: '3D/3dmodel.model', data: raw, method: 12 as 8, size: raw.length }]);
  refused(() => parse3mf(odd), 'BAD_FILE', /compression method 12/);
  refused(() => parse3mf(zip([]).subarray(0, 10)), 'BAD_FILE', /not a 3MF file|damaged/);
});
