/**
 * Writes the shipped example infill image, infillers/example-image/cells.png: a tileable 128 × 128
 * brick wall with round windows, flat colours (no anti-aliasing), 24-bit RGB.
 * Run: node dist-dev/tools/make-example-image.js [output.png]
 */
import { writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { encode } from 'fast-png';

const SIZE = 128;
const BRICK_W = 64;
const BRICK_H = 32;
const RADIUS = 20;
const BRICKS = [0xc8553d, 0xf28f3b, 0x588b8b, 0xffd5c2];
const WINDOW = 0x2d3047;

/** RGB bytes (row 0 at the top) of the example image. */
export function exampleImageRgb(): Uint8Array {
  const rgb = new Uint8Array(SIZE * SIZE * 3);
  for (let y = 0; y < SIZE; y++) {
    for (let x = 0; x < SIZE; x++) {
      const row = Math.floor(y / BRICK_H);
      const shift = row % 2 === 1 ? BRICK_W / 2 : 0;
      const brick = Math.floor((x + shift) / BRICK_W) % 2;
      let c = BRICKS[(row % 2) * 2 + brick];
      // Round windows centred on the tile's centre and (wrapping) corners.
      for (const [cx, cy] of [
        [SIZE / 2, SIZE / 2],
        [0, 0],
      ]) {
        let dx = Math.abs(x + 0.5 - cx);
        let dy = Math.abs(y + 0.5 - cy);
        dx = Math.min(dx, SIZE - dx);
        dy = Math.min(dy, SIZE - dy);
        if (dx * dx + dy * dy <= RADIUS * RADIUS) c = WINDOW;
      }
      const o = (y * SIZE + x) * 3;
      rgb[o] = (c >> 16) & 255;
      rgb[o + 1] = (c >> 8) & 255;
      rgb[o + 2] = c & 255;
    }
  }
  return rgb;
}

export function exampleImagePng(): Uint8Array {
  return encode({ width: SIZE, height: SIZE, data: exampleImageRgb(), channels: 3, depth: 8 });
}

if (process.argv[1] !== undefined && import.meta.url === pathToFileURL(process.argv[1]).href) {
  const out =
    process.argv[2] ??
    join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'infillers', 'example-image', 'cells.png');
  writeFileSync(out, exampleImagePng());
  console.log(`wrote ${out}`);
}
