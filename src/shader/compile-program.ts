/**
 * Whole-program GLSL → JS: globals, uniforms (`u_Pass`, `ui_*`), functions (overloads, in/out/inout
 * parameters, no recursion), the entry point, and assembly of the factory body. The produced source
 * names only its own generated identifiers and the math table `M` (its single parameter).
 */
import type { GType } from './glsl-types.js';
import { size, typeName } from './glsl-types.js';
import type { Ctx, FnCtx, FnSym, Value, VarSym } from './compiler-context.js';
import { Buf, newFnCtx, short } from './compiler-context.js';
import { compileInitializer, nodeLine, rootIdentifier, typeSpecifierType } from './compile-expr.js';
import { arrayLength, declareArray, initArray } from './compile-stmt.js';
import {
  checkRecursion,
  compileFunction,
  qualifiers,
  registerFunction,
  wrapFunction,
  zeroOf,
} from './compile-function.js';
import type { UiParamDecl } from './preprocess.js';
import { TABLE_KEYS } from './math-table.js';
import { lit } from './values.js';

// biome-ignore lint/suspicious/noExplicitAny: the GLSL parser's AST nodes are untyped
type Node = any;

export type UniformKind = 'pass' | 'param' | 'other';

const HOST_FUNCTIONS = new Set(['density', 'nozzle_diameter', 'layer_height']);

export interface UniformSlot {
  name: string;
  kind: UniformKind;
  type: GType;
  /** Default component values. */
  defaults: (number | boolean)[];
}

export type EntryKind = 'cellular' | 'density';

export interface ProgramOptions {
  entry: EntryKind;
  evalBudget: number;
  layerBudget: number;
  uiParams: readonly UiParamDecl[];
}

export interface CompiledProgram {
  /** Body of `new Function('M', body)`. */
  body: string;
  uniforms: UniformSlot[];
  /** numPasses when known at compile time; undefined when it depends on uniforms. */
  numPassesConst: number | undefined;
  hasNumPasses: boolean;
  usesDensity: boolean;
}

/** Names assigned anywhere (conservatively: also every root passed to a function with out params). */
function writtenNames(program: Node[], outFns: ReadonlySet<string>): Set<string> {
  const out = new Set<string>();
  const stack: unknown[] = [...program];
  let steps = 0;
  while (stack.length > 0) {
    if (++steps > 5_000_000) break;
    const n = stack.pop() as Node;
    if (n === null || typeof n !== 'object') continue;
    if (Array.isArray(n)) {
      for (const x of n) stack.push(x);
      continue;
    }
    const add = (e: Node) => {
      const r = rootIdentifier(e);
      if (r !== undefined) out.add(r);
    };
    if (n.type === 'assignment') add(n.left);
    else if (
      (n.type === 'unary' || n.type === 'postfix') &&
      (n.operator?.literal === '++' ||
        n.operator?.literal === '--' ||
        n.postfix?.literal === '++' ||
        n.postfix?.literal === '--')
    ) {
      add(n.expression);
    } else if (
      n.type === 'function_call' &&
      n.identifier?.type === 'identifier' &&
      outFns.has(n.identifier.identifier)
    ) {
      for (const a of n.args ?? []) add(a);
    }
    for (const k of Object.keys(n)) {
      if (k === 'location' || k === 'whitespace') continue;
      const v = n[k];
      if (v !== null && typeof v === 'object') stack.push(v);
    }
  }
  return out;
}

/** Register every function's signature (so call order in the source does not matter); returns them by node. */
function registerFunctions(ctx: Ctx, program: Node[]): Map<Node, FnSym> {
  const fnByNode = new Map<Node, FnSym>();
  for (const st of program) {
    if (st.type === 'function') fnByNode.set(st, registerFunction(ctx, st.prototype, true));
    else if (st.type === 'declaration_statement' && st.declaration?.type === 'function_prototype') {
      // A prototype of a host built-in (`float density(vec3 p);`) only declares what the host provides.
      if (HOST_FUNCTIONS.has(st.declaration.header?.name?.identifier)) continue;
      registerFunction(ctx, st.declaration, false);
    }
  }
  return fnByNode;
}

/** Names of the functions with an out or inout parameter. */
function outParamFunctions(ctx: Ctx): Set<string> {
  const outFns = new Set<string>();
  for (const [name, list] of ctx.functions) if (list.some((f) => f.params.some((p) => p.q !== 'in'))) outFns.add(name);
  return outFns;
}

/** What the top-level declarations build: uniforms, globals, their initialisers, and numPasses. */
interface Globals {
  /** Names assigned anywhere (writtenNames). */
  readonly written: ReadonlySet<string>;
  readonly uiByName: ReadonlyMap<string, UiParamDecl>;
  readonly uniforms: UniformSlot[];
  /** The JS names of each uniform's components. */
  readonly uniformNames: string[][];
  /** `let` declarations of the uniforms and globals. */
  readonly globalDecls: string[];
  /** Initialisers run once per configure() (I1). */
  readonly onceCtx: FnCtx;
  readonly onceBuf: Buf;
  /** Initialisers of written globals, run again before each evaluation (I2). */
  readonly eachCtx: FnCtx;
  readonly eachBuf: Buf;
  hasEach: boolean;
  numPassesSym: VarSym | undefined;
  numPassesDeclared: boolean;
}

/** An empty set of globals. */
function newGlobals(written: ReadonlySet<string>, uiParams: readonly UiParamDecl[]): Globals {
  const uiByName = new Map<string, UiParamDecl>();
  for (const p of uiParams) uiByName.set(p.name, p);
  return {
    written,
    uiByName,
    uniforms: [],
    uniformNames: [],
    globalDecls: [],
    onceCtx: newFnCtx(undefined, { base: 'float', rows: 0, cols: 0 }, true),
    eachCtx: newFnCtx(undefined, { base: 'float', rows: 0, cols: 0 }, true),
    onceBuf: new Buf(),
    eachBuf: new Buf(),
    hasEach: false,
    numPassesSym: undefined,
    numPassesDeclared: false,
  };
}

/** Run `f` with `fc` and `buf` as the current function and output (an initialiser's). */
function inGlobal<T>(ctx: Ctx, fc: FnCtx, buf: Buf, f: () => T): T {
  const savedFn = ctx.fn;
  const savedBuf = ctx.buf;
  ctx.fn = fc;
  ctx.buf = buf;
  try {
    return f();
  } finally {
    ctx.fn = savedFn;
    ctx.buf = savedBuf;
  }
}

/** Compile the top-level statements in order: functions (into `functionsJs`) and global declarations. */
function compileTopLevel(
  ctx: Ctx,
  program: Node[],
  fnByNode: ReadonlyMap<Node, FnSym>,
  g: Globals,
  entry: EntryKind,
  functionsJs: string[],
): FnSym | undefined {
  let entryFn: FnSym | undefined;
  for (const st of program) {
    ctx.line = nodeLine(st) ?? ctx.line;
    if (st.type === 'preprocessor') continue;
    if (st.type === 'function') {
      const fn = fnByNode.get(st) as FnSym;
      const isEntry = fn.glslName === entry;
      if (isEntry) {
        if (entryFn !== undefined) throw ctx.error(`${entry}() is defined twice`);
        entryFn = fn;
      }
      functionsJs.push(compileFunction(ctx, st, fn, isEntry));
      continue;
    }
    if (st.type !== 'declaration_statement')
      throw ctx.error(`unsupported top-level statement (${short(String(st.type))})`);
    declareGlobals(ctx, st.declaration, g);
  }
  return entryFn;
}

/** One top-level declaration: each of its names becomes a global array, a uniform or a global. */
function declareGlobals(ctx: Ctx, d: Node, g: Globals): void {
  if (d.type === 'precision' || d.type === 'function_prototype') return;
  if (d.type === 'qualifier_declarator') return; // `invariant x;` and the like
  if (d.type === 'interface_declarator') throw ctx.error('interface blocks are not supported');
  if (d.type !== 'declarator_list') throw ctx.error(`unsupported declaration (${short(String(d.type))})`);
  const spec = d.specified_type.specifier;
  if (spec?.specifier?.type === 'struct') throw ctx.error('structs are not supported');
  const quals = qualifiers(d.specified_type);
  const t = typeSpecifierType(ctx, spec);
  for (const decl of d.declarations ?? []) {
    ctx.line = nodeLine(decl) ?? ctx.line;
    const name: string = decl.identifier.identifier;
    const init: Node | undefined = decl.initializer ?? undefined;
    const len = arrayLength(ctx, spec.quantifier, decl.quantifier);
    const isUniform = quals.includes('uniform');
    const isConst = quals.includes('const');
    if (
      quals.includes('in') ||
      quals.includes('out') ||
      quals.includes('varying') ||
      quals.includes('attribute') ||
      quals.includes('buffer')
    ) {
      ctx.warnings.push(
        `${ctx.fileName} line ${ctx.line}: '${short(name)}' is a shader input/output; it is treated as a plain global`,
      );
    }
    if (len !== undefined) {
      if (isUniform) throw ctx.error('uniform arrays are not supported');
      const readOnly = isConst ? `cannot assign to const array '${short(name)}'` : undefined;
      const sym = inGlobal(ctx, g.onceCtx, g.onceBuf, () => declareArray(ctx, name, t, len, init, readOnly, true));
      if (g.written.has(name)) {
        g.hasEach = true;
        inGlobal(ctx, g.eachCtx, g.eachBuf, () => initArray(ctx, sym, init));
      }
      continue;
    }
    if (name === 'u_Pass' || isUniform) declareUniform(ctx, name, t, init, g);
    else declareGlobal(ctx, name, t, init, isConst, g);
  }
}

/** A uniform: u_Pass, a ui_ parameter, or anything else (its initialiser or zero). */
function declareUniform(ctx: Ctx, name: string, t: GType, init: Node | undefined, g: Globals): void {
  const ui = g.uiByName.get(name);
  const kind: UniformKind = name === 'u_Pass' ? 'pass' : ui !== undefined ? 'param' : 'other';
  if (kind === 'pass' && (t.base !== 'int' || size(t) !== 1)) throw ctx.error('u_Pass must be an int');
  let defaults: (number | boolean)[] = new Array<number | boolean>(size(t)).fill(t.base === 'bool' ? false : 0);
  if (ui !== undefined) defaults = [ui.defaultValue];
  else if (init !== undefined && kind === 'other') {
    const v = inGlobal(ctx, g.onceCtx, g.onceBuf, () => compileInitializer(ctx, init, t));
    if (!v.k) throw ctx.error(`uniform '${short(name)}' needs a constant initialiser`);
    defaults = v.k;
  } else if (kind === 'other') {
    ctx.warnings.push(
      `${ctx.fileName} line ${ctx.line}: uniform '${short(name)}' is not provided by Strata; it is ${typeName(t)}(0)`,
    );
  }
  const names: string[] = [];
  for (let i = 0; i < size(t); i++) names.push(ctx.id('u'));
  g.uniforms.push({ name, kind, type: t, defaults });
  g.uniformNames.push(names);
  g.globalDecls.push(`let ${names.map((n, i) => `${n} = ${lit(defaults[i])}`).join(', ')};`);
  const usym: VarSym = {
    kind: 'var',
    t,
    names,
    readOnly: `cannot assign to uniform '${short(name)}'`,
    global: true,
  };
  ctx.declare(name, usym);
  if (name === 'numPasses') {
    g.numPassesSym = usym;
    g.numPassesDeclared = true;
  }
}

/** A global variable or constant: folded into the code when never written, else JS variables set by I1/I2. */
function declareGlobal(ctx: Ctx, name: string, t: GType, init: Node | undefined, isConst: boolean, g: Globals): void {
  if (isConst && init === undefined) throw ctx.error(`const '${short(name)}' needs an initialiser`);
  const isWritten = g.written.has(name) && !isConst;
  let value =
    init !== undefined ? inGlobal(ctx, g.onceCtx, g.onceBuf, () => compileInitializer(ctx, init, t)) : undefined;
  if (!isWritten && (value?.k !== undefined || (init === undefined && !isConst))) {
    // Never written with a constant (or default zero) value: fold it into the code.
    const k = value?.k ?? new Array<number | boolean>(size(t)).fill(t.base === 'bool' ? false : 0);
    const sym: VarSym = {
      kind: 'var',
      t,
      names: [],
      k,
      readOnly: isConst ? `cannot assign to const '${short(name)}'` : undefined,
      global: true,
    };
    ctx.declare(name, sym);
    if (name === 'numPasses') g.numPassesSym = sym;
    if (name === 'numPasses') g.numPassesDeclared = true;
    return;
  }
  const names: string[] = [];
  for (let i = 0; i < size(t); i++) names.push(ctx.id('g'));
  g.globalDecls.push(`let ${names.map((n) => `${n} = ${zeroOf(t.base)}`).join(', ')};`);
  const emitInit = (v: Value | undefined) => {
    if (v === undefined) names.forEach((n) => ctx.emit(`${n} = ${zeroOf(t.base)};`));
    else names.forEach((n, i) => ctx.emit(`${n} = ${v.c[i]};`));
  };
  inGlobal(ctx, g.onceCtx, g.onceBuf, () => emitInit(value));
  if (isWritten) {
    g.hasEach = true;
    inGlobal(ctx, g.eachCtx, g.eachBuf, () => {
      value = init !== undefined ? compileInitializer(ctx, init, t) : undefined;
      emitInit(value);
    });
  }
  const sym: VarSym = {
    kind: 'var',
    t,
    names,
    readOnly: isConst ? `cannot assign to const '${short(name)}'` : undefined,
    global: true,
  };
  ctx.declare(name, sym);
  if (name === 'numPasses') {
    g.numPassesSym = sym;
    g.numPassesDeclared = true;
  }
}

/** The entry point, checked: defined, taking one vec3, returning a vec4 (cellular) or float (density). */
function checkEntry(ctx: Ctx, entryFn: FnSym | undefined, entry: EntryKind): FnSym {
  if (entryFn === undefined) {
    const sig = entry === 'cellular' ? 'vec4 cellular(vec3 world)' : 'float density(vec3 world)';
    throw ctx.error(`the shader must define ${sig}`, 0);
  }
  const ef = entryFn;
  if (
    ef.params.length !== 1 ||
    ef.params[0].q !== 'in' ||
    ef.params[0].t.base !== 'float' ||
    ef.params[0].t.rows !== 3 ||
    ef.params[0].t.cols !== 1
  ) {
    throw ctx.error(`${entry}() must take one vec3 argument`, ef.line);
  }
  if (ef.ret.rows === 0 || ef.ret.cols !== 1 || ef.ret.base === 'bool' || (entry === 'density' && ef.ret.rows !== 1)) {
    throw ctx.error(entry === 'cellular' ? 'cellular() must return a vec4' : 'density() must return a float', ef.line);
  }
  return ef;
}

/** Refuse functions that are called but never defined, and recursion. */
function checkFunctions(ctx: Ctx): void {
  for (const list of ctx.functions.values()) {
    for (const f of list) {
      if (!f.defined && [...ctx.calls.values()].some((s) => s.has(f.jsName))) {
        throw ctx.error(`${short(f.glslName)}() is declared but never defined`, f.line);
      }
    }
  }
  checkRecursion(ctx);
}

/** The entry function E(X, Y, Z): call the shader within its budgets and return its key. */
function entryJs(ef: FnSym, opts: ProgramOptions, hasEach: boolean): string {
  const EB = opts.evalBudget;
  const retN = size(ef.ret);
  const call = `${ef.jsName}(X, Y, Z)`;
  const entryLines: string[] = [`B = ${EB};`];
  if (hasEach) entryLines.push('I2();');
  if (opts.entry === 'density') {
    entryLines.push(`const r = ${call};`, `W += ${EB} - B;`, `if (W > ${opts.layerBudget}) m_wlim();`, 'return r;');
  } else if (retN === 1) {
    entryLines.push(
      `const r = ${call};`,
      `W += ${EB} - B;`,
      `if (W > ${opts.layerBudget}) m_wlim();`,
      'return m_key(r, 0, 0, 0);',
    );
  } else {
    const ch = [0, 1, 2, 3].map((i) => (i < retN ? `R[${i}]` : '0'));
    entryLines.push(
      `${call};`,
      `W += ${EB} - B;`,
      `if (W > ${opts.layerBudget}) m_wlim();`,
      `return m_key(${ch.join(', ')});`,
    );
  }
  return `function E(X, Y, Z) {\n${entryLines.join('\n')}\n}`;
}

/** The setup function S(A, D, N, T): uniform values, host functions and values, then the once initialisers. */
function setupJs(g: Globals, evalBudget: number): string {
  const setLines: string[] = [];
  let k = 0;
  g.uniforms.forEach((u, i) => {
    for (const n of g.uniformNames[i]) {
      setLines.push(
        u.type.base === 'bool'
          ? `${n} = A[${k}] !== 0;`
          : u.type.base === 'int'
            ? `${n} = A[${k}] | 0;`
            : u.type.base === 'uint'
              ? `${n} = A[${k}] >>> 0;`
              : `${n} = A[${k}];`,
      );
      k++;
    }
  });
  return `function S(A, D, N, T) {\n${setLines.join('\n')}\nh_den = D;\nh_noz = N;\nh_lh = T;\nB = ${evalBudget};\nI1();\n}`;
}

/** The factory body: the math table's names, globals, functions, initialisers, then E, S, NP, WR, WG. */
function factoryBody(
  ctx: Ctx,
  g: Globals,
  functionsJs: readonly string[],
  ef: FnSym,
  numPassesExpr: string,
  opts: ProgramOptions,
): string {
  const lines: string[] = [];
  lines.push('"use strict";');
  lines.push(`const ${TABLE_KEYS.map((k) => `m_${k} = M.${k}`).join(', ')};`);
  lines.push(`const R = new m_F64(${Math.max(4, ctx.rSize)});`);
  lines.push('let B = 0, W = 0;');
  lines.push('let h_den = m_den0, h_noz = 0.4, h_lh = 0.2;');
  for (const d of g.globalDecls) lines.push(d);
  for (const c of ctx.closureDecls) lines.push(c);
  for (const f of functionsJs) lines.push(f);
  lines.push(wrapFunction('I1', [], g.onceCtx.locals, g.onceBuf.lines));
  lines.push(wrapFunction('I2', [], g.eachCtx.locals, g.eachBuf.lines));
  lines.push(entryJs(ef, opts, g.hasEach));
  lines.push(setupJs(g, opts.evalBudget));
  lines.push(`function NP() { return ${numPassesExpr}; }`);
  lines.push('function WR(V) { W = V; }');
  lines.push('function WG() { return W; }');
  lines.push('return [E, S, NP, WR, WG, R];');
  return lines.join('\n');
}

/** Compile a parsed program into the body of the shader factory. */
export function compileProgram(ctx: Ctx, program: Node[], opts: ProgramOptions): CompiledProgram {
  const fnByNode = registerFunctions(ctx, program);
  const g = newGlobals(writtenNames(program, outParamFunctions(ctx)), opts.uiParams);
  const functionsJs: string[] = [];
  const entryFn = compileTopLevel(ctx, program, fnByNode, g, opts.entry, functionsJs);
  const ef = checkEntry(ctx, entryFn, opts.entry);
  checkFunctions(ctx);

  const numPassesSym = g.numPassesSym;
  if (numPassesSym !== undefined && (numPassesSym.t.base !== 'int' || size(numPassesSym.t) !== 1)) {
    throw ctx.error('numPasses must be an int', 0);
  }
  const numPassesConst =
    numPassesSym?.k !== undefined ? (numPassesSym.k[0] as number) : numPassesSym === undefined ? 1 : undefined;
  const numPassesExpr =
    numPassesSym === undefined ? '1' : numPassesSym.k !== undefined ? lit(numPassesSym.k[0]) : numPassesSym.names[0];
  return {
    body: factoryBody(ctx, g, functionsJs, ef, numPassesExpr, opts),
    uniforms: g.uniforms,
    numPassesConst,
    hasNumPasses: g.numPassesDeclared,
    usesDensity: ctx.hostUsed.has('density'),
  };
}
