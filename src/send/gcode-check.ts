/**
 * Is this file G-code? Checked before anything is sent, so that a model, a picture or an empty file is one
 * clear line here rather than a print host's 415 (OctoPrint) or a file the host lists but cannot print
 * (Moonraker takes any file and keeps it).
 */
import { StrataError } from '../errors.js';

/** File name endings both OctoPrint and Moonraker list as printable G-code. */
export const GCODE_EXTENSIONS = ['.gcode', '.gco', '.g'] as const;

/** How much of the file's start is looked at. */
const SNIFF_BYTES = 64 * 1024;

/** A line that is a G-code command (an optional line number, then G, M or T and a number). */
const COMMAND = /^\s*(?:N\d+\s+)?[GMT]\d+/m;

function kindOfModel(head: Uint8Array, text: string): string | null {
  if (head[0] === 0x50 && head[1] === 0x4b) return 'a zip archive (a 3MF model or a project?)';
  if (/^\s*solid\s/.test(text) && /\bfacet\s+normal\b/.test(text)) return 'an ASCII STL model';
  if (/^\s*(?:#.*\n\s*)*(?:v|vn|vt|o|g|mtllib)\s/m.test(text) && !COMMAND.test(text)) return 'an OBJ model';
  return null;
}

/** The name the file gets on the host: its own, which must end in a G-code extension. */
export function checkGcodeName(name: string): string {
  const base = name.split(/[\\/]/).pop() ?? '';
  if (!base) throw new StrataError('BAD_FILE', 'the file to send needs a name');
  if (!GCODE_EXTENSIONS.some((e) => base.toLowerCase().endsWith(e))) {
    throw new StrataError(
      'BAD_FILE',
      `${base} is not a G-code file name (print hosts take ${GCODE_EXTENSIONS.join(', ')})`,
    );
  }
  return base;
}

/** Throws a one-line BAD_FILE error unless `bytes` look like G-code. */
export function checkGcode(bytes: Uint8Array, name: string): void {
  if (bytes.length === 0) throw new StrataError('BAD_FILE', `${name} is empty`);
  const head = bytes.subarray(0, SNIFF_BYTES);
  const text = new TextDecoder('utf-8', { fatal: false }).decode(head);
  const model = kindOfModel(head, text);
  if (model)
    throw new StrataError('BAD_FILE', `${name} is ${model}, not G-code: slice it first (strata slice ${name})`);
  // a binary STL is an 80-byte header and a triangle count that gives its size exactly
  if (
    bytes.length >= 84 &&
    84 + 50 * new DataView(bytes.buffer, bytes.byteOffset + 80, 4).getUint32(0, true) === bytes.length
  ) {
    throw new StrataError(
      'BAD_FILE',
      `${name} is a binary STL model, not G-code: slice it first (strata slice ${name})`,
    );
  }
  if (head.includes(0))
    throw new StrataError('BAD_FILE', `${name} is binary data, not G-code (text lines of G and M commands)`);
  if (!COMMAND.test(text))
    throw new StrataError(
      'BAD_FILE',
      `${name} is not G-code: no G or M command in its first ${SNIFF_BYTES / 1024} KiB`,
    );
}
