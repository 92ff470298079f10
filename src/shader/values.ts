/**
 * Building blocks over scalarised values: literals, conversions between bases, splatting and
 * constructors (`vec3(x)`, `vec4(v.xy, 0.0, 1.0)`, `mat2(...)`, `int(f)`).
 */
import type { Base, GType } from './glsl-types.js';
import { gtype, isMatrix, isScalar, size, typeName } from './glsl-types.js';
import type { Ctx, Value } from './compiler-context.js';

/** JS literal for a constant; only digits, '.', 'e', signs and parentheses ever come out. */
export function lit(v: number | boolean): string {
  if (typeof v === 'boolean') return v ? 'true' : 'false';
  if (Number.isNaN(v)) return '(0/0)';
  if (v === Infinity) return '(1/0)';
  if (v === -Infinity) return '(-1/0)';
  if (Object.is(v, -0)) return '(-0)';
  const s = String(v);
  if (!/^-?\d+(\.\d+)?(e[+-]\d+)?$/.test(s)) throw new Error('internal: bad literal');
  return v < 0 ? `(${s})` : s;
}

/** Normalise a JS number to the representation of a base (int32, uint32, double, boolean). */
export function coerceConst(v: number | boolean, base: Base): number | boolean {
  const n = typeof v === 'boolean' ? (v ? 1 : 0) : v;
  switch (base) {
    case 'bool':
      return typeof v === 'boolean' ? v : n !== 0;
    case 'int':
      return Number.isFinite(n) ? Math.trunc(n) | 0 : 0;
    case 'uint':
      return Number.isFinite(n) ? Math.trunc(n) >>> 0 : 0;
    default:
      return n;
  }
}

export function constValue(t: GType, k: (number | boolean)[]): Value {
  const kk = k.map((v) => coerceConst(v, t.base));
  return { t, c: kk.map(lit), k: kk };
}

/** Convert one component expression from one base to another. */
export function convertComp(c: string, from: Base, to: Base): string {
  if (from === to) return c;
  switch (to) {
    case 'float':
      return from === 'bool' ? `(${c} ? 1 : 0)` : c;
    case 'int':
      return from === 'bool' ? `(${c} ? 1 : 0)` : `(${c} | 0)`;
    case 'uint':
      return from === 'bool' ? `(${c} ? 1 : 0)` : `(${c} >>> 0)`;
    case 'bool':
      return `(${c} !== 0)`;
  }
}

/** Change the base of a value component-wise (constructor semantics). */
export function convert(v: Value, to: Base): Value {
  const t = gtype(to, v.t.rows, v.t.cols);
  if (v.t.base === to) return v.t === t ? v : { t, c: v.c, k: v.k };
  if (v.k)
    return constValue(
      t,
      v.k.map((x) => coerceConst(x, to)),
    );
  return { t, c: v.c.map((c) => convertComp(c, v.t.base, to)) };
}

/** A scalar repeated n times (atomised first so it is evaluated once). */
export function splat(ctx: Ctx, v: Value, t: GType): Value {
  if (v.k) return constValue(t, new Array<number | boolean>(size(t)).fill(v.k[0]));
  const a = ctx.atom(v.c[0], v.t.base);
  return { t, c: new Array<string>(size(t)).fill(a) };
}

/** Component i of a value as a one-component value. */
export function comp(v: Value, i: number): Value {
  const t = gtype(v.t.base);
  return v.k ? { t, c: [v.c[i]], k: [v.k[i]] } : { t, c: [v.c[i]] };
}

export function fromComps(t: GType, comps: Value[]): Value {
  if (comps.every((c) => c.k !== undefined))
    return constValue(
      t,
      comps.map((c) => (c.k as (number | boolean)[])[0]),
    );
  return { t, c: comps.map((c) => c.c[0]) };
}

/**
 * A constructor call: scalar, vector or matrix type from a list of arguments (already compiled
 * and sequenced).
 */
export function construct(ctx: Ctx, t: GType, args: Value[]): Value {
  const n = size(t);
  if (args.length === 0) throw ctx.error(`${typeName(t)}() needs arguments`);
  for (const a of args) if (a.t.rows === 0) throw ctx.error(`${typeName(t)}(): argument has no value`);
  // Scalar conversions: int(x), float(v) takes the first component.
  if (isScalar(t)) {
    if (args.length !== 1) throw ctx.error(`${typeName(t)}() takes one argument`);
    return convert(comp(args[0], 0), t.base);
  }
  if (args.length === 1) {
    const a = args[0];
    if (isScalar(a.t)) {
      const s = convert(a, t.base);
      if (!isMatrix(t)) return splat(ctx, s, t);
      // mat(s): s on the diagonal.
      const zero = { t: gtype(t.base), c: ['0'], k: [0] };
      const d = s.k ? s : { t: s.t, c: [ctx.atom(s.c[0], s.t.base)] };
      const comps: Value[] = [];
      for (let c = 0; c < t.cols; c++) for (let r = 0; r < t.rows; r++) comps.push(r === c ? d : zero);
      return fromComps(t, comps);
    }
    if (isMatrix(t) && isMatrix(a.t)) {
      // mat3(mat4) and friends: the upper-left block, identity elsewhere.
      const comps: Value[] = [];
      for (let c = 0; c < t.cols; c++) {
        for (let r = 0; r < t.rows; r++) {
          if (c < a.t.cols && r < a.t.rows) comps.push(comp(a, c * a.t.rows + r));
          else comps.push({ t: gtype('float'), c: [r === c ? '1' : '0'], k: [r === c ? 1 : 0] });
        }
      }
      return fromComps(t, comps);
    }
    if (!isMatrix(t) && size(a.t) >= n) {
      // vec2(vec4) truncates.
      const comps: Value[] = [];
      for (let i = 0; i < n; i++) comps.push(convert(comp(a, i), t.base));
      return fromComps(t, comps);
    }
  }
  const flat: Value[] = [];
  for (const a of args) {
    if (isMatrix(a.t) && !isMatrix(t)) throw ctx.error(`${typeName(t)}(): matrix arguments are not supported here`);
    if (flat.length >= n) throw ctx.error(`${typeName(t)}(): too many arguments`);
    for (let i = 0; i < size(a.t) && flat.length < n; i++) flat.push(convert(comp(a, i), t.base));
  }
  if (flat.length < n) throw ctx.error(`${typeName(t)}(): not enough components (${flat.length} of ${n})`);
  return fromComps(t, flat);
}
