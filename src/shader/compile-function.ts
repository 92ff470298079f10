/**
 * GLSL functions → JS functions: signatures and overloads, parameters (in / out / inout, the latter
 * returned through the register R), bodies with a call-budget check, and the no-recursion rule.
 */
import type { GType } from './glsl-types.js';
import { parseTypeName, size } from './glsl-types.js';
import type { Ctx, FnParam, FnSym, ParamQualifier, VarSym } from './compiler-context.js';
import { Buf, newFnCtx, short } from './compiler-context.js';
import { nodeLine, typeSpecifierType } from './compile-expr.js';
import { compileStatement } from './compile-stmt.js';

// biome-ignore lint/suspicious/noExplicitAny: the GLSL parser's AST nodes are untyped
type Node = any;

export function qualifiers(node: Node): string[] {
  const q = node?.qualifiers ?? node?.qualifier ?? [];
  return q.map((k: Node) => (k.type === 'keyword' ? String(k.token) : String(k.type)));
}

export function paramsOf(ctx: Ctx, proto: Node): { params: FnParam[]; names: (string | undefined)[] } {
  const params: FnParam[] = [];
  const names: (string | undefined)[] = [];
  for (const p of proto.parameters ?? []) {
    const spec = p.specifier;
    const tName: string = spec?.specifier?.token ?? spec?.specifier?.identifier ?? '?';
    if (tName === 'void' && (proto.parameters ?? []).length === 1 && !p.identifier) break;
    const t = typeSpecifierType(ctx, spec);
    if ((spec.quantifier && spec.quantifier.length) || (p.quantifier && p.quantifier.length))
      throw ctx.error('array parameters are not supported');
    const qs = qualifiers(p);
    const q: ParamQualifier = qs.includes('inout') ? 'inout' : qs.includes('out') ? 'out' : 'in';
    params.push({ t, q });
    names.push(p.identifier?.identifier);
  }
  return { params, names };
}

function returnType(ctx: Ctx, proto: Node): GType {
  const spec = proto.header.returnType.specifier;
  const name: string = spec?.specifier?.token ?? spec?.specifier?.identifier ?? '?';
  if (name === 'void') return { base: 'float', rows: 0, cols: 0 };
  if (spec.quantifier && spec.quantifier.length) throw ctx.error('functions cannot return arrays');
  return typeSpecifierType(ctx, spec);
}

function sameParams(a: FnParam[], b: FnParam[]): boolean {
  return (
    a.length === b.length &&
    a.every((p, i) => p.t.base === b[i].t.base && p.t.rows === b[i].t.rows && p.t.cols === b[i].t.cols)
  );
}

export function registerFunction(ctx: Ctx, proto: Node, isDefinition: boolean): FnSym {
  ctx.line = nodeLine(proto) ?? ctx.line;
  const name: string = proto.header.name.identifier;
  if (parseTypeName(name) !== undefined) throw ctx.error(`'${short(name)}' is a type name`);
  const ret = returnType(ctx, proto);
  const { params } = paramsOf(ctx, proto);
  let list = ctx.functions.get(name);
  if (list === undefined) ctx.functions.set(name, (list = []));
  const existing = list.find((f) => sameParams(f.params, params));
  if (existing !== undefined) {
    if (existing.ret.rows !== ret.rows || existing.ret.base !== ret.base || existing.ret.cols !== ret.cols) {
      throw ctx.error(`${short(name)}() is declared with two return types`);
    }
    if (isDefinition) {
      if (existing.defined) throw ctx.error(`${short(name)}() is defined twice`);
      existing.defined = true;
      existing.line = ctx.line;
    }
    return existing;
  }
  const fn: FnSym = {
    glslName: name,
    jsName: ctx.id('f'),
    ret,
    params,
    defined: isDefinition,
    line: ctx.line,
    outOffset: ret.rows === 0 ? 0 : size(ret),
  };
  list.push(fn);
  return fn;
}

export function zeroOf(base: string): string {
  return base === 'bool' ? 'false' : '0';
}

export function compileFunction(ctx: Ctx, node: Node, fn: FnSym, isEntry: boolean): string {
  const fctx = newFnCtx(fn, fn.ret, false);
  fctx.isEntry = isEntry;
  const savedFn = ctx.fn;
  const savedBuf = ctx.buf;
  ctx.fn = fctx;
  ctx.buf = new Buf();
  ctx.pushScope();
  try {
    const { names } = paramsOf(ctx, node.prototype);
    const jsParams: string[] = [];
    fn.params.forEach((p, i) => {
      const comps: string[] = [];
      for (let k = 0; k < size(p.t); k++) {
        if (p.q === 'out') comps.push(ctx.local('v', p.t.base));
        else {
          const n = ctx.id('v');
          comps.push(n);
          jsParams.push(n);
        }
      }
      if (p.q !== 'in') fctx.outNames.push({ names: comps, base: p.t.base });
      const pname = names[i];
      if (pname !== undefined) {
        const sym: VarSym = { kind: 'var', t: p.t, names: comps, global: false };
        ctx.declare(pname, sym);
      }
    });
    let outSize = 0;
    for (const o of fctx.outNames) outSize += o.names.length;
    ctx.rSize = Math.max(ctx.rSize, fn.outOffset + outSize);
    ctx.line = fn.line;
    ctx.emit(`if (--B < 0) m_clim(${fn.line | 0});`);
    ctx.pushScope();
    for (const s of node.body.statements ?? []) compileStatement(ctx, s, 1);
    ctx.popScope();
    // Falling off the end: void returns; others return zeros (GLSL leaves this undefined).
    const stmts = node.body.statements ?? [];
    const endsWithReturn = stmts.length > 0 && stmts[stmts.length - 1].type === 'return_statement';
    if (endsWithReturn) {
      // Nothing to add.
    } else if (fn.ret.rows === 0) {
      let off = fn.outOffset;
      for (const o of fctx.outNames) for (const n of o.names) ctx.emit(`R[${off++}] = ${n};`);
    } else if (size(fn.ret) === 1) {
      let off = fn.outOffset;
      for (const o of fctx.outNames) for (const n of o.names) ctx.emit(`R[${off++}] = ${n};`);
      ctx.emit(`return ${zeroOf(fn.ret.base)};`);
    } else {
      for (let i = 0; i < size(fn.ret); i++) ctx.emit(`R[${i}] = 0;`);
      let off = fn.outOffset;
      for (const o of fctx.outNames) for (const n of o.names) ctx.emit(`R[${off++}] = ${n};`);
    }
    return wrapFunction(fn.jsName, jsParams, fctx.locals, ctx.buf.lines);
  } finally {
    ctx.popScope();
    ctx.fn = savedFn;
    ctx.buf = savedBuf;
  }
}

export function wrapFunction(
  name: string,
  params: string[],
  locals: { name: string; base: string }[],
  lines: string[],
): string {
  const decl = locals.length > 0 ? `let ${locals.map((l) => `${l.name} = ${zeroOf(l.base)}`).join(', ')};\n` : '';
  return `function ${name}(${params.join(', ')}) {\n${decl}${lines.join('\n')}\n}`;
}

export function checkRecursion(ctx: Ctx): void {
  const byJs = new Map<string, FnSym>();
  for (const list of ctx.functions.values()) for (const f of list) byJs.set(f.jsName, f);
  const state = new Map<string, number>(); // 1 = on stack, 2 = done
  const visit = (f: string, path: string[]): void => {
    state.set(f, 1);
    for (const g of ctx.calls.get(f) ?? []) {
      const s = state.get(g);
      if (s === 1) {
        const fn = byJs.get(g);
        throw ctx.error(`recursion is not allowed in GLSL (${short(fn?.glslName ?? '?')}() calls itself)`, fn?.line);
      }
      if (s === undefined) visit(g, [...path, g]);
    }
    state.set(f, 2);
  };
  for (const f of ctx.calls.keys()) if (!state.has(f)) visit(f, [f]);
}
