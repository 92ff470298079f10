/**
 * Shared state of one GLSL → JS compilation: emitted statement buffers, generated names, scopes,
 * symbols and the function being compiled. Every JS identifier in the output is made here from a
 * fixed prefix and a counter, never from shader text.
 */
import type { Base, GType } from './glsl-types.js';
import type { HostOptions } from './builtins.js';
import { badShader } from './shader-error.js';
import { unmangle } from './preprocess.js';

/** A compiled expression: one JS expression per component (column-major), plus constants if known. */
export interface Value {
  t: GType;
  c: string[];
  /** The component values when all are compile-time constants. */
  k?: (number | boolean)[];
}

/** The value of a call to a void function. */
export const VOID_TYPE: GType = { base: 'float', rows: 0, cols: 0 };

export function isVoid(v: Value): boolean {
  return v.t.rows === 0;
}

/** One writable/readable scalar storage place. */
export type Slot =
  | { kind: 'name'; name: string; base: Base }
  | { kind: 'elem'; arr: string; index: string; base: Base }
  | { kind: 'dyn'; index: string; options: Slot[]; base: Base };

export interface LValue {
  t: GType;
  slots: Slot[];
  /** Why the place cannot be assigned, or undefined if it can. */
  readOnly?: string;
  /** GLSL name of the root variable (only for error messages and write tracking). */
  root: string;
}

export interface VarSym {
  kind: 'var';
  t: GType;
  /** JS names of the components (empty when `k` holds a compile-time constant). */
  names: string[];
  k?: (number | boolean)[];
  readOnly?: string;
  global: boolean;
}

export interface ArraySym {
  kind: 'array';
  /** Element type. */
  t: GType;
  length: number;
  /** JS name of the Float64Array holding the elements. */
  store: string;
  readOnly?: string;
  global: boolean;
}

export type Sym = VarSym | ArraySym;

export type ParamQualifier = 'in' | 'out' | 'inout';

export interface FnParam {
  t: GType;
  q: ParamQualifier;
}

export interface FnSym {
  /** GLSL name (error messages only). */
  glslName: string;
  jsName: string;
  ret: GType;
  params: FnParam[];
  defined: boolean;
  line: number;
  /** Offset of the out/inout values in the return register (after the return value). */
  outOffset: number;
}

export class Buf {
  lines: string[] = [];
  /** Whether any emitted statement may change state visible to other expressions. */
  effect = false;
}

export interface LoopFrame {
  /** JS statement for `continue` inside this loop. */
  cont: string;
}

export interface FnCtx {
  locals: { name: string; base: Base }[];
  ret: GType;
  /** JS names of the out/inout parameter components, in order. */
  outNames: { names: string[]; base: Base }[];
  fn?: FnSym;
  loops: LoopFrame[];
  /** Nesting of JS switch statements (for `break`). */
  breakables: number;
  /** Whether this is the global initialiser (no return allowed). */
  isInit: boolean;
  /** Whether this is the entry function (discard allowed). */
  isEntry: boolean;
}

const STABLE = /^(?:t\d+|-?\d+(?:\.\d+)?(?:e[+-]?\d+)?|\(-\d+(?:\.\d+)?(?:e[+-]?\d+)?\)|true|false)$/;
const ATOM =
  /^(?:[tvgu]\d+(?:_\d+)?|h_[a-z]+|-?\d+(?:\.\d+)?(?:e[+-]?\d+)?|\(-\d+(?:\.\d+)?(?:e[+-]?\d+)?\)|true|false)$/;

/** Whether a component expression needs no temporary to be used twice. */
export function isAtom(c: string): boolean {
  return ATOM.test(c);
}

/** Whether a component expression's value can never change (a literal or a temporary). */
export function isStable(c: string): boolean {
  return STABLE.test(c);
}

export class Ctx {
  readonly fileName: string;
  private counter = 0;
  buf: Buf = new Buf();
  fn: FnCtx;
  scopes: Map<string, Sym>[] = [new Map()];
  readonly functions = new Map<string, FnSym[]>();
  line = 0;
  /** Closure-level declarations (arrays, globals, uniforms): JS text lines. */
  readonly closureDecls: string[] = [];
  /** Largest number of slots of the return register any call needs. */
  rSize = 4;
  /** Call graph for the recursion check: caller JS name → callees. */
  readonly calls = new Map<string, Set<string>>();
  /** Total array elements allocated. */
  arrayElements = 0;
  readonly warnings: string[] = [];
  /** Host built-ins used by the shader. */
  readonly hostUsed = new Set<string>();
  /** Which host built-ins (density(), nozzle_diameter(), layer_height()) exist. */
  host: HostOptions = { density: true, machine: true };

  constructor(fileName: string) {
    this.fileName = fileName;
    this.fn = newFnCtx(undefined, { base: 'float', rows: 0, cols: 0 }, true);
  }

  error(message: string, line = this.line): Error {
    return badShader(this.fileName, line, message);
  }

  id(prefix: string): string {
    this.counter++;
    return `${prefix}${this.counter}`;
  }

  emit(line: string, effect = true): void {
    this.buf.lines.push(line);
    if (effect) this.buf.effect = true;
  }

  /** Run `f` with output going to `buf`; returns f's result. */
  into<T>(buf: Buf, f: () => T): T {
    const saved = this.buf;
    this.buf = buf;
    try {
      return f();
    } finally {
      this.buf = saved;
    }
  }

  append(buf: Buf): void {
    for (const l of buf.lines) this.buf.lines.push(l);
    if (buf.effect) this.buf.effect = true;
  }

  /** A new local (function-level `let`) of the given base; returns its JS name. */
  local(prefix: string, base: Base): string {
    const name = this.id(prefix);
    this.fn.locals.push({ name, base });
    return name;
  }

  /** Bind `expr` to a fresh temporary unless it already is an atom. */
  atom(expr: string, base: Base): string {
    if (isAtom(expr)) return expr;
    const t = this.local('t', base);
    this.emit(`${t} = ${expr};`, false);
    return t;
  }

  /** Like atom(), but also copies variables: the result cannot change afterwards. */
  snapshot(expr: string, base: Base): string {
    if (isStable(expr)) return expr;
    const t = this.local('t', base);
    this.emit(`${t} = ${expr};`, false);
    return t;
  }

  atomValue(v: Value): Value {
    if (v.k) return v;
    return { t: v.t, c: v.c.map((c) => this.atom(c, v.t.base)) };
  }

  snapshotValue(v: Value): Value {
    if (v.k) return v;
    return { t: v.t, c: v.c.map((c) => this.snapshot(c, v.t.base)) };
  }

  /**
   * Evaluate expressions left to right with GLSL ordering: when a later one has side effects, the
   * earlier results are copied into temporaries first.
   */
  sequence<T extends Value>(fns: (() => T)[]): T[] {
    const vals: T[] = [];
    for (const f of fns) {
      const b = new Buf();
      const v = this.into(b, f);
      if (b.effect) for (let i = 0; i < vals.length; i++) vals[i] = this.snapshotValue(vals[i]) as T;
      this.append(b);
      vals.push(v);
    }
    return vals;
  }

  lookup(name: string): Sym | undefined {
    for (let i = this.scopes.length - 1; i >= 0; i--) {
      const s = this.scopes[i].get(name);
      if (s !== undefined) return s;
    }
    return undefined;
  }

  declare(name: string, sym: Sym): void {
    const scope = this.scopes[this.scopes.length - 1];
    if (scope.has(name)) throw this.error(`'${short(name)}' is already declared in this scope`);
    scope.set(name, sym);
  }

  pushScope(): void {
    this.scopes.push(new Map());
  }

  popScope(): void {
    this.scopes.pop();
  }

  noteCall(callee: string): void {
    const caller = this.fn.fn?.jsName ?? 'init';
    let set = this.calls.get(caller);
    if (set === undefined) this.calls.set(caller, (set = new Set()));
    set.add(callee);
  }
}

export function newFnCtx(fn: FnSym | undefined, ret: GType, isInit: boolean): FnCtx {
  return { locals: [], ret, outNames: [], fn, loops: [], breakables: 0, isInit, isEntry: false };
}

/** A shader identifier shortened for error messages. */
export function short(name: string): string {
  const n = unmangle(name);
  return n.length > 40 ? `${n.slice(0, 40)}…` : n;
}
