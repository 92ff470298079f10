/**
 * The `thumbnails` setting: `WxH` or `WxH/FORMAT` items separated by commas (PrusaSlicer 2.6+ form;
 * a bare size is PNG). Sizes are 1 to MAX_THUMBNAIL_PX pixels a side.
 */
import { StrataError } from '../errors.js';
import type { ThumbnailFormat, ThumbnailSpec } from './types.js';

/** Largest thumbnail side, px: printers' screens and hosts use up to 800 or so. */
export const MAX_THUMBNAIL_PX = 1024;

const ITEM = /^(\d+)\s*x\s*(\d+)(?:\s*\/\s*([a-z]+))?$/i;
const FORMATS: Readonly<Record<string, ThumbnailFormat>> = { png: 'PNG', qoi: 'QOI', jpg: 'JPG', jpeg: 'JPG' };

/** Parse the setting's text into image specs (empty text: none). Throws StrataError BAD_SETTING naming the bad item. */
export function parseThumbnailSpecs(text: string): ThumbnailSpec[] {
  const specs: ThumbnailSpec[] = [];
  for (const raw of text.split(',')) {
    const item = raw.trim();
    if (item === '') continue;
    const m = ITEM.exec(item);
    const format = m ? (m[3] === undefined ? 'PNG' : FORMATS[m[3].toLowerCase()]) : undefined;
    if (!m || !format) throw new StrataError('BAD_SETTING', `thumbnails: "${item}" is not WxH or WxH/PNG|QOI|JPG`);
    const width = Number(m[1]);
    const height = Number(m[2]);
    if (width < 1 || height < 1 || width > MAX_THUMBNAIL_PX || height > MAX_THUMBNAIL_PX) {
      throw new StrataError('BAD_SETTING', `thumbnails: ${item} must be 1 to ${MAX_THUMBNAIL_PX} pixels a side`);
    }
    specs.push({ width, height, format });
  }
  return specs;
}

/** The setting's text for these specs (the inverse of parseThumbnailSpecs). */
export function formatThumbnailSpecs(specs: readonly ThumbnailSpec[]): string {
  return specs.map((s) => `${s.width}x${s.height}/${s.format}`).join(',');
}
