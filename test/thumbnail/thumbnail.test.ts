import { test } from 'node:test';
import assert from 'node:assert/strict';
import { decode as decodePng } from 'fast-png';
import jpeg from 'jpeg-js';
import type { Mesh } from '#strata/mesh/types.js';
import { StrataError } from '#strata/errors.js';
import { toBase64 } from '#strata/thumbnail/base64.js';
import { decodeQoi, encodeQoi } from '#strata/thumbnail/qoi.js';
import { encodeJpeg } from '#strata/thumbnail/jpeg.js';
import {
  formatThumbnailSpecs,
  parseThumbnailSpecs,
  renderMesh,
  renderThumbnail,
  renderThumbnails,
} from '#strata/thumbnail/index.js';

/** A UV sphere of radius r at (cx, cy, r), outward-facing triangles. */
function sphere(cx: number, cy: number, r: number, rings = 24, segments = 48): Mesh {
  const pos: number[] = [];
  const idx: number[] = [];
  for (let i = 0; i <= rings; i++) {
    const t = (Math.PI * i) / rings;
    for (let j = 0; j < segments; j++) {
      const p = (2 * Math.PI * j) / segments;
      pos.push(cx + r * Math.sin(t) * Math.cos(p), cy + r * Math.sin(t) * Math.sin(p), r + r * Math.cos(t));
    }
  }
  for (let i = 0; i < rings; i++) {
    for (let j = 0; j < segments; j++) {
      const a = i * segments + j,
        b = i * segments + ((j + 1) % segments),
        c = a + segments,
        d = b + segments;
      idx.push(a, c, b, b, c, d);
    }
  }
  return { positions: new Float32Array(pos), indices: new Uint32Array(idx) };
}

/** An axis-aligned box from (x0,y0,0) to (x1,y1,z1). */
function box(x0: number, y0: number, x1: number, y1: number, z1: number): Mesh {
  const v = [
    [x0, y0, 0],
    [x1, y0, 0],
    [x1, y1, 0],
    [x0, y1, 0],
    [x0, y0, z1],
    [x1, y0, z1],
    [x1, y1, z1],
    [x0, y1, z1],
  ].flat();
  const f = [
    0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7,
  ];
  return { positions: new Float32Array(v), indices: new Uint32Array(f) };
}

/** Opaque share and number of distinct grey levels among opaque pixels. */
function coverage(
  data: Uint8Array | Uint8ClampedArray,
  channels = 4,
  background?: number[],
): { share: number; shades: number } {
  let opaque = 0;
  const shades = new Set<number>();
  for (let i = 0; i < data.length; i += channels) {
    const isModel = background
      ? Math.abs(data[i]! - background[0]!) +
          Math.abs(data[i + 1]! - background[1]!) +
          Math.abs(data[i + 2]! - background[2]!) >
        30
      : data[i + 3]! === 255;
    if (!isModel) continue;
    opaque++;
    shades.add(Math.round((data[i]! + data[i + 1]! + data[i + 2]!) / 24));
  }
  return { share: opaque / (data.length / channels), shades: shades.size };
}

test('PNG thumbnails decode at the declared size, show the model and its shading', () => {
  for (const [w, h] of [
    [16, 16],
    [48, 48],
    [300, 300],
    [313, 173],
  ] as const) {
    const img = renderThumbnail(box(90, 90, 130, 110, 30), { width: w, height: h, format: 'PNG' });
    const png = decodePng(img.data);
    assert.equal(png.width, w);
    assert.equal(png.height, h);
    assert.equal(png.channels, 4);
    const c = coverage(png.data as Uint8Array);
    assert.ok(c.share > 0.15 && c.share < 0.95, `${w}x${h}: model covers ${c.share}`);
    // a box seen from above and the side shows (at least) three differently lit faces
    assert.ok(c.shades >= 3, `${w}x${h}: ${c.shades} shades`);
  }
});

test('a sphere is round and shaded from light to dark; the background is transparent', () => {
  const { data, width, height } = renderMesh(sphere(100, 100, 20), 100, 100);
  const c = coverage(data);
  assert.ok(c.shades >= 6, `smooth shading: ${c.shades} shades`);
  assert.equal(data[3], 0, 'corner pixel transparent');
  // roughly a disc: the opaque area is close to π/4 of its bounding square
  let minX = width,
    maxX = 0,
    minY = height,
    maxY = 0,
    n = 0;
  for (let y = 0; y < height; y++)
    for (let x = 0; x < width; x++)
      if (data[(y * width + x) * 4 + 3]! > 127) {
        n++;
        minX = Math.min(minX, x);
        maxX = Math.max(maxX, x);
        minY = Math.min(minY, y);
        maxY = Math.max(maxY, y);
      }
  const fill = n / ((maxX - minX + 1) * (maxY - minY + 1));
  assert.ok(Math.abs(fill - Math.PI / 4) < 0.05, `disc fill ${fill}`);
});

test('QOI round-trips exactly, and QOI thumbnails decode at their size', () => {
  const image = renderMesh(sphere(0, 0, 10), 64, 40);
  const back = decodeQoi(encodeQoi(image));
  assert.equal(back.width, 64);
  assert.equal(back.height, 40);
  assert.deepEqual(back.data, image.data);
  // every QOI op: runs, index hits, small and luma differences, full RGB and RGBA
  const noisy = { width: 50, height: 3, data: new Uint8Array(600) };
  for (let i = 0; i < 600; i++) noisy.data[i] = i < 200 ? 7 : (i * 7919) % 251;
  assert.deepEqual(decodeQoi(encodeQoi(noisy)).data, noisy.data);
  const t = renderThumbnail(box(0, 0, 10, 10, 10), { width: 16, height: 16, format: 'QOI' });
  assert.equal(decodeQoi(t.data).width, 16);
  assert.ok(coverage(decodeQoi(t.data).data).share > 0.1);
});

test('JPG thumbnails are baseline JPEGs that decode at their size, close to the rendered image', () => {
  for (const [w, h] of [
    [16, 16],
    [100, 60],
    [300, 300],
  ] as const) {
    const img = renderThumbnail(sphere(50, 50, 15), { width: w, height: h, format: 'JPG' });
    assert.deepEqual([...img.data.subarray(0, 2)], [0xff, 0xd8]);
    const decoded = jpeg.decode(img.data, { useTArray: true });
    assert.equal(decoded.width, w);
    assert.equal(decoded.height, h);
    const c = coverage(decoded.data, 4, [38, 38, 38]);
    assert.ok(c.share > 0.2 && c.shades >= 3, `${w}x${h}: ${JSON.stringify(c)}`);
  }
  // lossy but close: a smooth render encodes within a few levels on average
  const src = renderMesh(sphere(0, 0, 10), 64, 64, { background: [38, 38, 38] });
  const out = jpeg.decode(encodeJpeg(src, 90), { useTArray: true });
  let err = 0;
  for (let i = 0; i < src.data.length; i += 4)
    for (let k = 0; k < 3; k++) err += Math.abs(src.data[i + k]! - out.data[i + k]!);
  assert.ok(err / (64 * 64 * 3) < 4, `mean error ${err / (64 * 64 * 3)}`);
});

test('the thumbnails setting: sizes and formats, empty means none, bad items are named', () => {
  assert.deepEqual(parseThumbnailSpecs(''), []);
  assert.deepEqual(parseThumbnailSpecs(' 16x16/QOI, 313x173/qoi ,380x285/PNG,32x32, 100x50/jpg'), [
    { width: 16, height: 16, format: 'QOI' },
    { width: 313, height: 173, format: 'QOI' },
    { width: 380, height: 285, format: 'PNG' },
    { width: 32, height: 32, format: 'PNG' },
    { width: 100, height: 50, format: 'JPG' },
  ]);
  assert.equal(formatThumbnailSpecs(parseThumbnailSpecs('16x16/QOI,32x32')), '16x16/QOI,32x32/PNG');
  assert.throws(
    () => parseThumbnailSpecs('16x16/BMP'),
    (e: unknown) => e instanceof StrataError && /16x16\/BMP/.test(e.message),
  );
  assert.throws(
    () => parseThumbnailSpecs('2000x20'),
    (e: unknown) => e instanceof StrataError && /1024/.test(e.message),
  );
  assert.throws(() => parseThumbnailSpecs('0x20'), StrataError);
  assert.equal(renderThumbnails(box(0, 0, 1, 1, 1), '').length, 0);
  assert.deepEqual(
    renderThumbnails(box(0, 0, 1, 1, 1), '8x8,9x7/QOI').map((t) => [t.width, t.height, t.format]),
    [
      [8, 8, 'PNG'],
      [9, 7, 'QOI'],
    ],
  );
});

test('rendering is deterministic, and an empty mesh gives a blank image', () => {
  const a = renderThumbnail(sphere(10, 10, 5), { width: 40, height: 30, format: 'PNG' });
  const b = renderThumbnail(sphere(10, 10, 5), { width: 40, height: 30, format: 'PNG' });
  assert.deepEqual(a.data, b.data);
  const empty = renderMesh({ positions: new Float32Array(0), indices: new Uint32Array(0) }, 8, 8);
  assert.ok(empty.data.every((v) => v === 0));
});

test('base64 matches the platform encoder for every length', () => {
  for (let n = 0; n < 20; n++) {
    const bytes = new Uint8Array(n * 7);
    for (let i = 0; i < bytes.length; i++) bytes[i] = (i * 131 + n) & 255;
    assert.equal(toBase64(bytes), Buffer.from(bytes).toString('base64'));
  }
});
