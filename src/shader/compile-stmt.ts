/**
 * GLSL statements → JS: blocks, declarations (scalars, vectors, matrices, arrays), if, for, while,
 * do-while, switch, break/continue/return/discard. Every loop iteration decrements the evaluation
 * budget `B` and stops the shader with LIMIT_EXCEEDED when it runs out.
 */
import type { GType } from './glsl-types.js';
import { size, typeName } from './glsl-types.js';
import type { ArraySym, Ctx, Value, VarSym } from './compiler-context.js';
import { isVoid, short } from './compiler-context.js';
import {
  callArgs,
  compileCondition,
  compileDiscarded,
  compileExpr,
  compileInitializer,
  nodeLine,
  typeSpecifierType,
} from './compile-expr.js';
import { convert, lit } from './values.js';
import { implicitlyConvertible } from './glsl-types.js';

// biome-ignore lint/suspicious/noExplicitAny: the GLSL parser's AST nodes are untyped
type Node = any;

/** Largest number of array elements one shader may allocate. */
export const MAX_ARRAY_ELEMENTS = 65536;
const MAX_STMT_DEPTH = 200;

function at(ctx: Ctx, node: Node): void {
  const l = nodeLine(node);
  if (l !== undefined) ctx.line = l;
}

function qualifierTokens(specifiedType: Node): string[] {
  const q = specifiedType?.qualifiers ?? [];
  return q.map((k: Node) => (k.type === 'keyword' ? String(k.token) : k.type)).filter((s: string) => s !== undefined);
}

/** Constant integer value of an array size expression. */
export function constInt(ctx: Ctx, node: Node): number {
  const v = compileExpr(ctx, node);
  if (!v.k || v.t.rows !== 1 || v.t.cols !== 1 || (v.t.base !== 'int' && v.t.base !== 'uint')) {
    throw ctx.error('array size must be a constant integer');
  }
  return v.k[0] as number;
}

/** Array length from `float a[N]` / `float[N] a`, or undefined for non-arrays; 0 means unsized (`a[]`). */
export function arrayLength(
  ctx: Ctx,
  typeQuantifier: Node[] | null,
  declQuantifier: Node[] | null,
): number | undefined {
  const q = [...(typeQuantifier ?? []), ...(declQuantifier ?? [])];
  if (q.length === 0) return undefined;
  if (q.length > 1) throw ctx.error('arrays of arrays are not supported');
  const e = q[0].expression;
  if (e === null || e === undefined) return 0;
  const n = constInt(ctx, e);
  if (n <= 0) throw ctx.error('array size must be positive');
  return n;
}

/** Elements of an array initialiser: `float[3](a, b, c)`, `float[](…)` or `{a, b, c}`. */
function arrayInitElements(ctx: Ctx, node: Node): Node[] {
  if (node.type === 'initializer_list') return node.initializers ?? [];
  if (node.type === 'function_call' && node.identifier?.type === 'type_specifier' && node.identifier.quantifier?.length)
    return callArgs(node);
  throw ctx.error('an array must be initialised with an array constructor');
}

/** Allocate closure storage for an array and declare the symbol; emits its initialisation. */
export function declareArray(
  ctx: Ctx,
  name: string,
  elem: GType,
  declared: number,
  init: Node | undefined,
  readOnly: string | undefined,
  global: boolean,
): ArraySym {
  const elems = init !== undefined ? arrayInitElements(ctx, init) : undefined;
  const length = declared === 0 ? (elems?.length ?? 0) : declared;
  if (length <= 0) throw ctx.error(`array '${short(name)}' needs a size`);
  if (elems !== undefined && elems.length !== length)
    throw ctx.error(`array '${short(name)}' has ${length} elements but ${elems.length} initialisers`);
  const total = length * size(elem);
  ctx.arrayElements += total;
  if (ctx.arrayElements > MAX_ARRAY_ELEMENTS)
    throw ctx.error(`arrays are too large (more than ${MAX_ARRAY_ELEMENTS} elements in total)`);
  const store = ctx.id('a');
  ctx.closureDecls.push(`const ${store} = new m_F64(${total});`);
  const sym: ArraySym = { kind: 'array', t: elem, length, store, readOnly, global };
  initArray(ctx, sym, init);
  ctx.declare(name, sym);
  return sym;
}

/** Emit the initialisation of an array's storage (its initialiser, or zeros). */
export function initArray(ctx: Ctx, sym: ArraySym, init: Node | undefined): void {
  const n = size(sym.t);
  if (init !== undefined) {
    const elems = arrayInitElements(ctx, init);
    const vals = ctx.sequence(elems.map((e) => () => compileInitializer(ctx, e, sym.t)));
    vals.forEach((v, i) => v.c.forEach((c, k) => ctx.emit(`${sym.store}[${i * n + k}] = ${c};`)));
  } else {
    const i = ctx.local('t', 'int');
    ctx.emit(`for (${i} = 0; ${i} < ${sym.length * n}; ${i}++) ${sym.store}[${i}] = 0;`);
  }
}

/** Declare a scalar/vector/matrix local variable, with optional initialiser. */
export function declareLocalVar(ctx: Ctx, name: string, t: GType, init: Node | undefined, isConst: boolean): VarSym {
  let value: Value | undefined;
  if (init !== undefined) value = compileInitializer(ctx, init, t);
  else if (isConst) throw ctx.error(`const '${short(name)}' needs an initialiser`);
  const readOnly = isConst ? `cannot assign to const '${short(name)}'` : undefined;
  if (isConst && value?.k) {
    const sym: VarSym = { kind: 'var', t, names: [], k: value.k, readOnly, global: false };
    ctx.declare(name, sym);
    return sym;
  }
  const names: string[] = [];
  for (let i = 0; i < size(t); i++) names.push(ctx.local('v', t.base));
  if (value !== undefined) {
    const v = value;
    names.forEach((n, i) => ctx.emit(`${n} = ${v.c[i]};`));
  } else {
    const zero = t.base === 'bool' ? 'false' : '0';
    for (const n of names) ctx.emit(`${n} = ${zero};`);
  }
  const sym: VarSym = { kind: 'var', t, names, readOnly, global: false };
  ctx.declare(name, sym);
  return sym;
}

function compileDeclaratorList(ctx: Ctx, decl: Node): void {
  const spec = decl.specified_type?.specifier;
  if (spec?.specifier?.type === 'type_name' && (decl.declarations ?? []).length === 0) {
    // `x;` parsed as a declaration of type x with no names: a no-op expression statement.
    const name: string = spec.specifier.identifier;
    if (ctx.lookup(name) === undefined) throw ctx.error(`unknown identifier '${short(name)}'`);
    return;
  }
  const quals = qualifierTokens(decl.specified_type);
  const isConst = quals.includes('const');
  for (const q of quals) {
    if (q === 'uniform' || q === 'in' || q === 'out' || q === 'inout' || q === 'attribute' || q === 'varying') {
      throw ctx.error(`'${q}' is not allowed on a local variable`);
    }
  }
  const t = typeSpecifierType(ctx, spec);
  for (const d of decl.declarations ?? []) {
    at(ctx, d);
    const name: string = d.identifier.identifier;
    const len = arrayLength(ctx, spec.quantifier, d.quantifier);
    if (len !== undefined)
      declareArray(
        ctx,
        name,
        t,
        len,
        d.initializer ?? undefined,
        isConst ? `cannot assign to const array '${short(name)}'` : undefined,
        false,
      );
    else declareLocalVar(ctx, name, t, d.initializer ?? undefined, isConst);
  }
}

function budgetCheck(ctx: Ctx): string {
  return `if (--B < 0) m_lim(${ctx.line | 0});`;
}

function compileBody(ctx: Ctx, node: Node, depth: number): void {
  // A loop/if body that is a block gets its own scope; a single statement too (GLSL rules).
  ctx.pushScope();
  try {
    compileStatement(ctx, node, depth + 1);
  } finally {
    ctx.popScope();
  }
}

/** Emit `if (!cond) break;` with the condition's own statements before it. */
function emitLoopCondition(ctx: Ctx, cond: Node): void {
  if (cond === null || cond === undefined) return;
  if (cond.type === 'condition_expression') throw ctx.error('declarations in loop conditions are not supported');
  const c = compileCondition(ctx, cond, 'loop condition');
  if (c.k) {
    if (!c.k[0]) ctx.emit('break;');
    return;
  }
  ctx.emit(`if (!${c.c[0]}) break;`);
}

function compileFor(ctx: Ctx, node: Node, depth: number): void {
  ctx.pushScope();
  try {
    const init = node.init;
    if (init !== null && init !== undefined) {
      if (init.type === 'declarator_list') compileDeclaratorList(ctx, init);
      else if (init.type === 'declaration_statement') compileStatement(ctx, init, depth + 1);
      else if (init.type === 'expression_statement') {
        if (init.expression) compileDiscarded(ctx, init.expression);
      } else compileDiscarded(ctx, init);
    }
    const label = ctx.id('L');
    const inner = ctx.id('L');
    const line = ctx.line;
    ctx.emit(`${label}: for (;;) {`);
    ctx.line = line;
    ctx.emit(budgetCheck(ctx));
    emitLoopCondition(ctx, node.condition);
    ctx.emit(`${inner}: {`);
    ctx.fn.loops.push({ cont: `break ${inner};` });
    compileBody(ctx, node.body, depth);
    ctx.fn.loops.pop();
    ctx.emit('}');
    if (node.operation !== null && node.operation !== undefined) compileDiscarded(ctx, node.operation);
    ctx.emit('}');
  } finally {
    ctx.popScope();
  }
}

function compileWhile(ctx: Ctx, node: Node, depth: number): void {
  const label = ctx.id('L');
  ctx.emit(`${label}: for (;;) {`);
  ctx.emit(budgetCheck(ctx));
  emitLoopCondition(ctx, node.condition);
  ctx.fn.loops.push({ cont: `continue ${label};` });
  compileBody(ctx, node.body, depth);
  ctx.fn.loops.pop();
  ctx.emit('}');
}

function compileDo(ctx: Ctx, node: Node, depth: number): void {
  const label = ctx.id('L');
  const inner = ctx.id('L');
  ctx.emit(`${label}: for (;;) {`);
  ctx.emit(budgetCheck(ctx));
  ctx.emit(`${inner}: {`);
  ctx.fn.loops.push({ cont: `break ${inner};` });
  compileBody(ctx, node.body, depth);
  ctx.fn.loops.pop();
  ctx.emit('}');
  emitLoopCondition(ctx, node.expression);
  ctx.emit('}');
}

function compileSwitch(ctx: Ctx, node: Node, depth: number): void {
  const v = compileExpr(ctx, node.expression);
  if (isVoid(v) || v.t.rows !== 1 || v.t.cols !== 1 || (v.t.base !== 'int' && v.t.base !== 'uint')) {
    throw ctx.error('switch needs an int expression');
  }
  ctx.emit(`switch (${v.c[0]}) {`);
  ctx.fn.breakables++;
  ctx.pushScope();
  const seen = new Set<number>();
  for (const c of node.cases ?? []) {
    at(ctx, c);
    if (c.type === 'default_case') ctx.emit('default:');
    else {
      const k = compileExpr(ctx, c.test);
      if (!k.k || k.t.rows !== 1 || k.t.base === 'float' || k.t.base === 'bool')
        throw ctx.error('case label must be a constant integer');
      const n = k.k[0] as number;
      if (seen.has(n)) throw ctx.error(`duplicate case ${n}`);
      seen.add(n);
      ctx.emit(`case ${lit(n)}:`);
    }
    for (const s of c.statements ?? []) compileStatement(ctx, s, depth + 1);
  }
  ctx.popScope();
  ctx.fn.breakables--;
  ctx.emit('}');
}

/** Write out/inout parameters to the return register. */
function emitOuts(ctx: Ctx): void {
  let off = ctx.fn.fn?.outOffset ?? 0;
  for (const o of ctx.fn.outNames) {
    for (const n of o.names) ctx.emit(`R[${off++}] = ${n};`);
  }
}

export function emitReturn(ctx: Ctx, value: Value | undefined): void {
  const ret = ctx.fn.ret;
  if (ctx.fn.isInit) throw ctx.error('return outside a function');
  if (ret.rows === 0) {
    if (value !== undefined && !isVoid(value)) throw ctx.error('a void function cannot return a value');
    emitOuts(ctx);
    ctx.emit('return;');
    return;
  }
  if (value === undefined || isVoid(value)) throw ctx.error(`this function must return a ${typeName(ret)}`);
  let v = value;
  if (v.t.base !== ret.base || v.t.rows !== ret.rows || v.t.cols !== ret.cols) {
    if (!implicitlyConvertible(v.t, ret))
      throw ctx.error(`cannot return ${typeName(v.t)} from a function returning ${typeName(ret)}`);
    v = convert(v, ret.base);
  }
  if (v.c.length === 1) {
    emitOuts(ctx);
    ctx.emit(`return ${v.c[0]};`);
    return;
  }
  v.c.forEach((c, i) => ctx.emit(`R[${i}] = ${c};`));
  emitOuts(ctx);
  ctx.emit('return;');
}

export function compileStatement(ctx: Ctx, node: Node, depth = 0): void {
  if (depth > MAX_STMT_DEPTH) throw ctx.error('statements nested too deeply');
  if (node === null || node === undefined) return;
  at(ctx, node);
  switch (node.type) {
    case 'compound_statement':
      ctx.pushScope();
      try {
        for (const s of node.statements ?? []) compileStatement(ctx, s, depth + 1);
      } finally {
        ctx.popScope();
      }
      return;
    case 'expression_statement':
      if (node.expression !== null && node.expression !== undefined) compileDiscarded(ctx, node.expression);
      return;
    case 'declaration_statement': {
      const d = node.declaration;
      if (d.type === 'precision') return;
      if (d.type === 'declarator_list') return compileDeclaratorList(ctx, d);
      if (d.type === 'function_prototype') throw ctx.error('functions cannot be declared inside functions');
      throw ctx.error(`unsupported declaration (${short(String(d.type))})`);
    }
    case 'declarator_list':
      return compileDeclaratorList(ctx, node);
    case 'if_statement': {
      const c = compileCondition(ctx, node.condition, 'if condition');
      ctx.emit(`if (${c.c[0]}) {`);
      compileBody(ctx, node.body, depth);
      const elseParts = (node.else ?? []).filter((e: Node) => !(e.type === 'keyword' && e.token === 'else'));
      if (elseParts.length > 0) {
        ctx.emit('} else {');
        for (const e of elseParts) compileBody(ctx, e, depth);
      }
      ctx.emit('}');
      return;
    }
    case 'for_statement':
      return compileFor(ctx, node, depth);
    case 'while_statement':
      return compileWhile(ctx, node, depth);
    case 'do_statement':
      return compileDo(ctx, node, depth);
    case 'switch_statement':
      return compileSwitch(ctx, node, depth);
    case 'break_statement':
      if (ctx.fn.loops.length === 0 && ctx.fn.breakables === 0) throw ctx.error('break outside a loop or switch');
      ctx.emit('break;');
      return;
    case 'continue_statement': {
      const loop = ctx.fn.loops[ctx.fn.loops.length - 1];
      if (loop === undefined) throw ctx.error('continue outside a loop');
      ctx.emit(loop.cont);
      return;
    }
    case 'return_statement':
      emitReturn(ctx, node.expression ? compileExpr(ctx, node.expression) : undefined);
      return;
    case 'discard_statement':
      if (!ctx.fn.isEntry) throw ctx.error('discard is only allowed in the entry function');
      emitReturn(ctx, { t: ctx.fn.ret, c: new Array<string>(size(ctx.fn.ret)).fill('0') });
      return;
    case 'function':
      throw ctx.error('functions cannot be defined inside functions');
    case 'preprocessor':
      throw ctx.error('unexpected preprocessor directive');
  }
  throw ctx.error(`unsupported statement (${short(String(node.type))})`);
}
