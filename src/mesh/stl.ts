/**
 * STL reader, binary and ASCII. Binary is recognised by its exact size (84 + 50·n bytes), not by the
 * "solid" prefix, which many binary files also start with. Each ASCII `solid` block becomes one object.
 */
import { StrataError } from '../errors.js';
import { printable } from './printable.js';
import { GrowableF32 } from './growable.js';
import { MAX_MODEL_TRIANGLES, tooManyTriangles } from './limits.js';
import type { MeshObject } from './types.js';
import { weld } from './weld.js';

export function parseStl(bytes: Uint8Array, name = 'model'): MeshObject[] {
  const len = bytes.length;
  const count = len >= 84 ? readU32(bytes, 80) : -1;
  if (count >= 0 && 84 + 50 * count === len) return [readBinary(bytes, count, name)];
  if (looksAscii(bytes)) return parseAsciiStl(new TextDecoder('utf-8').decode(bytes), name);
  if (len < 84) {
    throw new StrataError(
      'BAD_FILE',
      `not an STL file: ${len} bytes is too short for binary STL and it is not ASCII STL`,
    );
  }
  const expected = 84 + 50 * count;
  // Fewer than 50 stray bytes after the last triangle cannot hold geometry: tolerate them.
  if (expected < len && len - expected < 50) return [readBinary(bytes, count, name)];
  const what = expected > len ? 'the file is truncated or not an STL' : 'the file has extra data or is not an STL';
  throw new StrataError(
    'BAD_FILE',
    `binary STL size mismatch: the header says ${count} triangles (${expected} bytes) but the file has ${len} bytes; ${what}`,
  );
}

function readU32(b: Uint8Array, o: number): number {
  return (b[o] | (b[o + 1] << 8) | (b[o + 2] << 16) | (b[o + 3] << 24)) >>> 0;
}

/** ASCII if it starts with the keyword "solid" and the first bytes hold no binary control bytes. */
function looksAscii(b: Uint8Array): boolean {
  let i = 0;
  while (i < b.length && (b[i] === 32 || b[i] === 9 || b[i] === 10 || b[i] === 13)) i++;
  if (i === 0 && b[0] === 0xef && b[1] === 0xbb && b[2] === 0xbf) i = 3;
  const kw = 'solid';
  for (let k = 0; k < 5; k++) {
    const c = b[i + k];
    if (c !== kw.charCodeAt(k) && c !== kw.charCodeAt(k) - 32) return false;
  }
  const after = b[i + 5];
  if (after !== undefined && after !== 32 && after !== 9 && after !== 10 && after !== 13) return false;
  const end = Math.min(b.length, 256);
  for (let k = i; k < end; k++) {
    const c = b[k];
    if (c < 9 || (c > 13 && c < 32)) return false;
  }
  return true;
}

function readBinary(bytes: Uint8Array, count: number, name: string): MeshObject {
  if (count === 0) throw new StrataError('EMPTY_MODEL', 'the STL file holds no triangles');
  if (count > MAX_MODEL_TRIANGLES) tooManyTriangles('binary STL', count);
  const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const positions = new Float32Array(count * 9);
  for (let t = 0, o = 96, p = 0; t < count; t++, o += 50, p += 9) {
    positions[p] = dv.getFloat32(o, true);
    positions[p + 1] = dv.getFloat32(o + 4, true);
    positions[p + 2] = dv.getFloat32(o + 8, true);
    positions[p + 3] = dv.getFloat32(o + 12, true);
    positions[p + 4] = dv.getFloat32(o + 16, true);
    positions[p + 5] = dv.getFloat32(o + 20, true);
    positions[p + 6] = dv.getFloat32(o + 24, true);
    positions[p + 7] = dv.getFloat32(o + 28, true);
    positions[p + 8] = dv.getFloat32(o + 32, true);
  }
  return { name, mesh: weld(positions, null, 'binary STL') };
}

function isSpace(c: number): boolean {
  return c === 32 || c === 10 || c === 13 || c === 9 || c === 12 || c === 11;
}

/** Parse ASCII STL text: `solid name`, `facet normal`, `outer loop`, `vertex x y z`, `endloop`, `endfacet`, `endsolid`. */
export function parseAsciiStl(text: string, name = 'model'): MeshObject[] {
  const len = text.length;
  let pos = 0;
  let s = 0; // current token [s, e)
  let e = 0;

  const next = (): boolean => {
    while (pos < len && isSpace(text.charCodeAt(pos))) pos++;
    if (pos >= len) return false;
    s = pos;
    while (pos < len && !isSpace(text.charCodeAt(pos))) pos++;
    e = pos;
    return true;
  };
  const is = (kw: string): boolean => e - s === kw.length && text.startsWith(kw, s);
  const lineAt = (at: number): number => {
    let n = 1;
    for (let i = 0; i < at && i < len; i++) if (text.charCodeAt(i) === 10) n++;
    return n;
  };
  const fail = (msg: string, at = s): never => {
    throw new StrataError('BAD_FILE', `ASCII STL, line ${lineAt(at)}: ${msg}`);
  };
  const token = (): string => printable(text.slice(s, Math.min(e, s + 41)), 40);
  const number = (what: string): number => {
    if (!next()) fail(`the file ends where a ${what} coordinate was expected (truncated?)`, len);
    const v = Number(text.slice(s, e));
    if (!Number.isFinite(v) || e === s) fail(`"${token()}" is not a number (expected a ${what} coordinate)`);
    return v;
  };
  const restOfLine = (): string => {
    const start = pos;
    while (pos < len && text.charCodeAt(pos) !== 10 && text.charCodeAt(pos) !== 13) pos++;
    return text.slice(start, pos).trim();
  };

  const objects: MeshObject[] = [];
  let solidName = '';
  let tris: GrowableF32 | null = null;
  let inFacet = false;
  let facetStart = 0;
  const facet: number[] = [];
  let solids = 0;
  let triangles = 0;

  const finishSolid = (): void => {
    if (tris !== null && tris.length > 0) {
      solids++;
      objects.push({ name: solidName, mesh: weld(tris.toArray(), null, 'ASCII STL') });
    }
    tris = null;
  };

  while (next()) {
    if (is('facet')) {
      if (inFacet) fail('"facet" inside another facet (missing "endfacet")');
      if (tris === null) {
        tris = new GrowableF32(4096);
        solidName = '';
      }
      inFacet = true;
      facetStart = s;
      facet.length = 0;
    } else if (is('vertex')) {
      if (!inFacet) fail('"vertex" outside a facet');
      facet.push(number('vertex'), number('vertex'), number('vertex'));
    } else if (is('normal')) {
      if (!inFacet) fail('"normal" outside a facet');
      number('normal');
      number('normal');
      number('normal');
    } else if (is('outer')) {
      if (!inFacet) fail('"outer" outside a facet');
      if (!next() || !is('loop')) fail('"outer" is not followed by "loop"');
    } else if (is('endloop')) {
      if (!inFacet) fail('"endloop" outside a facet');
    } else if (is('endfacet')) {
      if (!inFacet) fail('"endfacet" without "facet"');
      const nv = facet.length / 3;
      if (nv < 3) fail(`a facet has ${nv} vertices; a triangle needs 3`, facetStart);
      const t = tris;
      if (t === null) return fail('"endfacet" outside a solid');
      triangles += nv - 2;
      if (triangles > MAX_MODEL_TRIANGLES) tooManyTriangles('ASCII STL');
      for (let k = 1; k + 1 < nv; k++) {
        t.push3(facet[0], facet[1], facet[2]);
        t.push3(facet[k * 3], facet[k * 3 + 1], facet[k * 3 + 2]);
        t.push3(facet[k * 3 + 3], facet[k * 3 + 4], facet[k * 3 + 5]);
      }
      inFacet = false;
    } else if (is('solid')) {
      if (inFacet) fail('"solid" inside a facet');
      finishSolid();
      solidName = printable(restOfLine(), 200);
      tris = new GrowableF32(4096);
    } else if (is('endsolid')) {
      if (inFacet) fail('"endsolid" inside a facet (missing "endfacet")');
      restOfLine();
      finishSolid();
    } else {
      fail(`unexpected "${token()}"`);
    }
  }
  if (inFacet) fail('the file ends inside a facet (truncated?)', len);
  finishSolid();
  if (objects.length === 0) throw new StrataError('EMPTY_MODEL', 'the STL file holds no triangles');
  objects.forEach((o, i) => {
    if (o.name === '') o.name = solids > 1 ? `${name} ${i + 1}` : name;
  });
  return objects;
}
