import { test } from 'node:test';
import assert from 'node:assert/strict';
import { encode } from 'fast-png';
import { strToU8, Zlib, zlibSync } from 'fflate';
import { Slicer } from '#strata/api/slicer.js';
import { StrataError } from '#strata/errors.js';
import { decodeCellsPng } from '#strata/shader/image.js';
import { guardPng, pngDataBytes, readPngHeader } from '#strata/shader/png-guard.js';

/** A PNG chunk (CRC left zero: the decoder does not check it). */
function chunk(type: string, data: Uint8Array): Uint8Array {
  const out = new Uint8Array(12 + data.length);
  new DataView(out.buffer).setUint32(0, data.length);
  out.set(strToU8(type), 4);
  out.set(data, 8);
  return out;
}

function concat(parts: Uint8Array[]): Uint8Array {
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  let o = 0;
  for (const p of parts) {
    out.set(p, o);
    o += p.length;
  }
  return out;
}

/** zlib data of `mib` MiB of zeros (packs ~1000×). */
function zeros(mib: number): Uint8Array {
  const parts: Uint8Array[] = [];
  const z = new Zlib({ level: 1 }, (c) => parts.push(c));
  const block = new Uint8Array(1 << 20);
  for (let i = 0; i < mib; i++) z.push(block, i === mib - 1);
  return concat(parts);
}

const SIG = Uint8Array.from([137, 80, 78, 71, 13, 10, 26, 10]);

function ihdr(w: number, h: number, colorType = 2, interlace = 0): Uint8Array {
  const d = new Uint8Array(13);
  const v = new DataView(d.buffer);
  v.setUint32(0, w);
  v.setUint32(4, h);
  d[8] = 8;
  d[9] = colorType;
  d[12] = interlace;
  return chunk('IHDR', d);
}

const rgb = (w: number, h: number) =>
  encode({ width: w, height: h, data: new Uint8Array(w * h * 3).fill(200), channels: 3, depth: 8 });

function refused(fn: () => unknown, code: string, re: RegExp): void {
  assert.throws(
    fn,
    (e: unknown) => e instanceof StrataError && e.code === code && re.test(e.message) && !e.message.includes('\n'),
  );
}

test('the unpacked size of the image data follows from the header (Adam7 passes when interlaced)', () => {
  const head = (w: number, h: number, interlaced = false, colorType = 2) => ({
    width: w,
    height: h,
    depth: 8,
    colorType,
    interlaced,
  });
  assert.equal(pngDataBytes(head(3, 2)), 2 * (1 + 9));
  assert.equal(pngDataBytes(head(1, 1, true)), 1 + 3);
  // 8 × 8 interlaced: passes of 1×1, 1×1, 2×1, 2×2, 4×2, 4×4 and 8×4 pixels
  assert.equal(pngDataBytes(head(8, 8, true)), 4 + 4 + 7 + 14 + 26 + 52 + 100);
  assert.equal(pngDataBytes({ ...head(5, 1), depth: 1, colorType: 0 }), 1 + 1);
  assert.deepEqual(readPngHeader(rgb(3, 2), 'x.png'), {
    width: 3,
    height: 2,
    depth: 8,
    colorType: 2,
    interlaced: false,
  });
});

test('image data that unpacks to more than its pixels need is refused after a few slices', () => {
  const bomb = concat([SIG, ihdr(1, 1), chunk('IDAT', zeros(16)), chunk('IEND', new Uint8Array(0))]);
  const before = process.memoryUsage().rss;
  refused(
    () => decodeCellsPng(bomb, 'bomb.png'),
    'BAD_IMAGE',
    /^bomb\.png: the image data unpacks to more than the 4 bytes its 1 × 1 pixels need/,
  );
  assert.ok(process.memoryUsage().rss - before < 12 * 1024 * 1024, 'not inflated to the end');
});

test('compressed side chunks are dropped unread: an ICC-profile bomb decodes as the plain image', () => {
  const plain = rgb(2, 2);
  const iccp = chunk('iCCP', concat([strToU8('icc'), Uint8Array.of(0, 0), zeros(16)]));
  const ztxt = chunk('zTXt', concat([strToU8('k'), Uint8Array.of(0, 0), zlibSync(strToU8('hello'))]));
  // after the header chunk (8 + 25 bytes)
  const withSide = concat([plain.subarray(0, 33), iccp, ztxt, plain.subarray(33)]);
  const cleaned = guardPng(withSide, 'c.png', readPngHeader(withSide, 'c.png'));
  assert.deepEqual([...cleaned], [...plain]);
  assert.deepEqual([...decodeCellsPng(withSide).pixels], [...decodeCellsPng(plain).pixels]);
});

test('an image that would take more than the budget to decode is refused, naming the setting', () => {
  const big = rgb(1024, 512);
  refused(
    () => decodeCellsPng(big, 'big.png', 1024 * 1024),
    'LIMIT_EXCEEDED',
    /^big\.png: decoding 1024 × 512 pixels takes \d+ MiB, more than the 1 MiB budget; raise inflateBudget/,
  );
  assert.throws(
    () => new Slicer({ inflateBudget: 1, customInfill: { name: 'big', image: big } }),
    (e: unknown) => e instanceof StrataError && /raise inflateBudget/.test(e.message),
  );
  assert.doesNotThrow(() => new Slicer({ customInfill: { name: 'big', image: big } }));
  // broken files stay BAD_IMAGE
  refused(
    () => decodeCellsPng(concat([SIG, ihdr(2, 2), chunk('IDAT', Uint8Array.of(1, 2, 3))]).subarray(0, 45)),
    'BAD_IMAGE',
    /broken PNG|cannot decode/,
  );
});
