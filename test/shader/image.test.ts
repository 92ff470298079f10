import { test } from 'node:test';
import assert from 'node:assert/strict';
import { encode } from 'fast-png';
import type { ExPolygon, Polyline } from '#strata/geometry/types.js';
import { StrataError } from '#strata/errors.js';
import { decodeCellsPng, imageLabelFn, loadCellImage, mergeAntialiased } from '#strata/shader/image.js';
import { infillerFromImage } from '#strata/shader/infiller.js';

const SQUARE: ExPolygon[] = [
  {
    outer: [
      { x: 0, y: 0 },
      { x: 10000, y: 0 },
      { x: 10000, y: 10000 },
      { x: 0, y: 10000 },
    ],
    holes: [],
  },
];
const RED = [220, 30, 30];
const BLUE = [30, 30, 220];

/** A w × h RGB PNG from a colour function (row 0 at the top). */
function png(w: number, h: number, color: (x: number, y: number) => number[], channels = 3): Uint8Array {
  const data = new Uint8Array(w * h * channels);
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      const c = color(x, y);
      data.set(channels === 4 ? [...c.slice(0, 3), c[3] ?? 255] : c.slice(0, 3), (y * w + x) * channels);
    }
  }
  return encode({ width: w, height: h, data, channels, depth: 8 });
}

function sideShare(paths: Polyline[], label: (x: number, y: number) => number, off: number): number {
  let good = 0;
  let total = 0;
  for (const p of paths) {
    for (let i = 1; i < p.length; i++) {
      const ax = p[i - 1].x / 1000;
      const ay = p[i - 1].y / 1000;
      const bx = p[i].x / 1000;
      const by = p[i].y / 1000;
      const len = Math.hypot(bx - ax, by - ay);
      const n = Math.max(1, Math.ceil(len / 0.02));
      for (let k = 0; k < n; k++) {
        const t = (k + 0.5) / n;
        const x = ax + (bx - ax) * t;
        const y = ay + (by - ay) * t;
        const nx = -(by - ay) / len;
        const ny = (bx - ax) / len;
        total += len / n;
        if (label(x + nx * off, y + ny * off) !== label(x - nx * off, y - ny * off)) good += len / n;
      }
    }
  }
  return good / total;
}

test('image infill: a small two-colour PNG tiles and gives boundary paths', () => {
  // 8 × 8 pixels: the left half red, the right half blue, so every tile has two vertical boundaries.
  const bytes = png(8, 8, (x) => (x < 4 ? RED : BLUE));
  const inf = infillerFromImage(bytes, 'halves');
  assert.equal(inf.kind, 'image');
  const inner: ExPolygon[] = [
    {
      outer: [
        { x: 300, y: 0 },
        { x: 9700, y: 0 },
        { x: 9700, y: 10000 },
        { x: 300, y: 10000 },
      ],
      holes: [],
    },
  ];
  const paths = inf.paths({ region: inner, z: 0.2 }, { pixelSize: 0.25 });
  // Tile width 2 mm: boundaries at x = 1, 2, 3, … 9 mm → 9 vertical lines across the region.
  assert.equal(paths.length, 9);
  for (const p of paths) {
    const xs = new Set(p.map((q) => q.x));
    assert.equal(xs.size, 1, 'boundary lines are straight and vertical');
    const x = [...xs][0];
    assert.equal(x % 1000, 0, `line at ${x} µm should sit on a pixel edge`);
    assert.ok(Math.abs(p[0].y - p[p.length - 1].y) >= 9900);
  }
  assert.ok(sideShare(paths, imageLabelFn(inf.image as NonNullable<typeof inf.image>, 0.25), 0.1) >= 0.99);
});

test('image infill: shapes give closed loops; row 0 is the top of the tile', () => {
  // 20 × 20 pixels, a 6 × 6 blue square in the top-left corner of a red tile.
  const bytes = png(20, 20, (x, y) => (x >= 2 && x < 8 && y >= 2 && y < 8 ? BLUE : RED));
  const inf = infillerFromImage(bytes, 'square');
  const label = imageLabelFn(inf.image as NonNullable<typeof inf.image>, 0.5);
  assert.notEqual(label(2.5, 7.5), label(7.5, 2.5), 'blue square near the top of the 10 mm tile');
  const paths = inf.paths({ region: SQUARE, z: 0.2 }, { pixelSize: 0.5 });
  assert.equal(paths.length, 1);
  const loop = paths[0];
  assert.deepEqual(loop[0], loop[loop.length - 1], 'closed loop');
  const xs = loop.map((q) => q.x);
  const ys = loop.map((q) => q.y);
  assert.deepEqual([Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)], [1000, 4000, 6000, 9000]);
});

test('anti-aliased in-between colours are merged into their neighbours with a warning', () => {
  // Red left, blue right, a one-pixel column of purple blends in between, plus a small grey blob.
  const bytes = png(16, 16, (x, y) => {
    if (x === 8) return y % 2 === 0 ? [125, 30, 125] : [140, 30, 110];
    if (x >= 12 && x < 14 && y >= 4 && y < 6) return [128, 128, 128];
    return x < 8 ? RED : BLUE;
  });
  const img = loadCellImage(bytes);
  assert.ok(img.mergedPixels === 16, `merged ${img.mergedPixels}`);
  assert.ok(
    img.warnings.some((w) => /merged 16 anti-aliased pixel\(s\) in 2 in-between colour\(s\)/.test(w)),
    img.warnings.join('; '),
  );
  const colours = new Set(img.pixels);
  assert.equal(colours.size, 3, 'red, blue and the (non-blend) grey blob remain');
  const inf = infillerFromImage(bytes, 'aa');
  const paths = inf.paths({ region: SQUARE, z: 0.2 }, { pixelSize: 0.25 });
  // Per 4 mm tile: red|blue edge, blue|red edge at the tile border, the grey blob's loop.
  const loops = paths.filter((p) => p.length > 3 && p[0].x === p[p.length - 1].x && p[0].y === p[p.length - 1].y);
  assert.ok(loops.length >= 4);
  assert.ok(paths.every((p) => p.length >= 2));
  const without = loadCellImage(bytes, { mergeAntialiasing: false });
  assert.equal(new Set(without.pixels).size, 5);
});

test('gradient blends between two colours are merged even in thick bands, real colours are not', () => {
  const m = mergeAntialiased(4, 1, Int32Array.from([0xff0000, 0x800080, 0x0000ff, 0x00ff00]));
  assert.equal(m.mergedPixels, 1);
  assert.deepEqual(
    [...m.pixels].filter((c) => c === 0x800080),
    [],
  );
  const keep = mergeAntialiased(3, 1, Int32Array.from([0xff0000, 0x00ff00, 0x0000ff]));
  assert.equal(keep.mergedPixels, 0);
});

test('PNG formats: alpha refused, opaque alpha and grey accepted, garbage refused', () => {
  const transparent = png(4, 4, () => [10, 20, 30, 128], 4);
  assert.throws(
    () => decodeCellsPng(transparent),
    (e: unknown) => e instanceof StrataError && e.code === 'BAD_IMAGE' && /transparent/.test(e.message),
  );
  const opaque = png(4, 4, () => [10, 20, 30, 255], 4);
  const d = decodeCellsPng(opaque);
  assert.equal(d.pixels[0], 0x0a141e);
  assert.ok(d.warnings.some((w) => /alpha/.test(w)));
  const grey = encode({ width: 2, height: 1, data: Uint8Array.from([0, 200]), channels: 1, depth: 8 });
  assert.deepEqual([...decodeCellsPng(grey).pixels], [0, 0xc8c8c8]);
  assert.throws(
    () => decodeCellsPng(Uint8Array.from([1, 2, 3])),
    (e: unknown) => e instanceof StrataError && e.code === 'BAD_IMAGE' && /not a PNG/.test(e.message),
  );
  // A header claiming a huge image is refused before decoding.
  const huge = png(2, 2, () => RED);
  const dv = new DataView(huge.buffer, huge.byteOffset);
  dv.setUint32(16, 100000);
  dv.setUint32(20, 100000);
  assert.throws(
    () => decodeCellsPng(huge),
    (e: unknown) => e instanceof StrataError && e.code === 'LIMIT_EXCEEDED',
  );
});
