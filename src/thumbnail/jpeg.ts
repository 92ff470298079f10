/**
 * JPEG thumbnails, encoded by jpeg-js (a pure-JavaScript baseline JPEG encoder; its decoder is not
 * imported, so only the encoder is bundled). Alpha is ignored: callers composite onto a background first.
 *
 * jpeg-js returns a node Buffer when it is loaded as a CommonJS module: in node that is a Uint8Array;
 * the browser bundles (web/build.mjs) give it a `Buffer.from` that makes a Uint8Array.
 */
import encode from 'jpeg-js/lib/encoder.js';
import type { RgbaImage } from './types.js';

/** Encode an RGBA image as a baseline JPEG (JFIF) of the given quality, 1..100. */
export function encodeJpeg(image: RgbaImage, quality = 90): Uint8Array {
  const { data } = encode(
    { width: image.width, height: image.height, data: image.data },
    Math.min(100, Math.max(1, Math.round(quality))),
  );
  return new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
}
