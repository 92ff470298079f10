/** Preview images of the plate embedded in G-code. */

export type ThumbnailFormat = 'PNG' | 'QOI' | 'JPG';

/** One requested image: size in pixels and file format. */
export interface ThumbnailSpec {
  width: number;
  height: number;
  format: ThumbnailFormat;
}

/** An image encoded in its file format, ready to be written as a G-code comment block. */
export interface EncodedThumbnail extends ThumbnailSpec {
  data: Uint8Array;
}

/** Pixels, 4 bytes (R, G, B, A) per pixel, rows top to bottom. */
export interface RgbaImage {
  width: number;
  height: number;
  data: Uint8Array;
}
