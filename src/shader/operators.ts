/**
 * GLSL operators over scalarised values: arithmetic (with int/uint wrap-around), bitwise, shifts,
 * comparisons, equality, unary operators, and the linear-algebra products m*v, v*m, m*m.
 */
import type { Base, GType } from './glsl-types.js';
import { BOOL, commonBase, gtype, isMatrix, isScalar, isVector, sameType, size, typeName } from './glsl-types.js';
import type { Ctx, Value } from './compiler-context.js';
import { constValue, convert, splat } from './values.js';

export type ArithOp = '+' | '-' | '*' | '/' | '%' | '&' | '|' | '^' | '<<' | '>>';

function opCode(op: ArithOp, base: Base, x: string, y: string): string {
  if (base === 'float') return `(${x} ${op} ${y})`;
  if (base === 'int') {
    switch (op) {
      case '*':
        return `m_imul(${x}, ${y})`;
      case '&':
      case '|':
      case '^':
      case '<<':
      case '>>':
        return `(${x} ${op} ${y})`;
      default:
        return `((${x} ${op} ${y}) | 0)`;
    }
  }
  switch (op) {
    case '*':
      return `(m_imul(${x}, ${y}) >>> 0)`;
    case '>>':
      return `(${x} >>> ${y})`;
    default:
      return `((${x} ${op} ${y}) >>> 0)`;
  }
}

function foldOp(op: ArithOp, base: Base, x: number, y: number): number {
  if (base === 'float') {
    switch (op) {
      case '+':
        return x + y;
      case '-':
        return x - y;
      case '*':
        return x * y;
      case '/':
        return x / y;
    }
    return NaN;
  }
  const wrap = base === 'int' ? (v: number) => v | 0 : (v: number) => v >>> 0;
  switch (op) {
    case '+':
      return wrap(x + y);
    case '-':
      return wrap(x - y);
    case '*':
      return wrap(Math.imul(x, y));
    case '/':
      return wrap(x / y);
    case '%':
      return wrap(x % y);
    case '&':
      return wrap(x & y);
    case '|':
      return wrap(x | y);
    case '^':
      return wrap(x ^ y);
    case '<<':
      return wrap(x << y);
    case '>>':
      return base === 'int' ? x >> y : x >>> y;
  }
}

function checkNumeric(ctx: Ctx, op: string, v: Value): void {
  if (v.t.rows === 0) throw ctx.error(`operator ${op}: operand has no value`);
  if (v.t.base === 'bool') throw ctx.error(`operator ${op} needs numbers, not ${typeName(v.t)}`);
}

/** Same-shape component-wise op (after splatting scalars). */
function componentwise(ctx: Ctx, op: ArithOp, a: Value, b: Value, base: Base): Value {
  let x = a;
  let y = b;
  if (!sameShape(x.t, y.t)) {
    if (isScalar(x.t)) x = splat(ctx, x, gtype(x.t.base, y.t.rows, y.t.cols));
    else if (isScalar(y.t)) y = splat(ctx, y, gtype(y.t.base, x.t.rows, x.t.cols));
    else throw ctx.error(`operator ${op}: ${typeName(a.t)} and ${typeName(b.t)} do not match`);
  }
  const t = gtype(base, x.t.rows, x.t.cols);
  if (x.k && y.k) {
    const xk = x.k as number[];
    const yk = y.k as number[];
    return constValue(
      t,
      xk.map((v, i) => foldOp(op, base, v, yk[i])),
    );
  }
  return { t, c: x.c.map((c, i) => opCode(op, base, c, y.c[i])) };
}

function sameShape(a: GType, b: GType): boolean {
  return a.rows === b.rows && a.cols === b.cols;
}

function sum(terms: string[]): string {
  return terms.length === 1 ? terms[0] : `(${terms.join(' + ')})`;
}

function matMul(ctx: Ctx, a: Value, b: Value): Value {
  const A = ctx.atomValue(a);
  const Bv = ctx.atomValue(b);
  if (isMatrix(A.t) && isMatrix(Bv.t)) {
    const n = A.t.rows;
    if (A.t.cols !== Bv.t.rows) throw ctx.error(`cannot multiply ${typeName(A.t)} by ${typeName(Bv.t)}`);
    const c: string[] = [];
    for (let col = 0; col < Bv.t.cols; col++) {
      for (let row = 0; row < n; row++) {
        const terms: string[] = [];
        for (let k = 0; k < A.t.cols; k++) terms.push(`${A.c[k * n + row]} * ${Bv.c[col * Bv.t.rows + k]}`);
        c.push(sum(terms));
      }
    }
    return { t: gtype('float', n, Bv.t.cols), c };
  }
  if (isMatrix(A.t)) {
    // m * v: a column vector.
    if (A.t.cols !== Bv.t.rows) throw ctx.error(`cannot multiply ${typeName(A.t)} by ${typeName(Bv.t)}`);
    const c: string[] = [];
    for (let row = 0; row < A.t.rows; row++) {
      const terms: string[] = [];
      for (let k = 0; k < A.t.cols; k++) terms.push(`${A.c[k * A.t.rows + row]} * ${Bv.c[k]}`);
      c.push(sum(terms));
    }
    return { t: gtype('float', A.t.rows), c };
  }
  // v * m: a row vector.
  if (A.t.rows !== Bv.t.rows) throw ctx.error(`cannot multiply ${typeName(A.t)} by ${typeName(Bv.t)}`);
  const c: string[] = [];
  for (let col = 0; col < Bv.t.cols; col++) {
    const terms: string[] = [];
    for (let k = 0; k < Bv.t.rows; k++) terms.push(`${A.c[k]} * ${Bv.c[col * Bv.t.rows + k]}`);
    c.push(sum(terms));
  }
  return { t: gtype('float', Bv.t.cols), c };
}

export function arith(ctx: Ctx, op: ArithOp, a: Value, b: Value): Value {
  checkNumeric(ctx, op, a);
  checkNumeric(ctx, op, b);
  if (op === '<<' || op === '>>') {
    if (a.t.base === 'float' || b.t.base === 'float') throw ctx.error(`operator ${op} needs integers`);
    if (!isScalar(b.t) && !sameShape(a.t, b.t))
      throw ctx.error(`operator ${op}: ${typeName(a.t)} and ${typeName(b.t)} do not match`);
    let y = b;
    if (!sameShape(a.t, b.t)) y = splat(ctx, b, gtype(b.t.base, a.t.rows, a.t.cols));
    if (isScalar(a.t) && !isScalar(b.t)) throw ctx.error(`operator ${op}: a scalar cannot be shifted by a vector`);
    return componentwise(ctx, op, a, y, a.t.base);
  }
  const base = commonBase(a.t.base, b.t.base);
  if (base === undefined) throw ctx.error(`operator ${op}: ${typeName(a.t)} and ${typeName(b.t)} do not match`);
  if (base === 'float' && (op === '%' || op === '&' || op === '|' || op === '^')) {
    throw ctx.error(op === '%' ? 'operator % needs integers (use mod() for floats)' : `operator ${op} needs integers`);
  }
  const x = convert(a, base);
  const y = convert(b, base);
  if (op === '*' && (isMatrix(x.t) || isMatrix(y.t)) && !isScalar(x.t) && !isScalar(y.t)) {
    if (isVector(x.t) && isVector(y.t)) return componentwise(ctx, op, x, y, base);
    return matMul(ctx, x, y);
  }
  return componentwise(ctx, op, x, y, base);
}

export type CompareOp = '<' | '>' | '<=' | '>=';

export function compare(ctx: Ctx, op: CompareOp, a: Value, b: Value): Value {
  checkNumeric(ctx, op, a);
  checkNumeric(ctx, op, b);
  if (!isScalar(a.t) || !isScalar(b.t))
    throw ctx.error(`operator ${op} needs scalars (use lessThan() etc. for vectors)`);
  const base = commonBase(a.t.base, b.t.base) as Base;
  const x = convert(a, base);
  const y = convert(b, base);
  if (x.k && y.k) {
    const p = x.k[0] as number;
    const q = y.k[0] as number;
    const r = op === '<' ? p < q : op === '>' ? p > q : op === '<=' ? p <= q : p >= q;
    return constValue(BOOL, [r]);
  }
  return { t: BOOL, c: [`(${x.c[0]} ${op} ${y.c[0]})`] };
}

export function equality(ctx: Ctx, op: '==' | '!=', a: Value, b: Value): Value {
  if (a.t.rows === 0 || b.t.rows === 0) throw ctx.error(`operator ${op}: operand has no value`);
  const base = commonBase(a.t.base, b.t.base);
  if (base === undefined || !sameShape(a.t, b.t))
    throw ctx.error(`operator ${op}: ${typeName(a.t)} and ${typeName(b.t)} do not match`);
  const x = convert(a, base);
  const y = convert(b, base);
  if (x.k && y.k) {
    const yk = y.k;
    const eq = x.k.every((v, i) => v === yk[i]);
    return constValue(BOOL, [op === '==' ? eq : !eq]);
  }
  const parts = x.c.map((c, i) => `${c} ${op === '==' ? '===' : '!=='} ${y.c[i]}`);
  return { t: BOOL, c: [`(${parts.join(op === '==' ? ' && ' : ' || ')})`] };
}

export function negate(ctx: Ctx, a: Value): Value {
  checkNumeric(ctx, '-', a);
  const base = a.t.base;
  if (a.k)
    return constValue(
      a.t,
      (a.k as number[]).map((v) => (base === 'float' ? -v : base === 'int' ? -v | 0 : -v >>> 0)),
    );
  const c = a.c.map((x) => (base === 'float' ? `(-${x})` : base === 'int' ? `((-${x}) | 0)` : `((-${x}) >>> 0)`));
  return { t: a.t, c };
}

export function logicalNot(ctx: Ctx, a: Value): Value {
  if (!sameType(a.t, BOOL)) throw ctx.error(`operator ! needs a bool, not ${typeName(a.t)}`);
  if (a.k) return constValue(BOOL, [!a.k[0]]);
  return { t: BOOL, c: [`(!${a.c[0]})`] };
}

export function bitNot(ctx: Ctx, a: Value): Value {
  checkNumeric(ctx, '~', a);
  if (a.t.base === 'float') throw ctx.error('operator ~ needs integers');
  const base = a.t.base;
  if (a.k)
    return constValue(
      a.t,
      (a.k as number[]).map((v) => (base === 'int' ? ~v : ~v >>> 0)),
    );
  return { t: a.t, c: a.c.map((x) => (base === 'int' ? `(~${x})` : `((~${x}) >>> 0)`)) };
}

/** `a ^^ b` (both evaluated). */
export function logicalXor(ctx: Ctx, a: Value, b: Value): Value {
  if (!sameType(a.t, BOOL) || !sameType(b.t, BOOL)) throw ctx.error('operator ^^ needs bools');
  if (a.k && b.k) return constValue(BOOL, [a.k[0] !== b.k[0]]);
  return { t: BOOL, c: [`(${a.c[0]} !== ${b.c[0]})`] };
}

export function requireBool(ctx: Ctx, v: Value, what: string): Value {
  if (!sameType(v.t, BOOL)) throw ctx.error(`${what} must be a bool, not ${v.t.rows === 0 ? 'void' : typeName(v.t)}`);
  return v;
}

export function countOf(t: GType): number {
  return size(t);
}
