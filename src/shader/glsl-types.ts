/**
 * The GLSL value types the shader compiler understands: scalars, vectors and square matrices of
 * float / int / uint / bool. A value of `rows × cols` components is scalarised into that many JS
 * locals, column-major (component index = col · rows + row).
 */

export type Base = 'float' | 'int' | 'uint' | 'bool';

export interface GType {
  readonly base: Base;
  /** Components per column (1 for scalars). */
  readonly rows: number;
  /** Columns (1 for scalars and vectors). */
  readonly cols: number;
}

export const VOID_NAME = 'void';

export function gtype(base: Base, rows = 1, cols = 1): GType {
  return { base, rows, cols };
}

export const FLOAT = gtype('float');
export const INT = gtype('int');
export const UINT = gtype('uint');
export const BOOL = gtype('bool');

export function size(t: GType): number {
  return t.rows * t.cols;
}

export function isScalar(t: GType): boolean {
  return t.rows === 1 && t.cols === 1;
}

export function isVector(t: GType): boolean {
  return t.rows > 1 && t.cols === 1;
}

export function isMatrix(t: GType): boolean {
  return t.cols > 1;
}

export function sameType(a: GType, b: GType): boolean {
  return a.base === b.base && a.rows === b.rows && a.cols === b.cols;
}

export function withBase(t: GType, base: Base): GType {
  return { base, rows: t.rows, cols: t.cols };
}

const VEC_PREFIX: Record<Base, string> = { float: 'vec', int: 'ivec', uint: 'uvec', bool: 'bvec' };

export function typeName(t: GType): string {
  if (isScalar(t)) return t.base;
  if (isMatrix(t)) return `mat${t.cols}`;
  return `${VEC_PREFIX[t.base]}${t.rows}`;
}

/** The type named by a GLSL type keyword, or undefined for names this compiler does not support. */
export function parseTypeName(name: string): GType | undefined {
  switch (name) {
    case 'float':
      return FLOAT;
    case 'int':
      return INT;
    case 'uint':
      return UINT;
    case 'bool':
      return BOOL;
  }
  const vec = /^(vec|ivec|uvec|bvec)([234])$/.exec(name);
  if (vec) {
    const base: Base = vec[1] === 'vec' ? 'float' : vec[1] === 'ivec' ? 'int' : vec[1] === 'uvec' ? 'uint' : 'bool';
    return gtype(base, Number(vec[2]));
  }
  const mat = /^mat([234])(?:x([234]))?$/.exec(name);
  if (mat) {
    const n = Number(mat[1]);
    if (mat[2] !== undefined && Number(mat[2]) !== n) return undefined;
    return gtype('float', n, n);
  }
  return undefined;
}

/** Whether a value of type `from` converts implicitly to `to` (GLSL 4: int → uint → float). */
export function implicitlyConvertible(from: GType, to: GType): boolean {
  if (from.rows !== to.rows || from.cols !== to.cols) return false;
  if (from.base === to.base) return true;
  if (from.base === 'int') return to.base === 'float' || to.base === 'uint';
  if (from.base === 'uint') return to.base === 'float';
  return false;
}

/** The common base of two numeric operands after implicit conversion, or undefined. */
export function commonBase(a: Base, b: Base): Base | undefined {
  if (a === b) return a;
  if (a === 'bool' || b === 'bool') return undefined;
  if (a === 'float' || b === 'float') return 'float';
  return 'uint';
}
