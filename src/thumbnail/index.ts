/**
 * Thumbnails: render the placed mesh for every requested size and encode it in the requested format.
 */
import { encode as encodePng } from 'fast-png';
import type { Mesh } from '../mesh/types.js';
import { encodeJpeg } from './jpeg.js';
import { encodeQoi } from './qoi.js';
import { renderMesh } from './render.js';
import { parseThumbnailSpecs } from './spec.js';
import type { EncodedThumbnail, ThumbnailSpec } from './types.js';

export type { EncodedThumbnail, RgbaImage, ThumbnailFormat, ThumbnailSpec } from './types.js';
export { parseThumbnailSpecs, formatThumbnailSpecs, MAX_THUMBNAIL_PX } from './spec.js';
export { renderMesh } from './render.js';

/** JPEG has no transparency: the model is drawn on this dark grey, as printer screens show it. */
const JPEG_BACKGROUND: readonly [number, number, number] = [38, 38, 38];
/** JPEG quality, 1..100. */
const JPEG_QUALITY = 90;

/** Render and encode one thumbnail of the mesh or meshes (placed together on the bed). */
export function renderThumbnail(mesh: Mesh | readonly Mesh[], spec: ThumbnailSpec): EncodedThumbnail {
  const { width, height, format } = spec;
  if (format === 'JPG') {
    const image = renderMesh(mesh, width, height, { background: JPEG_BACKGROUND });
    return { width, height, format, data: encodeJpeg(image, JPEG_QUALITY) };
  }
  const image = renderMesh(mesh, width, height);
  const data =
    format === 'QOI' ? encodeQoi(image) : encodePng({ width, height, data: image.data, channels: 4, depth: 8 });
  return { width, height, format, data };
}

/** The thumbnails the `thumbnails` setting asks for (none for an empty setting). */
export function renderThumbnails(mesh: Mesh | readonly Mesh[], setting: string): EncodedThumbnail[] {
  return parseThumbnailSpecs(setting).map((spec) => renderThumbnail(mesh, spec));
}
