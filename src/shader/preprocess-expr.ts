/** Evaluation of `#if` / `#elif` integer expressions (C preprocessor rules, 32-bit arithmetic). */
import { badShader } from './shader-error.js';

type Tok = { k: 'num'; v: number } | { k: 'op'; v: string };

const OPS = [
  '<<',
  '>>',
  '<=',
  '>=',
  '==',
  '!=',
  '&&',
  '||',
  '+',
  '-',
  '*',
  '/',
  '%',
  '<',
  '>',
  '&',
  '|',
  '^',
  '!',
  '~',
  '(',
  ')',
  '?',
  ':',
];

function tokenize(src: string, fileName: string, line: number): Tok[] {
  const toks: Tok[] = [];
  let i = 0;
  while (i < src.length) {
    const c = src[i];
    if (/\s/.test(c)) {
      i++;
      continue;
    }
    if (/[0-9]/.test(c)) {
      const m = /^(0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)[uU]?/.exec(src.slice(i));
      if (!m) throw badShader(fileName, line, 'bad number in #if');
      const body = m[1];
      const v = body.length > 1 && body[0] === '0' && !/[xX]/.test(body) ? parseInt(body, 8) : Number(body);
      toks.push({ k: 'num', v: v | 0 });
      i += m[0].length;
      continue;
    }
    const op = OPS.find((o) => src.startsWith(o, i));
    if (op === undefined) throw badShader(fileName, line, `unexpected '${c}' in #if`);
    toks.push({ k: 'op', v: op });
    i += op.length;
  }
  return toks;
}

const BINARY_PRECEDENCE = new Map<string, number>([
  ['||', 1],
  ['&&', 2],
  ['|', 3],
  ['^', 4],
  ['&', 5],
  ['==', 6],
  ['!=', 6],
  ['<', 7],
  ['>', 7],
  ['<=', 7],
  ['>=', 7],
  ['<<', 8],
  ['>>', 8],
  ['+', 9],
  ['-', 9],
  ['*', 10],
  ['/', 10],
  ['%', 10],
]);

function applyBinary(op: string, a: number, b: number, fail: (m: string) => never): number {
  switch (op) {
    case '||':
      return a !== 0 || b !== 0 ? 1 : 0;
    case '&&':
      return a !== 0 && b !== 0 ? 1 : 0;
    case '|':
      return a | b;
    case '^':
      return a ^ b;
    case '&':
      return a & b;
    case '==':
      return a === b ? 1 : 0;
    case '!=':
      return a !== b ? 1 : 0;
    case '<':
      return a < b ? 1 : 0;
    case '>':
      return a > b ? 1 : 0;
    case '<=':
      return a <= b ? 1 : 0;
    case '>=':
      return a >= b ? 1 : 0;
    case '<<':
      return a << b;
    case '>>':
      return a >> b;
    case '+':
      return (a + b) | 0;
    case '-':
      return (a - b) | 0;
    case '*':
      return Math.imul(a, b);
    case '/':
      if (b === 0) fail('division by zero in #if');
      return (a / b) | 0;
    case '%':
      if (b === 0) fail('division by zero in #if');
      return (a % b) | 0;
  }
  return fail(`unknown operator ${op}`);
}

/**
 * Evaluate a #if expression: `defined X` / `defined(X)` first, then macro expansion (via `expand`),
 * then identifiers left over count as 0.
 */
export function evalIfExpression(
  expr: string,
  macros: ReadonlyMap<string, unknown>,
  expand: (text: string) => string,
  fileName: string,
  line: number,
): number {
  const fail = (m: string): never => {
    throw badShader(fileName, line, m);
  };
  const withDefined = expr.replace(
    /\bdefined\s*(?:\(\s*([A-Za-z_][A-Za-z0-9_]*)\s*\)|([A-Za-z_][A-Za-z0-9_]*))/g,
    (_m, a?: string, b?: string) => (macros.has((a ?? b) as string) ? ' 1 ' : ' 0 '),
  );
  const expanded = expand(withDefined)
    .replace(/\btrue\b/g, '1')
    .replace(/\b[A-Za-z_][A-Za-z0-9_]*\b/g, '0');
  const toks = tokenize(expanded, fileName, line);
  if (toks.length === 0) fail('#if needs an expression');
  let pos = 0;
  const peek = (): Tok | undefined => toks[pos];
  const expectOp = (v: string) => {
    const t = toks[pos];
    if (t === undefined || t.k !== 'op' || t.v !== v) fail(`expected '${v}' in #if`);
    pos++;
  };
  const unary = (depth: number): number => {
    if (depth > 200) fail('#if expression nested too deeply');
    const t = toks[pos++];
    if (t === undefined) return fail('unexpected end of #if expression');
    if (t.k === 'num') return t.v;
    switch (t.v) {
      case '(': {
        const v = ternary(depth + 1);
        expectOp(')');
        return v;
      }
      case '-':
        return -unary(depth + 1) | 0;
      case '+':
        return unary(depth + 1);
      case '!':
        return unary(depth + 1) === 0 ? 1 : 0;
      case '~':
        return ~unary(depth + 1);
    }
    return fail(`unexpected '${t.v}' in #if`);
  };
  const binary = (minPrec: number, depth: number): number => {
    let left = unary(depth);
    for (;;) {
      const t = peek();
      if (t === undefined || t.k !== 'op') break;
      const prec = BINARY_PRECEDENCE.get(t.v);
      if (prec === undefined || prec < minPrec) break;
      pos++;
      const right = binary(prec + 1, depth + 1);
      left = applyBinary(t.v, left, right, fail);
    }
    return left;
  };
  const ternary = (depth: number): number => {
    const c = binary(1, depth);
    const t = peek();
    if (t !== undefined && t.k === 'op' && t.v === '?') {
      pos++;
      const a = ternary(depth + 1);
      expectOp(':');
      const b = ternary(depth + 1);
      return c !== 0 ? a : b;
    }
    return c;
  };
  const v = ternary(0);
  if (pos !== toks.length) fail('unexpected tokens at the end of #if');
  return v;
}
