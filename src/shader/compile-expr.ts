/**
 * GLSL expressions → scalarised JS: identifiers, literals, swizzles (also as assignment targets),
 * indexing, operators, assignments, ternaries, short-circuit logic, constructors and calls.
 * Side effects (assignments, ++/--, user calls) are emitted as statements in evaluation order.
 */
import type { Base, GType } from './glsl-types.js';
import {
  BOOL,
  FLOAT,
  INT,
  UINT,
  gtype,
  implicitlyConvertible,
  isMatrix,
  isScalar,
  parseTypeName,
  size,
  typeName,
} from './glsl-types.js';
import type { ArraySym, Ctx, FnSym, LValue, Slot, Value } from './compiler-context.js';
import { Buf, VOID_TYPE, isVoid, short } from './compiler-context.js';
import { constValue, construct, convert, lit } from './values.js';
import type { ArithOp } from './operators.js';
import { arith, bitNot, compare, equality, logicalNot, logicalXor, negate, requireBool } from './operators.js';
import { callBuiltin, isBuiltinName, isUnavailable } from './builtins.js';

// The parser's node types are loose; compile code reads fields through this alias.
// biome-ignore lint/suspicious/noExplicitAny: the GLSL parser's AST nodes are untyped
type Node = any;

const MAX_EXPR_DEPTH = 1000;

export function nodeLine(node: Node): number | undefined {
  return node?.location?.start?.line;
}

function at(ctx: Ctx, node: Node): void {
  const l = nodeLine(node);
  if (l !== undefined) ctx.line = l;
}

// ── literals ──────────────────────────────────────────────────────────────────

function parseIntToken(ctx: Ctx, token: string): Value {
  const m = /^(0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)([uU]?)$/.exec(token);
  if (!m) throw ctx.error(`bad integer literal '${short(token)}'`);
  const body = m[1];
  const v = /^0[xX]/.test(body)
    ? parseInt(body.slice(2), 16)
    : body.length > 1 && body[0] === '0'
      ? parseInt(body, 8)
      : Number(body);
  if (!Number.isFinite(v) || v > 0xffffffff) throw ctx.error(`integer literal '${short(token)}' is too large`);
  return m[2] ? constValue(UINT, [v >>> 0]) : constValue(INT, [v | 0]);
}

function parseFloatToken(ctx: Ctx, token: string): Value {
  const m = /^((?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)(?:[fF]|lf|LF)?$/.exec(token);
  if (!m) throw ctx.error(`bad float literal '${short(token)}'`);
  return constValue(FLOAT, [Number(m[1])]);
}

// ── places (lvalues) ──────────────────────────────────────────────────────────

type Ref = { kind: 'lv'; lv: LValue } | { kind: 'val'; v: Value } | { kind: 'arr'; sym: ArraySym; root: string };

export function readSlot(s: Slot): string {
  switch (s.kind) {
    case 'name':
      return s.name;
    case 'elem':
      return s.base === 'bool' ? `(${s.arr}[${s.index}] !== 0)` : `${s.arr}[${s.index}]`;
    case 'dyn': {
      let out = readSlot(s.options[s.options.length - 1]);
      for (let i = s.options.length - 2; i >= 0; i--) out = `${s.index} === ${i} ? ${readSlot(s.options[i])} : ${out}`;
      return `(${out})`;
    }
  }
}

function writeSlotCode(s: Slot, expr: string): string {
  switch (s.kind) {
    case 'name':
      return `${s.name} = ${expr};`;
    case 'elem':
      return `${s.arr}[${s.index}] = ${expr};`;
    case 'dyn': {
      let out = `{ ${writeSlotCode(s.options[s.options.length - 1], expr)} }`;
      for (let i = s.options.length - 2; i >= 0; i--)
        out = `if (${s.index} === ${i}) { ${writeSlotCode(s.options[i], expr)} } else ${out}`;
      return out;
    }
  }
}

export function readLValue(lv: LValue): Value {
  return { t: lv.t, c: lv.slots.map(readSlot) };
}

function slotNames(s: Slot, out: string[]): void {
  if (s.kind === 'name') out.push(s.name);
  else if (s.kind === 'dyn') for (const o of s.options) slotNames(o, out);
  else out.push(s.arr);
}

function mentions(expr: string, name: string): boolean {
  let i = expr.indexOf(name);
  while (i >= 0) {
    const before = expr[i - 1];
    const after = expr[i + name.length];
    if ((before === undefined || !/[A-Za-z0-9_]/.test(before)) && (after === undefined || !/[A-Za-z0-9_]/.test(after)))
      return true;
    i = expr.indexOf(name, i + 1);
  }
  return false;
}

/** Store a value into a place (implicit conversions applied); emits statements. */
export function assign(ctx: Ctx, lv: LValue, value: Value): void {
  if (lv.readOnly !== undefined) throw ctx.error(lv.readOnly);
  if (isVoid(value)) throw ctx.error('cannot assign a void value');
  let v = value;
  if (v.t.base !== lv.t.base || v.t.rows !== lv.t.rows || v.t.cols !== lv.t.cols) {
    if (!implicitlyConvertible(v.t, lv.t)) throw ctx.error(`cannot assign ${typeName(v.t)} to ${typeName(lv.t)}`);
    v = convert(v, lv.t.base);
  }
  if (lv.slots.length > 1 && !v.k) {
    // Copy first if a later component reads a place written by an earlier one (v.xy = v.yx).
    const names: string[][] = lv.slots.map((s) => {
      const n: string[] = [];
      slotNames(s, n);
      return n;
    });
    let clash = false;
    for (let i = 1; i < v.c.length && !clash; i++) {
      for (let j = 0; j < i && !clash; j++) for (const n of names[j]) if (mentions(v.c[i], n)) clash = true;
    }
    if (clash) v = { t: v.t, c: v.c.map((c) => ctx.snapshot(c, v.t.base)) };
  }
  for (let i = 0; i < lv.slots.length; i++) {
    const s = lv.slots[i];
    const expr = s.kind === 'dyn' ? ctx.atom(v.c[i], v.t.base) : v.c[i];
    ctx.emit(writeSlotCode(s, expr));
  }
}

const SWIZZLE_SETS = ['xyzw', 'rgba', 'stpq'];

function swizzleIndices(ctx: Ctx, sel: string, n: number): number[] {
  if (sel.length < 1 || sel.length > 4) throw ctx.error(`bad swizzle '.${short(sel)}'`);
  for (const set of SWIZZLE_SETS) {
    if (!set.includes(sel[0])) continue;
    const idx: number[] = [];
    for (const ch of sel) {
      const i = set.indexOf(ch);
      if (i < 0) throw ctx.error(`bad swizzle '.${short(sel)}' (mixes component sets)`);
      if (i >= n) throw ctx.error(`swizzle '.${short(sel)}' reads past the end of a ${n}-component value`);
      idx.push(i);
    }
    return idx;
  }
  throw ctx.error(`unknown field '.${short(sel)}'`);
}

function clampIndexConst(ctx: Ctx, i: number, n: number, what: string): number {
  if (i < 0 || i >= n) throw ctx.error(`index ${i} is out of range for ${what} of ${n}`);
  return i;
}

function indexValue(ctx: Ctx, node: Node): Value {
  const v = compileExpr(ctx, node);
  if (!isScalar(v.t) || (v.t.base !== 'int' && v.t.base !== 'uint'))
    throw ctx.error(`index must be an int, not ${isVoid(v) ? 'void' : typeName(v.t)}`);
  return v;
}

/** Atomised dynamic index clamped to [0, n-1] (GLSL leaves out-of-range undefined; we clamp). */
function clampedIndex(ctx: Ctx, v: Value, n: number): string {
  const i = ctx.atom(v.c[0], 'int');
  return ctx.atom(`(${i} < 0 ? 0 : ${i} > ${n - 1} ? ${n - 1} : ${i})`, 'int');
}

function rootIdentifier(node: Node): string | undefined {
  if (node === null || node === undefined) return undefined;
  if (node.type === 'identifier') return node.identifier;
  if (node.type === 'type_specifier' && node.identifier?.type === 'identifier') return node.identifier.identifier;
  if (node.type === 'postfix') return rootIdentifier(node.expression);
  if (node.type === 'group') return rootIdentifier(node.expression);
  return undefined;
}

/** The selectors of a postfix chain (`.xy`, `[i]`, `++`) in order; the parser nests them. */
function selectors(p: Node, out: Node[] = [], depth = 0): Node[] {
  if (depth > MAX_EXPR_DEPTH) return out;
  if (p?.type === 'postfix') {
    selectors(p.expression, out, depth + 1);
    selectors(p.postfix, out, depth + 1);
  } else if (p !== null && p !== undefined) out.push(p);
  return out;
}

function applySelector(ctx: Ctx, base: Ref, sel: Node): Ref {
  if (sel.type === 'field_selection') {
    const name: string = sel.selection?.identifier ?? sel.selection?.literal ?? '';
    if (base.kind === 'arr') throw ctx.error(`arrays have no field '.${short(name)}' (only .length())`);
    const t = base.kind === 'lv' ? base.lv.t : base.v.t;
    if (isMatrix(t) || t.rows === 0)
      throw ctx.error(`${t.rows === 0 ? 'void' : typeName(t)} has no field '.${short(name)}'`);
    const idx = swizzleIndices(ctx, name, t.rows);
    const rt = gtype(t.base, idx.length);
    if (base.kind === 'lv') {
      const dup = new Set(idx).size !== idx.length;
      const readOnly =
        base.lv.readOnly ?? (dup ? `cannot assign to swizzle '.${short(name)}' with repeated components` : undefined);
      return { kind: 'lv', lv: { t: rt, slots: idx.map((i) => base.lv.slots[i]), readOnly, root: base.lv.root } };
    }
    const v = base.v;
    return {
      kind: 'val',
      v: v.k
        ? constValue(
            rt,
            idx.map((i) => (v.k as (number | boolean)[])[i]),
          )
        : { t: rt, c: idx.map((i) => v.c[i]) },
    };
  }
  if (sel.type === 'quantifier' || sel.type === 'array_specifier') {
    if (base.kind === 'arr') {
      const sym = base.sym;
      const iv = indexValue(ctx, sel.expression);
      const n = size(sym.t);
      let index: number | string;
      if (iv.k) index = clampIndexConst(ctx, iv.k[0] as number, sym.length, 'an array');
      else index = clampedIndex(ctx, iv, sym.length);
      const slots: Slot[] = [];
      for (let c = 0; c < n; c++) {
        const ix =
          typeof index === 'number'
            ? lit(index * n + c)
            : n === 1
              ? index
              : c === 0
                ? `${index} * ${n}`
                : `${index} * ${n} + ${c}`;
        slots.push({ kind: 'elem', arr: sym.store, index: ix, base: sym.t.base });
      }
      return { kind: 'lv', lv: { t: sym.t, slots, readOnly: sym.readOnly, root: base.root } };
    }
    if (base.kind === 'val') {
      // Index into a computed value: evaluate the index after it, copying the value if needed.
      const [v, iv] = ctx.sequence([() => base.v, () => indexValue(ctx, sel.expression)]);
      const tmp: LValue = {
        t: v.t,
        slots: v.c.map((c) => ({ kind: 'name', name: ctx.atom(c, v.t.base), base: v.t.base })),
        root: '',
      };
      return { kind: 'val', v: readLValue(indexInto(ctx, tmp, iv)) };
    }
    const iv = indexValue(ctx, sel.expression);
    return { kind: 'lv', lv: indexInto(ctx, base.lv, iv) };
  }
  throw ctx.error('unsupported selector');
}

function identifierRef(ctx: Ctx, name: string): Ref {
  const sym = ctx.lookup(name);
  if (sym === undefined) throw ctx.error(`unknown identifier '${short(name)}'`);
  if (sym.kind === 'array') return { kind: 'arr', sym, root: name };
  if (sym.k !== undefined) return { kind: 'val', v: constValue(sym.t, sym.k) };
  return {
    kind: 'lv',
    lv: {
      t: sym.t,
      slots: sym.names.map((n) => ({ kind: 'name', name: n, base: sym.t.base })),
      readOnly: sym.readOnly,
      root: name,
    },
  };
}

/** A place or value with its selectors applied; `sels` overrides the node's own postfix chain. */
function compileRef(ctx: Ctx, node: Node, depth: number, sels?: Node[]): Ref {
  if (depth > MAX_EXPR_DEPTH) throw ctx.error('expression nested too deeply');
  at(ctx, node);
  if (node.type === 'postfix' && sels === undefined) {
    return compileRef(ctx, node.expression, depth + 1, selectors(node.postfix));
  }
  let base: Ref;
  if (node.type === 'identifier') base = identifierRef(ctx, node.identifier);
  else if (node.type === 'type_specifier' && node.identifier?.type === 'identifier') {
    base = identifierRef(ctx, node.identifier.identifier);
    for (const q of node.quantifier ?? []) base = applySelector(ctx, base, q);
  } else if (node.type === 'group') base = compileRef(ctx, node.expression, depth + 1);
  else base = { kind: 'val', v: compileExpr(ctx, node, depth + 1) };
  for (const s of sels ?? []) base = applySelector(ctx, base, s);
  return base;
}

/** v[i] on a vector (a component) or m[i] on a matrix (a column). */
function indexInto(ctx: Ctx, lv: LValue, iv: Value): LValue {
  const t = lv.t;
  if (isScalar(t) || t.rows === 0) throw ctx.error(`cannot index a ${t.rows === 0 ? 'void' : typeName(t)}`);
  const isMat = isMatrix(t);
  const count = isMat ? t.cols : t.rows;
  const elemT = isMat ? gtype(t.base, t.rows) : gtype(t.base);
  const width = isMat ? t.rows : 1;
  let slots: Slot[];
  if (iv.k) {
    const i = clampIndexConst(ctx, iv.k[0] as number, count, isMat ? 'a matrix' : 'a vector');
    slots = lv.slots.slice(i * width, i * width + width);
  } else {
    const index = clampedIndex(ctx, iv, count);
    slots = [];
    for (let r = 0; r < width; r++) {
      const options: Slot[] = [];
      for (let c = 0; c < count; c++) options.push(lv.slots[c * width + r]);
      slots.push({ kind: 'dyn', index, options, base: t.base });
    }
  }
  return { t: elemT, slots, readOnly: lv.readOnly, root: lv.root };
}

export function compileLValue(ctx: Ctx, node: Node, sels?: Node[]): LValue {
  const r = compileRef(ctx, node, 0, sels);
  if (r.kind === 'lv') return r.lv;
  if (r.kind === 'arr') throw ctx.error('cannot assign whole arrays');
  const root = rootIdentifier(node);
  throw ctx.error(
    root !== undefined && ctx.lookup(root)?.readOnly
      ? (ctx.lookup(root)?.readOnly as string)
      : 'this expression cannot be assigned to',
  );
}

// ── operators ────────────────────────────────────────────────────────────────

const ARITH = new Set(['+', '-', '*', '/', '%', '&', '|', '^', '<<', '>>']);

function one(base: Base): Value {
  return constValue(gtype(base), [1]);
}

function compileIncDec(ctx: Ctx, target: Node, op: '++' | '--', prefix: boolean, sels?: Node[]): Value {
  const lv = compileLValue(ctx, target, sels);
  if (lv.t.base === 'bool') throw ctx.error(`operator ${op} needs a number`);
  const cur = readLValue(lv);
  const old = prefix ? cur : ctx.snapshotValue(cur);
  const next = arith(ctx, op === '++' ? '+' : '-', old, one(lv.t.base));
  assign(ctx, lv, next);
  return prefix ? readLValue(lv) : old;
}

function compileAssignment(ctx: Ctx, node: Node, depth: number): Value {
  const op: string = node.operator.literal;
  const lv = compileLValue(ctx, node.left);
  if (op === '=') {
    const rhs = compileExpr(ctx, node.right, depth + 1);
    assign(ctx, lv, rhs);
    return readLValue(lv);
  }
  const aop = op.slice(0, -1);
  if (!ARITH.has(aop)) throw ctx.error(`unknown operator ${op}`);
  const [cur, rhs] = ctx.sequence([() => readLValue(lv), () => compileExpr(ctx, node.right, depth + 1)]);
  assign(ctx, lv, arith(ctx, aop as ArithOp, cur, rhs));
  return readLValue(lv);
}

function compileLogical(ctx: Ctx, op: '&&' | '||', node: Node, depth: number): Value {
  const left = requireBool(ctx, compileExpr(ctx, node.left, depth + 1), `left side of ${op}`);
  const b = new Buf();
  const right = ctx.into(b, () => requireBool(ctx, compileExpr(ctx, node.right, depth + 1), `right side of ${op}`));
  if (b.lines.length === 0) {
    if (left.k && right.k) return constValue(BOOL, [op === '&&' ? left.k[0] && right.k[0] : left.k[0] || right.k[0]]);
    return { t: BOOL, c: [`(${left.c[0]} ${op} ${right.c[0]})`] };
  }
  const t = ctx.local('t', 'bool');
  ctx.emit(`${t} = ${left.c[0]};`, false);
  ctx.emit(`if (${op === '&&' ? t : `!${t}`}) {`, b.effect);
  ctx.append(b);
  ctx.emit(`${t} = ${right.c[0]};`, false);
  ctx.emit('}', false);
  return { t: BOOL, c: [t] };
}

function compileTernary(ctx: Ctx, node: Node, depth: number): Value {
  const cond = requireBool(ctx, compileExpr(ctx, node.expression, depth + 1), 'condition of ?:');
  const ba = new Buf();
  const bb = new Buf();
  let a = ctx.into(ba, () => compileExpr(ctx, node.left, depth + 1));
  let b = ctx.into(bb, () => compileExpr(ctx, node.right, depth + 1));
  if (isVoid(a) || isVoid(b)) throw ctx.error('?: branches must have values');
  if (a.t.base !== b.t.base) {
    if (implicitlyConvertible(a.t, { ...a.t, base: b.t.base })) a = convert(a, b.t.base);
    else if (implicitlyConvertible(b.t, { ...b.t, base: a.t.base })) b = convert(b, a.t.base);
  }
  if (a.t.base !== b.t.base || a.t.rows !== b.t.rows || a.t.cols !== b.t.cols) {
    throw ctx.error(`?: branches have different types (${typeName(a.t)} and ${typeName(b.t)})`);
  }
  if (ba.lines.length === 0 && bb.lines.length === 0) {
    if (cond.k) return cond.k[0] ? a : b;
    const c = a.c.length > 1 ? ctx.atom(cond.c[0], 'bool') : cond.c[0];
    return { t: a.t, c: a.c.map((x, i) => `(${c} ? ${x} : ${b.c[i]})`) };
  }
  const temps = a.c.map(() => ctx.local('t', a.t.base));
  ctx.emit(`if (${cond.c[0]}) {`, ba.effect || bb.effect);
  ctx.into(ba, () => temps.forEach((t, i) => ctx.emit(`${t} = ${a.c[i]};`, false)));
  ctx.append(ba);
  ctx.emit('} else {', false);
  ctx.into(bb, () => temps.forEach((t, i) => ctx.emit(`${t} = ${b.c[i]};`, false)));
  ctx.append(bb);
  ctx.emit('}', false);
  return { t: a.t, c: temps };
}

function compileBinary(ctx: Ctx, node: Node, depth: number): Value {
  const op: string = node.operator.literal;
  if (op === '&&' || op === '||') return compileLogical(ctx, op, node, depth);
  if (op === ',') {
    const left = compileExpr(ctx, node.left, depth + 1);
    void left;
    return compileExpr(ctx, node.right, depth + 1);
  }
  const [a, b] = ctx.sequence([
    () => compileExpr(ctx, node.left, depth + 1),
    () => compileExpr(ctx, node.right, depth + 1),
  ]);
  if (ARITH.has(op)) return arith(ctx, op as ArithOp, a, b);
  switch (op) {
    case '<':
    case '>':
    case '<=':
    case '>=':
      return compare(ctx, op, a, b);
    case '==':
    case '!=':
      return equality(ctx, op, a, b);
    case '^^':
      return logicalXor(ctx, a, b);
  }
  throw ctx.error(`unknown operator ${short(op)}`);
}

// ── calls ────────────────────────────────────────────────────────────────────

function callArgs(node: Node): Node[] {
  return (node.args ?? []).filter((a: Node) => !(a.type === 'literal' && a.literal === ','));
}

function typeSpecifierType(ctx: Ctx, spec: Node): GType {
  const s = spec.specifier;
  const name: string = s?.token ?? s?.identifier ?? '?';
  if (s?.type === 'struct') throw ctx.error('structs are not supported');
  const t = parseTypeName(name);
  if (t === undefined) throw ctx.error(`unknown or unsupported type '${short(name)}'`);
  return t;
}

function matchCost(fn: FnSym, args: Value[]): number {
  if (fn.params.length !== args.length) return -1;
  let cost = 0;
  for (let i = 0; i < args.length; i++) {
    const p = fn.params[i].t;
    const a = args[i].t;
    if (a.rows === 0) return -1;
    if (a.base === p.base && a.rows === p.rows && a.cols === p.cols) continue;
    if (fn.params[i].q !== 'in') return -1;
    if (!implicitlyConvertible(a, p)) return -1;
    cost++;
  }
  return cost;
}

function compileUserCall(ctx: Ctx, name: string, overloads: FnSym[], argNodes: Node[], depth: number): Value {
  const sameArity = overloads.filter((f) => f.params.length === argNodes.length);
  if (sameArity.length === 0) throw ctx.error(`no version of ${short(name)}() takes ${argNodes.length} argument(s)`);
  const outAt = argNodes.map((_a, i) => sameArity.every((f) => f.params[i].q !== 'in'));
  const lvs: (LValue | undefined)[] = [];
  const args = ctx.sequence(
    argNodes.map((a, i) => () => {
      if (!outAt[i]) {
        lvs[i] = undefined;
        return compileExpr(ctx, a, depth + 1);
      }
      const lv = compileLValue(ctx, a);
      if (lv.readOnly !== undefined) throw ctx.error(`argument ${i + 1} of ${short(name)}(): ${lv.readOnly}`);
      lvs[i] = lv;
      return readLValue(lv);
    }),
  );
  let best: FnSym | undefined;
  let bestCost = Infinity;
  let tie = false;
  for (const f of sameArity) {
    const c = matchCost(f, args);
    if (c < 0) continue;
    if (c < bestCost) {
      best = f;
      bestCost = c;
      tie = false;
    } else if (c === bestCost) tie = true;
  }
  if (best === undefined) {
    throw ctx.error(
      `no version of ${short(name)}() takes (${args.map((a) => (isVoid(a) ? 'void' : typeName(a.t))).join(', ')})`,
    );
  }
  if (tie) throw ctx.error(`call to ${short(name)}() is ambiguous`);
  const fn = best;
  const jsArgs: string[] = [];
  fn.params.forEach((p, i) => {
    if (p.q === 'out') return;
    const v = convert(args[i], p.t.base);
    for (const c of v.c) jsArgs.push(c);
  });
  ctx.noteCall(fn.jsName);
  const call = `${fn.jsName}(${jsArgs.join(', ')})`;
  let result: Value;
  const retSize = fn.ret.rows === 0 ? 0 : size(fn.ret);
  if (retSize === 0) {
    ctx.emit(`${call};`);
    result = { t: VOID_TYPE, c: [] };
  } else if (retSize === 1) {
    const t = ctx.local('t', fn.ret.base);
    ctx.emit(`${t} = ${call};`);
    result = { t: fn.ret, c: [t] };
  } else {
    ctx.emit(`${call};`);
    const c: string[] = [];
    for (let i = 0; i < retSize; i++) {
      const t = ctx.local('t', fn.ret.base);
      ctx.emit(`${t} = ${fn.ret.base === 'bool' ? `(R[${i}] !== 0)` : `R[${i}]`};`, false);
      c.push(t);
    }
    result = { t: fn.ret, c };
  }
  // Copy out/inout results back into the argument places.
  let off = fn.outOffset;
  fn.params.forEach((p, i) => {
    if (p.q === 'in') return;
    const lv = lvs[i];
    if (lv === undefined) throw ctx.error(`argument ${i + 1} of ${short(name)}() must be a variable (out parameter)`);
    const n = size(p.t);
    const comps: string[] = [];
    for (let k = 0; k < n; k++) comps.push(p.t.base === 'bool' ? `(R[${off + k}] !== 0)` : `R[${off + k}]`);
    off += n;
    assign(ctx, lv, { t: p.t, c: comps });
  });
  ctx.rSize = Math.max(ctx.rSize, off, retSize);
  return result;
}

function compileArrayConstructor(ctx: Ctx, _node: Node): Value {
  throw ctx.error('array constructors are only supported as array initialisers');
}

function compileCall(ctx: Ctx, node: Node, depth: number): Value {
  const id = node.identifier;
  const argNodes = callArgs(node);
  if (id.type === 'type_specifier' && id.identifier === undefined && id.specifier?.type === 'keyword') {
    if (id.quantifier && id.quantifier.length > 0) return compileArrayConstructor(ctx, node);
    const t = typeSpecifierType(ctx, id);
    const args = ctx.sequence(argNodes.map((a) => () => compileExpr(ctx, a, depth + 1)));
    return construct(ctx, t, args);
  }
  if (id.type === 'postfix') {
    const sels = selectors(id.postfix);
    const last = sels[sels.length - 1];
    if (last?.type === 'field_selection' && last.selection?.identifier === 'length' && argNodes.length === 0) {
      const base = compileRef(ctx, id.expression, depth + 1, sels.slice(0, -1));
      if (base.kind === 'arr') return constValue(INT, [base.sym.length]);
      const t = base.kind === 'lv' ? base.lv.t : base.v.t;
      if (t.rows > 1) return constValue(INT, [isMatrix(t) ? t.cols : t.rows]);
    }
    throw ctx.error('unsupported method call');
  }
  if (id.type === 'type_specifier' && id.quantifier && id.quantifier.length > 0)
    return compileArrayConstructor(ctx, node);
  const name: string | undefined =
    id.type === 'identifier' ? id.identifier : (id.identifier?.identifier ?? id.specifier?.identifier);
  if (name === undefined) throw ctx.error('unsupported call');
  const user = ctx.functions.get(name);
  if (user !== undefined && user.length > 0) return compileUserCall(ctx, name, user, argNodes, depth);
  const ctorType = parseTypeName(name);
  if (ctorType !== undefined) {
    const args = ctx.sequence(argNodes.map((a) => () => compileExpr(ctx, a, depth + 1)));
    return construct(ctx, ctorType, args);
  }
  if (isUnavailable(name)) throw ctx.error(`${short(name)}() is not available in infill shaders`);
  const args = ctx.sequence(argNodes.map((a) => () => compileExpr(ctx, a, depth + 1)));
  const v = callBuiltin(ctx, name, args, ctx.host);
  if (v !== undefined) return v;
  if (isBuiltinName(name)) throw ctx.error(`${short(name)}() is not available here`);
  throw ctx.error(`unknown function '${short(name)}'`);
}

// ── entry ────────────────────────────────────────────────────────────────────

export function compileExpr(ctx: Ctx, node: Node, depth = 0): Value {
  if (depth > MAX_EXPR_DEPTH) throw ctx.error('expression nested too deeply');
  if (node === null || node === undefined) throw ctx.error('missing expression');
  at(ctx, node);
  switch (node.type) {
    case 'int_constant':
    case 'uint_constant':
      return parseIntToken(ctx, node.token);
    case 'float_constant':
    case 'double_constant':
      return parseFloatToken(ctx, node.token);
    case 'bool_constant':
      return constValue(BOOL, [node.token === 'true']);
    case 'group':
      return compileExpr(ctx, node.expression, depth + 1);
    case 'identifier':
    case 'postfix': {
      if (node.type === 'postfix') {
        const sels = selectors(node.postfix);
        const last = sels[sels.length - 1];
        if (last?.type === 'literal') {
          const op = last.literal;
          if (op === '++' || op === '--') return compileIncDec(ctx, node.expression, op, false, sels.slice(0, -1));
          throw ctx.error(`unknown postfix operator ${short(String(op))}`);
        }
        if (sels.some((x) => x.type === 'literal')) throw ctx.error('unsupported postfix expression');
      }
      const r = compileRef(ctx, node, depth + 1);
      if (r.kind === 'arr') throw ctx.error(`array '${short(r.root)}' must be indexed`);
      return r.kind === 'lv' ? readLValue(r.lv) : r.v;
    }
    case 'type_specifier':
      if (node.identifier?.type === 'identifier') {
        const r = compileRef(ctx, node, depth + 1);
        if (r.kind === 'arr') throw ctx.error(`array '${short(r.root)}' must be indexed`);
        return r.kind === 'lv' ? readLValue(r.lv) : r.v;
      }
      throw ctx.error('a type name cannot be used as a value');
    case 'unary': {
      const op: string = node.operator.literal;
      if (op === '++' || op === '--') return compileIncDec(ctx, node.expression, op, true);
      const v = compileExpr(ctx, node.expression, depth + 1);
      switch (op) {
        case '-':
          return negate(ctx, v);
        case '+':
          if (v.t.base === 'bool' || isVoid(v)) throw ctx.error('operator + needs a number');
          return v;
        case '!':
          return logicalNot(ctx, v);
        case '~':
          return bitNot(ctx, v);
      }
      throw ctx.error(`unknown operator ${short(op)}`);
    }
    case 'binary':
      return compileBinary(ctx, node, depth);
    case 'assignment':
      return compileAssignment(ctx, node, depth);
    case 'ternary':
      return compileTernary(ctx, node, depth);
    case 'function_call':
      return compileCall(ctx, node, depth);
    case 'field_selection':
    case 'quantifier':
      throw ctx.error('unexpected selector');
  }
  throw ctx.error(`unsupported expression (${short(String(node.type))})`);
}

/** An expression whose value is not used (statements, for-loop updates): `i++` compiles as `++i`. */
export function compileDiscarded(ctx: Ctx, node: Node): void {
  if (node?.type === 'postfix') {
    const sels = selectors(node.postfix);
    const last = sels[sels.length - 1];
    if (last?.type === 'literal' && (last.literal === '++' || last.literal === '--')) {
      at(ctx, node);
      compileIncDec(ctx, node.expression, last.literal, true, sels.slice(0, -1));
      return;
    }
  }
  if (node?.type === 'binary' && node.operator?.literal === ',') {
    compileDiscarded(ctx, node.left);
    compileDiscarded(ctx, node.right);
    return;
  }
  compileExpr(ctx, node);
}

/** A condition: bool scalar expression; returns the JS expression. */
export function compileCondition(ctx: Ctx, node: Node, what: string): Value {
  return requireBool(ctx, compileExpr(ctx, node), what);
}

/** Compile an initialiser for a variable of type t (implicit conversion). */
export function compileInitializer(ctx: Ctx, node: Node, t: GType): Value {
  const v = compileExpr(ctx, node);
  if (isVoid(v)) throw ctx.error('initialiser has no value');
  if (v.t.base === t.base && v.t.rows === t.rows && v.t.cols === t.cols) return v;
  if (!implicitlyConvertible(v.t, t)) throw ctx.error(`cannot initialise ${typeName(t)} with ${typeName(v.t)}`);
  return convert(v, t.base);
}

export { typeSpecifierType, callArgs, rootIdentifier };
