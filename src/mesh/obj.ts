/**
 * Wavefront OBJ reader: `v` and `f` (v, v/vt, v//vn, v/vt/vn; negative = relative indices),
 * polygons fan-triangulated, every `o` / `g` starts a new object. Other statements are ignored.
 */
import { StrataError } from '../errors.js';
import { printable } from './printable.js';
import { GrowableF64, GrowableU32 } from './growable.js';
import { MAX_MODEL_TRIANGLES, MAX_MODEL_VERTICES, tooManyTriangles, tooManyVertices } from './limits.js';
import type { MeshObject } from './types.js';
import { weld } from './weld.js';

interface Group {
  name: string;
  /** Triangle corners as global vertex indices (resolved, 0-based). */
  corners: GrowableU32;
  /** First line of the group, for messages. */
  line: number;
}

export function parseObj(input: string | Uint8Array, name = 'model'): MeshObject[] {
  const text = typeof input === 'string' ? input : new TextDecoder('utf-8').decode(input);
  const len = text.length;
  const verts = new GrowableF64(4096);
  const groups: Group[] = [];
  let current: Group = { name: '', corners: new GrowableU32(4096), line: 1 };
  groups.push(current);
  const poly: number[] = [];
  /** Largest positive index seen (1-based), checked against the vertex count at the end. */
  let maxIndex = 0;
  let maxIndexLine = 0;
  let triangles = 0;

  let lineNo = 0;
  let pos = 0;
  while (pos < len) {
    lineNo++;
    let end = text.indexOf('\n', pos);
    if (end < 0) end = len;
    const lineStart = pos;
    pos = end + 1;
    let i = lineStart;
    while (i < end && isBlank(text.charCodeAt(i))) i++;
    if (i >= end) continue;
    const c0 = text.charCodeAt(i);
    const c1 = i + 1 < end ? text.charCodeAt(i + 1) : 32;
    if (!isBlank(c1) && c1 !== 13) {
      // Keywords longer than one letter: vt, vn, vp, usemtl, mtllib, ... all ignored.
      continue;
    }
    const line = text.slice(i + 1, end);
    if (c0 === 118 /* v */) {
      const t = tokens(line);
      if (t.length < 3) fail(lineNo, `a vertex needs 3 coordinates, found ${t.length}`);
      const x = Number(t[0]),
        y = Number(t[1]),
        z = Number(t[2]);
      if (!Number.isFinite(x) || !Number.isFinite(y) || !Number.isFinite(z)) {
        fail(lineNo, `vertex "${clip(line.trim())}" has a coordinate that is not a number`);
      }
      verts.push3(x, y, z);
      if (verts.length > 3 * MAX_MODEL_VERTICES) tooManyVertices('OBJ');
    } else if (c0 === 102 /* f */) {
      const t = tokens(line);
      if (t.length < 3) fail(lineNo, `a face needs at least 3 vertices, found ${t.length}`);
      poly.length = 0;
      const nv = verts.length / 3;
      for (const tok of t) {
        const slash = tok.indexOf('/');
        const s = slash < 0 ? tok : tok.slice(0, slash);
        const k = parseIndex(s);
        if (k === 0 || k === undefined) fail(lineNo, `"${clip(tok)}" is not a valid vertex index`);
        let v: number;
        if (k > 0) {
          v = k - 1;
          if (k > maxIndex) {
            maxIndex = k;
            maxIndexLine = lineNo;
          }
        } else {
          v = nv + k;
          if (v < 0) fail(lineNo, `relative index ${k} points before the first vertex (${nv} so far)`);
        }
        poly.push(v);
      }
      const g = current.corners;
      triangles += poly.length - 2;
      if (triangles > MAX_MODEL_TRIANGLES) tooManyTriangles('OBJ');
      for (let k = 1; k + 1 < poly.length; k++) g.push3(poly[0], poly[k], poly[k + 1]);
    } else if (c0 === 111 /* o */ || c0 === 103 /* g */) {
      const groupName = printable(line.trim(), 200);
      if (current.corners.length === 0) {
        current.name = groupName;
        current.line = lineNo;
      } else {
        current = { name: groupName, corners: new GrowableU32(1024), line: lineNo };
        groups.push(current);
      }
    }
    // Everything else (comments, vt, vn, usemtl, s, l, p, ...) carries no triangles.
  }

  const nVerts = verts.length / 3;
  if (maxIndex > nVerts) {
    fail(maxIndexLine, `a face uses vertex ${maxIndex} but the file has only ${nVerts} vertices`);
  }
  const nonEmpty = groups.filter((g) => g.corners.length > 0);
  if (nonEmpty.length === 0) throw new StrataError('EMPTY_MODEL', 'the OBJ file holds no faces');

  const all = verts.data;
  const stamp = new Int32Array(nVerts).fill(-1);
  const local = new Uint32Array(nVerts);
  return nonEmpty.map((g, gi) => {
    const corners = g.corners.data.subarray(0, g.corners.length);
    let used = 0;
    for (let i = 0; i < corners.length; i++) {
      const v = corners[i];
      if (stamp[v] !== gi) {
        stamp[v] = gi;
        local[v] = used++;
      }
    }
    const positions = new Float32Array(used * 3);
    const indices = new Uint32Array(corners.length);
    for (let i = 0; i < corners.length; i++) {
      const v = corners[i];
      const l = local[v];
      indices[i] = l;
      positions[l * 3] = all[v * 3];
      positions[l * 3 + 1] = all[v * 3 + 1];
      positions[l * 3 + 2] = all[v * 3 + 2];
    }
    const objName = g.name !== '' ? g.name : nonEmpty.length > 1 ? `${name} ${gi + 1}` : name;
    return { name: objName, mesh: weld(positions, indices, 'OBJ') };
  });
}

function isBlank(c: number): boolean {
  return c === 32 || c === 9 || c === 13 || c === 12 || c === 11;
}

function tokens(s: string): string[] {
  const out: string[] = [];
  const n = s.length;
  let i = 0;
  while (i < n) {
    while (i < n && isBlank(s.charCodeAt(i))) i++;
    if (i >= n) break;
    const start = i;
    while (i < n && !isBlank(s.charCodeAt(i))) i++;
    if (s.charCodeAt(start) === 35 /* # */) break;
    out.push(s.slice(start, i));
  }
  return out;
}

/** A signed decimal integer, or undefined. */
function parseIndex(s: string): number | undefined {
  const n = s.length;
  let i = 0;
  let neg = false;
  if (n > 0 && (s.charCodeAt(0) === 45 || s.charCodeAt(0) === 43)) {
    neg = s.charCodeAt(0) === 45;
    i = 1;
  }
  if (i >= n || n - i > 10) return undefined;
  let v = 0;
  for (; i < n; i++) {
    const d = s.charCodeAt(i) - 48;
    if (d < 0 || d > 9) return undefined;
    v = v * 10 + d;
  }
  if (v > 0xffffffff) return undefined;
  return neg ? -v : v;
}

function clip(s: string): string {
  return printable(s, 40);
}

function fail(line: number, msg: string): never {
  throw new StrataError('BAD_FILE', `OBJ, line ${line}: ${msg}`);
}
