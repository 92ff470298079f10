/**
 * The only things generated shader code can reach: a frozen table of pure math functions plus a few
 * host callbacks (limit errors, the colour → label key). One table is built per shader instance.
 */
import { limitExceeded } from './shader-error.js';

/** Pure functions, also used for compile-time constant folding. */
export const PURE_MATH = Object.freeze({
  sin: Math.sin,
  cos: Math.cos,
  tan: Math.tan,
  asin: Math.asin,
  acos: Math.acos,
  atan: Math.atan,
  atan2: Math.atan2,
  sinh: Math.sinh,
  cosh: Math.cosh,
  tanh: Math.tanh,
  asinh: Math.asinh,
  acosh: Math.acosh,
  atanh: Math.atanh,
  pow: Math.pow,
  exp: Math.exp,
  log: Math.log,
  log2: Math.log2,
  sqrt: Math.sqrt,
  abs: Math.abs,
  sign: Math.sign,
  floor: Math.floor,
  ceil: Math.ceil,
  trunc: Math.trunc,
  round: Math.round,
  imul: Math.imul,
  roundEven(x: number): number {
    const r = Math.round(x);
    return Math.abs(x % 1) === 0.5 && r % 2 !== 0 ? r - 1 : r;
  },
});

export type PureMathName = keyof typeof PURE_MATH;

export interface TableOptions {
  fileName: string;
  evalBudget: number;
  layerBudget: number;
}

/** Names of the table entries the generated code binds (`const m_x = M.x`). */
export const TABLE_KEYS: readonly string[] = [
  ...Object.keys(PURE_MATH),
  'fbi',
  'fbu',
  'ibf',
  'ubf',
  'key',
  'lim',
  'clim',
  'wlim',
  'den0',
  'F64',
];

/** Build the table handed to the generated factory as its only parameter. */
export function makeMathTable(opts: TableOptions): Readonly<Record<string, unknown>> {
  const f32 = new Float32Array(4);
  const i32 = new Int32Array(f32.buffer);
  const u32 = new Uint32Array(f32.buffer);
  const table: Record<string, unknown> = { ...PURE_MATH };
  table.fbi = (x: number) => {
    f32[0] = x;
    return i32[0];
  };
  table.fbu = (x: number) => {
    f32[0] = x;
    return u32[0];
  };
  table.ibf = (x: number) => {
    i32[0] = x;
    return f32[0];
  };
  table.ubf = (x: number) => {
    u32[0] = x;
    return f32[0];
  };
  /** Label of an RGBA colour: float32 bits of each channel mixed into a 53-bit integer. */
  table.key = (r: number, g: number, b: number, a: number) => {
    f32[0] = r + 0;
    f32[1] = g + 0;
    f32[2] = b + 0;
    f32[3] = a + 0;
    let h1 = 0x811c9dc5 ^ i32[0];
    h1 = Math.imul(h1 ^ (h1 >>> 16), 0x85ebca6b) ^ i32[1];
    h1 = Math.imul(h1 ^ (h1 >>> 13), 0xc2b2ae35) ^ i32[2];
    h1 = Math.imul(h1 ^ (h1 >>> 16), 0x27d4eb2f) ^ i32[3];
    h1 = Math.imul(h1 ^ (h1 >>> 15), 0x165667b1);
    let h2 = 0x9747b28c ^ i32[3];
    h2 = Math.imul(h2 ^ (h2 >>> 15), 0x2c1b3c6d) ^ i32[2];
    h2 = Math.imul(h2 ^ (h2 >>> 12), 0x297a2d39) ^ i32[1];
    h2 = Math.imul(h2 ^ (h2 >>> 15), 0x85ebca6b) ^ i32[0];
    h2 = Math.imul(h2 ^ (h2 >>> 13), 0xc2b2ae35);
    return (h1 >>> 0) + ((h2 >>> 11) & 0x1fffff) * 4294967296;
  };
  table.lim = (line: number) => {
    throw limitExceeded(opts.fileName, line, `loop ran more than ${opts.evalBudget} iterations in one evaluation`);
  };
  table.clim = (line: number) => {
    throw limitExceeded(
      opts.fileName,
      line,
      `more than ${opts.evalBudget} function calls and loop iterations in one evaluation`,
    );
  };
  table.wlim = () => {
    throw limitExceeded(
      opts.fileName,
      undefined,
      `one layer needed more than ${opts.layerBudget} shader steps (loop iterations and function calls); simplify the shader or use a coarser resolution`,
    );
  };
  table.den0 = () => 20;
  table.F64 = Float64Array;
  return Object.freeze(table);
}
