/**
 * GLSL built-in functions, expanded component-wise into scalar JS over the math table (`m_*`), plus
 * the host functions IceSL gives infill shaders: density(vec3), nozzle_diameter(), layer_height().
 */
import type { Base, GType } from './glsl-types.js';
import { BOOL, FLOAT, gtype, isMatrix, isScalar, isVector, size, typeName } from './glsl-types.js';
import type { Ctx, Value } from './compiler-context.js';
import { constValue, convert, splat } from './values.js';
import { PURE_MATH } from './math-table.js';
import type { PureMathName } from './math-table.js';
import { arith } from './operators.js';

type Comp = (c: string[]) => string;
type Fold = (k: number[]) => number | boolean;

const UNAVAILABLE = new Set([
  'texture',
  'texture2D',
  'texture3D',
  'textureLod',
  'texelFetch',
  'textureSize',
  'dFdx',
  'dFdy',
  'fwidth',
  'noise1',
  'noise2',
  'noise3',
  'noise4',
  'imageLoad',
  'imageStore',
]);

/** Whether `name` is a GLSL built-in that infill shaders cannot use (textures, derivatives). */
export function isUnavailable(name: string): boolean {
  return UNAVAILABLE.has(name);
}

/** Which host built-ins a shader may call. */
export interface HostOptions {
  density: boolean;
  machine: boolean;
}

function numeric(ctx: Ctx, name: string, v: Value): void {
  if (v.t.rows === 0) throw ctx.error(`${name}(): argument has no value`);
  if (v.t.base === 'bool') throw ctx.error(`${name}(): needs numbers, not ${typeName(v.t)}`);
}

function arity(ctx: Ctx, name: string, args: Value[], n: number | number[]): void {
  const ok = typeof n === 'number' ? args.length === n : n.includes(args.length);
  if (!ok)
    throw ctx.error(`${name}() takes ${typeof n === 'number' ? n : n.join(' or ')} argument(s), got ${args.length}`);
}

/** The common shape of component-wise arguments: scalars splat to the one vector shape present. */
function shapeOf(ctx: Ctx, name: string, args: Value[]): GType {
  let shape: GType | undefined;
  for (const a of args) {
    if (isScalar(a.t)) continue;
    if (shape === undefined) shape = a.t;
    else if (shape.rows !== a.t.rows || shape.cols !== a.t.cols)
      throw ctx.error(`${name}(): argument sizes do not match`);
  }
  return shape ?? FLOAT;
}

/**
 * Apply `f` to each component. `reuse[i]` says argument i appears more than once in f's output
 * (it is then bound to temporaries first).
 */
function mapComps(
  ctx: Ctx,
  name: string,
  args: Value[],
  base: Base,
  resultBase: Base,
  f: Comp,
  fold?: Fold,
  reuse: boolean[] = [],
): Value {
  const shape = shapeOf(ctx, name, args);
  const t = gtype(base, shape.rows, shape.cols);
  const conv = args.map((a) => convert(a, base));
  if (fold && conv.every((a) => a.k)) {
    const out: (number | boolean)[] = [];
    for (let i = 0; i < size(t); i++) out.push(fold(conv.map((a) => (isScalar(a.t) ? a.k?.[0] : a.k?.[i]) as number)));
    return constValue(gtype(resultBase, t.rows, t.cols), out);
  }
  const full = conv.map((a, i) => {
    const s = isScalar(a.t) && !isScalar(t) ? splat(ctx, a, t) : a;
    return reuse[i] ? ctx.atomValue(s) : s;
  });
  const c: string[] = [];
  for (let i = 0; i < size(t); i++) c.push(f(full.map((a) => a.c[i])));
  return { t: gtype(resultBase, t.rows, t.cols), c };
}

/** Base for functions with int overloads (abs, sign, min, max, clamp). */
function intOrFloat(args: Value[]): Base {
  if (args.every((a) => a.t.base === 'int')) return 'int';
  if (args.every((a) => a.t.base === 'uint')) return 'uint';
  return 'float';
}

function math1(ctx: Ctx, name: string, args: Value[], fn: PureMathName): Value {
  arity(ctx, name, args, 1);
  numeric(ctx, name, args[0]);
  const f = PURE_MATH[fn] as (x: number) => number;
  return mapComps(
    ctx,
    name,
    args,
    'float',
    'float',
    (c) => `m_${fn}(${c[0]})`,
    (k) => f(k[0]),
  );
}

function dotComps(a: Value, b: Value): string {
  return a.c.length === 1 ? `(${a.c[0]} * ${b.c[0]})` : `(${a.c.map((c, i) => `${c} * ${b.c[i]}`).join(' + ')})`;
}

function vecArgs(ctx: Ctx, name: string, args: Value[], n: number): Value[] {
  arity(ctx, name, args, n);
  for (const a of args) numeric(ctx, name, a);
  const conv = args.map((a) => convert(a, 'float'));
  for (const a of conv) if (isMatrix(a.t)) throw ctx.error(`${name}(): needs vectors, not matrices`);
  return conv;
}

function sameSize(ctx: Ctx, name: string, a: Value, b: Value): void {
  if (size(a.t) !== size(b.t)) throw ctx.error(`${name}(): argument sizes do not match`);
}

function vectorCompare(ctx: Ctx, name: string, args: Value[], op: string): Value {
  arity(ctx, name, args, 2);
  const [a, b] = args;
  if (!isVector(a.t) || !isVector(b.t) || a.t.rows !== b.t.rows)
    throw ctx.error(`${name}() needs two vectors of the same size`);
  const numericOp = op !== '===' && op !== '!==';
  if (numericOp) {
    numeric(ctx, name, a);
    numeric(ctx, name, b);
  }
  const base: Base = a.t.base === b.t.base ? a.t.base : 'float';
  const x = convert(a, base);
  const y = convert(b, base);
  return { t: gtype('bool', a.t.rows), c: x.c.map((c, i) => `(${c} ${op} ${y.c[i]})`) };
}

function determinantComps(m: string[], n: number): string {
  const at = (r: number, c: number) => m[c * n + r];
  if (n === 2) return `(${at(0, 0)} * ${at(1, 1)} - ${at(0, 1)} * ${at(1, 0)})`;
  if (n === 3) {
    return `(${at(0, 0)} * (${at(1, 1)} * ${at(2, 2)} - ${at(1, 2)} * ${at(2, 1)}) - ${at(0, 1)} * (${at(1, 0)} * ${at(2, 2)} - ${at(1, 2)} * ${at(2, 0)}) + ${at(0, 2)} * (${at(1, 0)} * ${at(2, 1)} - ${at(1, 1)} * ${at(2, 0)}))`;
  }
  // Laplace expansion along the first row.
  const terms: string[] = [];
  for (let c = 0; c < 4; c++) {
    const minor: string[] = [];
    for (let cc = 0; cc < 4; cc++) {
      if (cc === c) continue;
      for (let r = 1; r < 4; r++) minor.push(at(r, cc));
    }
    terms.push(`${c % 2 === 0 ? '+' : '-'} ${at(0, c)} * ${determinantComps(minor, 3)}`);
  }
  return `(${terms.join(' ')})`;
}

/** Compiles one built-in call from its compiled arguments; undefined when the host does not offer it. */
type Builtin = (ctx: Ctx, name: string, args: Value[], host: HostOptions) => Value | undefined;

/** A one-argument float function, applied to each component. */
function float1(ctx: Ctx, name: string, args: Value[], f: Comp, fold: Fold, reuse?: boolean[]): Value {
  arity(ctx, name, args, 1);
  numeric(ctx, name, args[0]);
  return mapComps(ctx, name, args, 'float', 'float', f, fold, reuse);
}

/** A two-argument float function, applied to each component. */
function float2(ctx: Ctx, name: string, args: Value[], f: Comp, fold: Fold, reuse?: boolean[]): Value {
  arity(ctx, name, args, 2);
  for (const a of args) numeric(ctx, name, a);
  return mapComps(ctx, name, args, 'float', 'float', f, fold, reuse);
}

// ---- Angles, trigonometry, exponentials (and the rounding the math table computes) ----

/** One-argument functions that call the math table's function of the same name. */
const MATH_TABLE_1: readonly PureMathName[] = [
  'sin',
  'cos',
  'tan',
  'asin',
  'acos',
  'sinh',
  'cosh',
  'tanh',
  'asinh',
  'acosh',
  'atanh',
  'exp',
  'log',
  'log2',
  'sqrt',
  'floor',
  'ceil',
  'trunc',
  'round',
  'roundEven',
];

/** radians() and degrees(): a multiplication by a constant. */
function angleUnits(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, 1);
  numeric(ctx, name, args[0]);
  const f = name === 'radians' ? Math.PI / 180 : 180 / Math.PI;
  return mapComps(
    ctx,
    name,
    args,
    'float',
    'float',
    (c) => `(${c[0]} * ${f})`,
    (k) => k[0] * f,
  );
}

/** atan(y_over_x) or atan(y, x). */
function atan(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, [1, 2]);
  for (const a of args) numeric(ctx, name, a);
  if (args.length === 1) return math1(ctx, name, args, 'atan');
  return mapComps(
    ctx,
    name,
    args,
    'float',
    'float',
    (c) => `m_atan2(${c[0]}, ${c[1]})`,
    (k) => Math.atan2(k[0], k[1]),
  );
}

const TRIG_EXP: Record<string, Builtin> = {
  ...Object.fromEntries(
    MATH_TABLE_1.map((fn): [string, Builtin] => [fn, (ctx, name, args) => math1(ctx, name, args, fn)]),
  ),
  radians: angleUnits,
  degrees: angleUnits,
  exp2: (ctx, name, args) =>
    float1(
      ctx,
      name,
      args,
      (c) => `m_pow(2, ${c[0]})`,
      (k) => Math.pow(2, k[0]),
    ),
  inversesqrt: (ctx, name, args) =>
    float1(
      ctx,
      name,
      args,
      (c) => `(1 / m_sqrt(${c[0]}))`,
      (k) => 1 / Math.sqrt(k[0]),
    ),
  atan,
  pow: (ctx, name, args) =>
    float2(
      ctx,
      name,
      args,
      (c) => `m_pow(${c[0]}, ${c[1]})`,
      (k) => Math.pow(k[0], k[1]),
    ),
};

// ---- Common functions ----

/** abs(): int, uint (unchanged) or float. */
function abs(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, 1);
  numeric(ctx, name, args[0]);
  const base = intOrFloat(args);
  if (base === 'uint') return args[0];
  const wrap = base === 'int' ? ' | 0' : '';
  return mapComps(
    ctx,
    name,
    args,
    base,
    base,
    (c) => (wrap ? `(m_abs(${c[0]})${wrap})` : `m_abs(${c[0]})`),
    (k) => (base === 'int' ? Math.abs(k[0]) | 0 : Math.abs(k[0])),
  );
}

/** sign(): int, uint or float. */
function sign(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, 1);
  numeric(ctx, name, args[0]);
  const base = intOrFloat(args);
  return mapComps(
    ctx,
    name,
    args,
    base,
    base,
    (c) => `m_sign(${c[0]})`,
    (k) => Math.sign(k[0]),
  );
}

/** min() and max(): int, uint or float. */
function minMax(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, 2);
  for (const a of args) numeric(ctx, name, a);
  const base = intOrFloat(args);
  const op = name === 'min' ? '<' : '>';
  return mapComps(
    ctx,
    name,
    args,
    base,
    base,
    (c) => `(${c[0]} ${op} ${c[1]} ? ${c[0]} : ${c[1]})`,
    (k) => (name === 'min' ? (k[0] < k[1] ? k[0] : k[1]) : k[0] > k[1] ? k[0] : k[1]),
    [true, true],
  );
}

/** clamp(x, lo, hi): int, uint or float. */
function clamp(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, 3);
  for (const a of args) numeric(ctx, name, a);
  const base = intOrFloat(args);
  return mapComps(
    ctx,
    name,
    args,
    base,
    base,
    (c) => `(${c[0]} < ${c[1]} ? ${c[1]} : ${c[0]} > ${c[2]} ? ${c[2]} : ${c[0]})`,
    (k) => (k[0] < k[1] ? k[1] : k[0] > k[2] ? k[2] : k[0]),
    [true, true, true],
  );
}

/** mix(x, y, a): a linear blend, or a per-component choice when a is bool. */
function mix(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, 3);
  if (args[2].t.base === 'bool') {
    const base = args[0].t.base === args[1].t.base ? args[0].t.base : 'float';
    return mapComps(
      ctx,
      name,
      [convert(args[0], base), convert(args[1], base), args[2]].map((a, i) => (i === 2 ? a : a)),
      base,
      base,
      (c) => `(${c[2]} ? ${c[1]} : ${c[0]})`,
    );
  }
  for (const a of args) numeric(ctx, name, a);
  return mapComps(
    ctx,
    name,
    args,
    'float',
    'float',
    (c) => `(${c[0]} * (1 - ${c[2]}) + ${c[1]} * ${c[2]})`,
    (k) => k[0] * (1 - k[2]) + k[1] * k[2],
    [false, false, true],
  );
}

/** smoothstep(e0, e1, x): the scaled x, clamped to [0, 1], then the cubic. */
function smoothstep(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, 3);
  for (const a of args) numeric(ctx, name, a);
  const q = mapComps(
    ctx,
    name,
    args,
    'float',
    'float',
    (c) => `((${c[2]} - ${c[0]}) / (${c[1]} - ${c[0]}))`,
    (k) => (k[2] - k[0]) / (k[1] - k[0]),
    [true, false, false],
  );
  const clamped = mapComps(
    ctx,
    name,
    [q],
    'float',
    'float',
    (c) => `(${c[0]} < 0 ? 0 : ${c[0]} > 1 ? 1 : ${c[0]})`,
    (k) => Math.min(1, Math.max(0, k[0])),
    [true],
  );
  return mapComps(
    ctx,
    name,
    [clamped],
    'float',
    'float',
    (c) => `(${c[0]} * ${c[0]} * (3 - 2 * ${c[0]}))`,
    (k) => k[0] * k[0] * (3 - 2 * k[0]),
    [true],
  );
}

/** isnan() and isinf(): float in, bool out. */
function floatTest(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, 1);
  numeric(ctx, name, args[0]);
  if (name === 'isnan') {
    return mapComps(
      ctx,
      name,
      args,
      'float',
      'bool',
      (c) => `(${c[0]} !== ${c[0]})`,
      (k) => Number.isNaN(k[0]),
      [true],
    );
  }
  return mapComps(
    ctx,
    name,
    args,
    'float',
    'bool',
    (c) => `(m_abs(${c[0]}) === (1/0))`,
    (k) => Math.abs(k[0]) === Infinity,
  );
}

/** The math table's function for each bit cast. */
const BIT_CASTS: Record<string, string> = {
  floatBitsToInt: 'fbi',
  floatBitsToUint: 'fbu',
  intBitsToFloat: 'ibf',
  uintBitsToFloat: 'ubf',
};

/** floatBitsToInt() and the other bit casts between float, int and uint. */
function bitCast(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, 1);
  numeric(ctx, name, args[0]);
  const fn = BIT_CASTS[name];
  const from: Base = name.startsWith('float') ? 'float' : name.startsWith('int') ? 'int' : 'uint';
  const to: Base = name.endsWith('Float') ? 'float' : name.endsWith('Uint') ? 'uint' : 'int';
  return mapComps(ctx, name, args, from, to, (c) => `m_${fn}(${c[0]})`);
}

const COMMON: Record<string, Builtin> = {
  fract: (ctx, name, args) =>
    float1(
      ctx,
      name,
      args,
      (c) => `(${c[0]} - m_floor(${c[0]}))`,
      (k) => k[0] - Math.floor(k[0]),
      [true],
    ),
  mod: (ctx, name, args) =>
    float2(
      ctx,
      name,
      args,
      (c) => `(${c[0]} - ${c[1]} * m_floor(${c[0]} / ${c[1]}))`,
      (k) => k[0] - k[1] * Math.floor(k[0] / k[1]),
      [true, true],
    ),
  abs,
  sign,
  min: minMax,
  max: minMax,
  clamp,
  mix,
  step: (ctx, name, args) =>
    float2(
      ctx,
      name,
      args,
      (c) => `(${c[1]} < ${c[0]} ? 0 : 1)`,
      (k) => (k[1] < k[0] ? 0 : 1),
    ),
  smoothstep,
  isnan: floatTest,
  isinf: floatTest,
  floatBitsToInt: bitCast,
  floatBitsToUint: bitCast,
  intBitsToFloat: bitCast,
  uintBitsToFloat: bitCast,
};

// ---- Geometric functions ----

/** refract(I, N, eta): zero where the ray is totally reflected. */
function refract(ctx: Ctx, name: string, args: Value[]): Value {
  const [i0, n0, eta0] = vecArgs(ctx, name, args, 3);
  sameSize(ctx, name, i0, n0);
  if (!isScalar(eta0.t)) throw ctx.error('refract(): eta must be a float');
  const i = ctx.atomValue(i0);
  const n = ctx.atomValue(n0);
  const eta = ctx.atom(eta0.c[0], 'float');
  const d = ctx.atom(dotComps(n, i), 'float');
  const k = ctx.atom(`(1 - ${eta} * ${eta} * (1 - ${d} * ${d}))`, 'float');
  const f = ctx.atom(`(${eta} * ${d} + (${k} < 0 ? 0 : m_sqrt(${k})))`, 'float');
  return { t: i.t, c: i.c.map((x, j) => `(${k} < 0 ? 0 : ${eta} * ${x} - ${f} * ${n.c[j]})`) };
}

const GEOMETRIC: Record<string, Builtin> = {
  length: (ctx, name, args) => {
    const [a] = vecArgs(ctx, name, args, 1);
    if (isScalar(a.t)) return math1(ctx, 'abs', [a], 'abs');
    const v = ctx.atomValue(a);
    return { t: FLOAT, c: [`m_sqrt${dotComps(v, v)}`] };
  },
  distance: (ctx, name, args) => {
    const [a, b] = vecArgs(ctx, name, args, 2);
    sameSize(ctx, name, a, b);
    const d = ctx.atomValue(arith(ctx, '-', a, b));
    if (isScalar(d.t)) return { t: FLOAT, c: [`m_abs(${d.c[0]})`] };
    return { t: FLOAT, c: [`m_sqrt${dotComps(d, d)}`] };
  },
  dot: (ctx, name, args) => {
    const [a, b] = vecArgs(ctx, name, args, 2);
    sameSize(ctx, name, a, b);
    if (a.k && b.k) {
      const bk = b.k as number[];
      return constValue(FLOAT, [(a.k as number[]).reduce((s, v, i) => s + v * bk[i], 0)]);
    }
    return { t: FLOAT, c: [dotComps(a, b)] };
  },
  cross: (ctx, name, args) => {
    const [a0, b0] = vecArgs(ctx, name, args, 2);
    if (a0.t.rows !== 3 || b0.t.rows !== 3 || !isVector(a0.t)) throw ctx.error('cross() needs two vec3');
    const a = ctx.atomValue(a0).c;
    const b = ctx.atomValue(b0).c;
    return {
      t: gtype('float', 3),
      c: [
        `(${a[1]} * ${b[2]} - ${a[2]} * ${b[1]})`,
        `(${a[2]} * ${b[0]} - ${a[0]} * ${b[2]})`,
        `(${a[0]} * ${b[1]} - ${a[1]} * ${b[0]})`,
      ],
    };
  },
  normalize: (ctx, name, args) => {
    const [a] = vecArgs(ctx, name, args, 1);
    if (isScalar(a.t)) return math1(ctx, 'sign', [a], 'sign');
    const v = ctx.atomValue(a);
    const inv = ctx.atom(`(1 / m_sqrt${dotComps(v, v)})`, 'float');
    return { t: v.t, c: v.c.map((c) => `(${c} * ${inv})`) };
  },
  faceforward: (ctx, name, args) => {
    const [n, i, nref] = vecArgs(ctx, name, args, 3);
    const c = ctx.atom(`(${dotComps(nref, i)} < 0)`, 'bool');
    const nv = ctx.atomValue(n);
    return { t: nv.t, c: nv.c.map((x) => `(${c} ? ${x} : (-${x}))`) };
  },
  reflect: (ctx, name, args) => {
    const [i0, n0] = vecArgs(ctx, name, args, 2);
    sameSize(ctx, name, i0, n0);
    const i = ctx.atomValue(i0);
    const n = ctx.atomValue(n0);
    const d = ctx.atom(`(2 * ${dotComps(n, i)})`, 'float');
    return { t: i.t, c: i.c.map((x, k) => `(${x} - ${d} * ${n.c[k]})`) };
  },
  refract,
};

// ---- Matrix functions ----

/** inverse() of a mat2 or mat3: the adjugate times 1 / determinant. */
function inverse(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, 1);
  const m0 = args[0];
  if (!isMatrix(m0.t) || m0.t.rows === 4) throw ctx.error('inverse() supports mat2 and mat3');
  const m = ctx.atomValue(m0);
  const n = m.t.rows;
  const inv = ctx.atom(`(1 / ${determinantComps(m.c, n)})`, 'float');
  const at = (r: number, c: number) => m.c[c * n + r];
  const out: string[] = [];
  if (n === 2) {
    out.push(`(${at(1, 1)} * ${inv})`, `(-${at(1, 0)} * ${inv})`, `(-${at(0, 1)} * ${inv})`, `(${at(0, 0)} * ${inv})`);
  } else {
    for (let col = 0; col < 3; col++) {
      for (let row = 0; row < 3; row++) {
        // inverse[col][row] = cofactor(col, row) / det (adjugate is the transposed cofactor matrix).
        const r0 = (col + 1) % 3;
        const r1 = (col + 2) % 3;
        const c0 = (row + 1) % 3;
        const c1 = (row + 2) % 3;
        out.push(`((${at(r0, c0)} * ${at(r1, c1)} - ${at(r0, c1)} * ${at(r1, c0)}) * ${inv})`);
      }
    }
  }
  return { t: m.t, c: out };
}

const MATRIX: Record<string, Builtin> = {
  matrixCompMult: (ctx, name, args) => {
    arity(ctx, name, args, 2);
    const [a, b] = args;
    if (!isMatrix(a.t) || a.t.rows !== b.t.rows || a.t.cols !== b.t.cols)
      throw ctx.error('matrixCompMult() needs two matrices of the same size');
    return { t: a.t, c: a.c.map((c, i) => `(${c} * ${b.c[i]})`) };
  },
  outerProduct: (ctx, name, args) => {
    const [c0, r0] = vecArgs(ctx, name, args, 2);
    if (!isVector(c0.t) || c0.t.rows !== r0.t.rows)
      throw ctx.error('outerProduct() needs two vectors of the same size');
    const c = ctx.atomValue(c0);
    const r = ctx.atomValue(r0);
    const n = c.t.rows;
    const out: string[] = [];
    for (let col = 0; col < n; col++) for (let row = 0; row < n; row++) out.push(`(${c.c[row]} * ${r.c[col]})`);
    return { t: gtype('float', n, n), c: out };
  },
  transpose: (ctx, name, args) => {
    arity(ctx, name, args, 1);
    const m = args[0];
    if (!isMatrix(m.t)) throw ctx.error('transpose() needs a matrix');
    const n = m.t.rows;
    const out: string[] = [];
    for (let col = 0; col < n; col++) for (let row = 0; row < n; row++) out.push(m.c[row * n + col]);
    return { t: m.t, c: out };
  },
  determinant: (ctx, name, args) => {
    arity(ctx, name, args, 1);
    if (!isMatrix(args[0].t)) throw ctx.error('determinant() needs a matrix');
    const m = ctx.atomValue(args[0]);
    return { t: FLOAT, c: [determinantComps(m.c, m.t.rows)] };
  },
  inverse,
};

// ---- Vector relational functions ----

/** any() and all() of a bvec. */
function anyAll(ctx: Ctx, name: string, args: Value[]): Value {
  arity(ctx, name, args, 1);
  const v = args[0];
  if (v.t.base !== 'bool' || !isVector(v.t)) throw ctx.error(`${name}() needs a bvec`);
  return { t: BOOL, c: [`(${v.c.join(name === 'any' ? ' || ' : ' && ')})`] };
}

const VECTOR_RELATIONAL: Record<string, Builtin> = {
  lessThan: (ctx, name, args) => vectorCompare(ctx, name, args, '<'),
  lessThanEqual: (ctx, name, args) => vectorCompare(ctx, name, args, '<='),
  greaterThan: (ctx, name, args) => vectorCompare(ctx, name, args, '>'),
  greaterThanEqual: (ctx, name, args) => vectorCompare(ctx, name, args, '>='),
  equal: (ctx, name, args) => vectorCompare(ctx, name, args, '==='),
  notEqual: (ctx, name, args) => vectorCompare(ctx, name, args, '!=='),
  any: anyAll,
  all: anyAll,
  not: (ctx, name, args) => {
    arity(ctx, name, args, 1);
    const v = args[0];
    if (v.t.base !== 'bool' || !isVector(v.t)) throw ctx.error('not() needs a bvec');
    return { t: v.t, c: v.c.map((c) => `(!${c})`) };
  },
};

// ---- Host functions (IceSL's), only where the host offers them ----

/** nozzle_diameter() and layer_height(): the machine's values, when offered. */
function machineValue(ctx: Ctx, name: string, args: Value[], host: HostOptions): Value | undefined {
  if (!host.machine) return undefined;
  arity(ctx, name, args, 0);
  return { t: FLOAT, c: [name === 'nozzle_diameter' ? 'h_noz' : 'h_lh'] };
}

const HOST: Record<string, Builtin> = {
  density: (ctx, name, args, host) => {
    if (!host.density) return undefined;
    arity(ctx, name, args, 1);
    numeric(ctx, name, args[0]);
    if (!isVector(args[0].t) || args[0].t.rows !== 3) throw ctx.error('density() takes a vec3');
    const p = convert(args[0], 'float');
    ctx.hostUsed.add('density');
    const t = ctx.local('t', 'float');
    ctx.emit(`${t} = +h_den(${p.c.join(', ')});`, false);
    return { t: FLOAT, c: [t] };
  },
  nozzle_diameter: machineValue,
  layer_height: machineValue,
};

/** Every built-in by name (a Map, so names such as `toString` are not found on a prototype). */
const BUILTINS: ReadonlyMap<string, Builtin> = new Map(
  Object.entries({ ...TRIG_EXP, ...COMMON, ...GEOMETRIC, ...MATRIX, ...VECTOR_RELATIONAL, ...HOST }),
);

/**
 * Compile a built-in call, or return undefined when `name` is not a built-in.
 * Arguments are already compiled and sequenced.
 */
export function callBuiltin(ctx: Ctx, name: string, args: Value[], host: HostOptions): Value | undefined {
  if (UNAVAILABLE.has(name)) throw ctx.error(`${name}() is not available in infill shaders`);
  return BUILTINS.get(name)?.(ctx, name, args, host);
}

/** Names callBuiltin knows (so a user function can be told apart from a typo). */
export function isBuiltinName(name: string): boolean {
  return BUILTINS.has(name);
}
