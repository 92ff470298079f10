/**
 * Thumbnails as G-code comments, in PrusaSlicer's layout (read by Klipper/Moonraker/Mainsail, OctoPrint
 * and Prusa printers): an empty `;` line, `; thumbnail begin WxH LEN` (LEN = characters of base64),
 * the base64 of the image in lines of at most THUMBNAIL_LINE_CHARS after `; `, `; thumbnail end`, and
 * an empty `;` line. QOI and JPG images are marked `thumbnail_QOI` and `thumbnail_JPG`.
 */
import { toBase64 } from '../thumbnail/base64.js';
import type { EncodedThumbnail } from '../thumbnail/types.js';

/** Base64 characters per comment line, as PrusaSlicer writes them. */
export const THUMBNAIL_LINE_CHARS = 78;

export function thumbnailBlockLines(image: EncodedThumbnail): string[] {
  const tag = image.format === 'PNG' ? 'thumbnail' : `thumbnail_${image.format}`;
  const text = toBase64(image.data);
  const lines = [';', `; ${tag} begin ${image.width}x${image.height} ${text.length}`];
  for (let i = 0; i < text.length; i += THUMBNAIL_LINE_CHARS)
    lines.push('; ' + text.slice(i, i + THUMBNAIL_LINE_CHARS));
  lines.push(`; ${tag} end`, ';');
  return lines;
}
