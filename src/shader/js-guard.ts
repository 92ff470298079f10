/**
 * Defence in depth for generated shader code: before the body reaches `new Function`, check that it
 * contains no string, template, regex or escape characters and that every identifier is one the
 * code generator makes (prefix + digits), a fixed keyword, or a math-table key read as `M.key`.
 * The generator never copies shader text into the output, so a failure here is a compiler bug.
 */
import { TABLE_KEYS } from './math-table.js';

const PROLOGUE = '"use strict";\n';
const ALLOWED_CHARS = /^[A-Za-z0-9_ \n;,.(){}[\]=+\-*/%<>!&|^~?:]*$/;
const GENERATED = /^(?:[tvfagu]\d+|L\d+|m_[A-Za-z0-9]+|h_(?:den|noz|lh)|I1|I2|NP|WR|WG|[MRBWESXYZADNTVr])$/;
const KEYWORDS = new Set([
  'let',
  'const',
  'function',
  'return',
  'if',
  'else',
  'for',
  'break',
  'continue',
  'new',
  'switch',
  'case',
  'default',
  'true',
  'false',
]);

/** Throws if the generated body contains anything the generator should never produce. */
export function assertSafeJs(body: string): void {
  if (!body.startsWith(PROLOGUE)) throw new Error('internal: generated code lacks its prologue');
  const rest = body.slice(PROLOGUE.length);
  if (!ALLOWED_CHARS.test(rest)) throw new Error('internal: generated code contains a forbidden character');
  const keys = new Set(TABLE_KEYS);
  const token = /[A-Za-z_][A-Za-z0-9_]*|\d+(?:\.\d+)?(?:e[+-]?\d+)?/g;
  for (let m = token.exec(rest); m !== null; m = token.exec(rest)) {
    const t = m[0];
    if (/^\d/.test(t)) continue;
    if (rest[m.index - 1] === '.') {
      if (rest.slice(m.index - 2, m.index) === 'M.' && keys.has(t)) continue;
      throw new Error('internal: generated code reads a property it should not');
    }
    if (KEYWORDS.has(t) || GENERATED.test(t)) continue;
    throw new Error('internal: generated code names an identifier it should not');
  }
}
