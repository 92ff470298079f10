/**
 * A GLSL preprocessor that keeps line numbers: comments, directives and inactive #if branches become
 * blank lines, so every token of the output sits on the line it had in the source (errors can name
 * it). Supports #define (object- and function-like), #undef, #ifdef, #ifndef, #if, #elif, #else,
 * #endif, #error; ignores #version, #extension, #pragma, #line. It also recognises IceSL's
 * one-line UI parameters, `uniform float ui_NAME = VALUE; // tooltip`, records them and rewrites the
 * line to a plain `uniform float ui_NAME;`.
 */
import { badShader } from './shader-error.js';
import { evalIfExpression } from './preprocess-expr.js';

export type UiParamType = 'bool' | 'int' | 'float';

/** A `ui_` parameter as declared in the shader source. */
export interface UiParamDecl {
  name: string;
  type: UiParamType;
  defaultValue: number | boolean;
  tooltip: string;
  line: number;
}

export interface Preprocessed {
  /** The source with the same number of lines, ready for the parser. */
  text: string;
  uiParams: UiParamDecl[];
}

interface Macro {
  params?: string[];
  body: string;
}

interface CondFrame {
  /** Whether lines in the current branch are kept. */
  active: boolean;
  /** Whether some branch of this #if chain was already taken. */
  taken: boolean;
  /** Whether the enclosing region is active. */
  parentActive: boolean;
  sawElse: boolean;
  line: number;
}

/** Largest preprocessed output accepted, characters (guards against macro bombs). */
const MAX_OUTPUT = 200_000;
const MAX_DEPTH = 64;
/** Most macro invocations expanded in one shader. */
const MAX_MACRO_STEPS = 200_000;
/** Lines a function-like macro invocation may span. */
const MAX_JOINED_LINES = 32;

interface ExpandState {
  macros: Map<string, Macro>;
  size: number;
  /** Macro invocations so far (bounds expansions that produce little text). */
  steps: number;
  fileName: string;
  line: number;
}

class NeedMoreInput extends Error {}

/** Remove comments, keeping newlines; returns the code and each line's `//` comment text. */
function stripComments(src: string): { code: string; lineComments: Map<number, string> } {
  const lineComments = new Map<number, string>();
  let out = '';
  let line = 0;
  let i = 0;
  const n = src.length;
  while (i < n) {
    const ch = src[i];
    if (ch === '/' && src[i + 1] === '/') {
      let j = i + 2;
      while (j < n && src[j] !== '\n') j++;
      lineComments.set(line, src.slice(i + 2, j));
      out += ' ';
      i = j;
    } else if (ch === '/' && src[i + 1] === '*') {
      const end = src.indexOf('*/', i + 2);
      const stop = end < 0 ? n : end + 2;
      out += ' ';
      for (let j = i; j < stop; j++) {
        if (src[j] === '\n') {
          out += '\n';
          line++;
        }
      }
      i = stop;
    } else {
      if (ch === '\n') line++;
      out += ch;
      i++;
    }
  }
  return { code: out, lineComments };
}

const isIdentStart = (c: string | undefined) => c !== undefined && /[A-Za-z_]/.test(c);
const isIdentChar = (c: string | undefined) => c !== undefined && /[A-Za-z0-9_]/.test(c);
const isDigit = (c: string | undefined) => c !== undefined && c >= '0' && c <= '9';

/** Index just past a preprocessing number starting at i. */
function scanNumber(src: string, i: number): number {
  let j = i;
  while (j < src.length) {
    const c = src[j];
    if (isIdentChar(c) || c === '.') j++;
    else if ((c === '+' || c === '-') && /[eE]/.test(src[j - 1] ?? '') && !/^0[xX]/.test(src.slice(i, j))) j++;
    else break;
  }
  return j;
}

/** Split `( a, (b, c), d )` starting at the '(' index; returns the raw arguments and the ')' index. */
function splitArgs(src: string, open: number): { args: string[]; close: number } {
  const args: string[] = [];
  let depth = 0;
  let start = open + 1;
  for (let i = open; i < src.length; i++) {
    const c = src[i];
    if (c === '(') depth++;
    else if (c === ')') {
      depth--;
      if (depth === 0) {
        args.push(src.slice(start, i));
        return { args, close: i };
      }
    } else if (c === ',' && depth === 1) {
      args.push(src.slice(start, i));
      start = i + 1;
    }
  }
  throw new NeedMoreInput();
}

function substituteParams(body: string, params: readonly string[], args: readonly string[]): string {
  let out = '';
  let i = 0;
  while (i < body.length) {
    const c = body[i];
    if (isIdentStart(c)) {
      let j = i + 1;
      while (isIdentChar(body[j])) j++;
      const name = body.slice(i, j);
      const k = params.indexOf(name);
      out += k >= 0 ? args[k] : name;
      i = j;
    } else if (isDigit(c)) {
      const j = scanNumber(body, i);
      out += body.slice(i, j);
      i = j;
    } else {
      out += c;
      i++;
    }
  }
  return out;
}

function expand(src: string, hidden: readonly string[], st: ExpandState): string {
  if (hidden.length > MAX_DEPTH) throw badShader(st.fileName, st.line, 'macros nested too deeply');
  let out = '';
  let i = 0;
  while (i < src.length) {
    const c = src[i];
    if (isIdentStart(c)) {
      let j = i + 1;
      while (isIdentChar(src[j])) j++;
      const name = src.slice(i, j);
      i = j;
      if (name === '__LINE__') {
        out += String(st.line);
        continue;
      }
      const m = st.macros.get(name);
      if (m === undefined || hidden.includes(name)) {
        out += name;
        continue;
      }
      if (++st.steps > MAX_MACRO_STEPS) throw badShader(st.fileName, st.line, 'macro expansion is too complex');
      if (m.params === undefined) {
        out += expand(m.body, [...hidden, name], st);
      } else {
        let k = j;
        while (k < src.length && /\s/.test(src[k])) k++;
        if (k >= src.length) throw new NeedMoreInput();
        if (src[k] !== '(') {
          out += name;
          continue;
        }
        const { args, close } = splitArgs(src, k);
        const raw = m.params.length === 0 && args.length === 1 && args[0].trim() === '' ? [] : args;
        if (raw.length !== m.params.length) {
          throw badShader(
            st.fileName,
            st.line,
            `macro ${name} takes ${m.params.length} argument(s), got ${raw.length}`,
          );
        }
        const expandedArgs = raw.map((a) => expand(a.trim(), hidden, st));
        out += expand(substituteParams(m.body, m.params, expandedArgs), [...hidden, name], st);
        i = close + 1;
      }
    } else if (isDigit(c) || (c === '.' && isDigit(src[i + 1]))) {
      const j = scanNumber(src, i);
      out += src.slice(i, j);
      i = j;
    } else {
      out += c;
      i++;
    }
    if (out.length + st.size > MAX_OUTPUT) throw badShader(st.fileName, st.line, 'macro expansion is too large');
  }
  return out;
}

function parseDefine(rest: string, fileName: string, line: number): { name: string; macro: Macro } {
  const m = /^([A-Za-z_][A-Za-z0-9_]*)(\(([^)]*)\))?(.*)$/s.exec(rest);
  if (!m) throw badShader(fileName, line, '#define needs a macro name');
  const name = m[1];
  if (name === 'defined' || name.startsWith('GL_')) throw badShader(fileName, line, `cannot #define ${name}`);
  if (m[2] !== undefined) {
    const list = m[3].trim();
    const params = list === '' ? [] : list.split(',').map((p) => p.trim());
    for (const p of params) {
      if (!/^[A-Za-z_][A-Za-z0-9_]*$/.test(p))
        throw badShader(fileName, line, `bad macro parameter '${p.slice(0, 40)}'`);
    }
    return { name, macro: { params, body: m[4].trim() } };
  }
  return { name, macro: { body: m[4].trim() } };
}

const UI_LINE = /^\s*uniform\s+(bool|int|float)\s+(ui_[A-Za-z0-9_]*)\s*=(.*)$/s;

/** The value text of a ui_ line: everything after '=', without a trailing ';'. */
function uiValueText(rest: string): string | undefined {
  let t = rest.trim();
  if (t.endsWith(';')) t = t.slice(0, -1).trim();
  return t.includes(';') ? undefined : t;
}

function parseUiDefault(type: UiParamType, text: string): number | boolean | undefined {
  const t = text.trim();
  if (type === 'bool') return t === 'true' ? true : t === 'false' ? false : undefined;
  if (type === 'int') {
    if (!/^[+-]?\d+$/.test(t)) return undefined;
    const v = Number(t);
    return Number.isSafeInteger(v) && Math.abs(v) <= 2147483647 ? v : undefined;
  }
  const m = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?[fF]?$/.exec(t);
  if (!m) return undefined;
  const v = Number(t.replace(/[fF]$/, ''));
  return Number.isFinite(v) ? v : undefined;
}

/** Preprocess GLSL source; throws StrataError('BAD_SHADER') naming the line on errors. */
export function preprocessGlsl(
  source: string,
  fileName: string,
  predefined: ReadonlyMap<string, string> = new Map(),
): Preprocessed {
  const { code, lineComments } = stripComments(source.replace(/\r\n?/g, '\n'));
  const lines = code.split('\n');
  const out: string[] = new Array<string>(lines.length).fill('');
  const macros = new Map<string, Macro>();
  macros.set('__VERSION__', { body: '430' });
  macros.set('GL_core_profile', { body: '1' });
  for (const [k, v] of predefined) macros.set(k, { body: v });
  const st: ExpandState = { macros, size: 0, steps: 0, fileName, line: 0 };
  const stack: CondFrame[] = [];
  const uiParams: UiParamDecl[] = [];
  const active = () => stack.length === 0 || stack[stack.length - 1].active;

  // Line continuations: join, keep the line count.
  for (let i = 0; i < lines.length; i++) {
    if (!lines[i].endsWith('\\')) continue;
    const parts = [lines[i].slice(0, -1)];
    let j = i;
    while (j + 1 < lines.length) {
      j++;
      const next = lines[j];
      lines[j] = '';
      if (next.endsWith('\\')) parts.push(next.slice(0, -1));
      else {
        parts.push(next);
        break;
      }
    }
    lines[i] = parts.join('');
    i = j;
  }

  for (let i = 0; i < lines.length; i++) {
    const lineNo = i + 1;
    st.line = lineNo;
    const raw = lines[i];
    const dir = /^\s*#\s*([A-Za-z_]*)\s*(.*)$/s.exec(raw);
    if (dir) {
      const name = dir[1];
      const rest = dir[2].trim();
      switch (name) {
        case 'ifdef':
        case 'ifndef': {
          const id = /^[A-Za-z_][A-Za-z0-9_]*/.exec(rest)?.[0];
          if (id === undefined) throw badShader(fileName, lineNo, `#${name} needs a macro name`);
          const on = active() && macros.has(id) === (name === 'ifdef');
          stack.push({ active: on, taken: on, parentActive: active(), sawElse: false, line: lineNo });
          break;
        }
        case 'if': {
          const parent = active();
          const on = parent && evalIfExpression(rest, st.macros, (t) => expand(t, [], st), fileName, lineNo) !== 0;
          stack.push({ active: on, taken: on, parentActive: parent, sawElse: false, line: lineNo });
          break;
        }
        case 'elif': {
          const f = stack[stack.length - 1];
          if (f === undefined || f.sawElse) throw badShader(fileName, lineNo, '#elif without #if');
          if (f.taken || !f.parentActive) f.active = false;
          else {
            f.active = evalIfExpression(rest, st.macros, (t) => expand(t, [], st), fileName, lineNo) !== 0;
            f.taken = f.active;
          }
          break;
        }
        case 'else': {
          const f = stack[stack.length - 1];
          if (f === undefined || f.sawElse) throw badShader(fileName, lineNo, '#else without #if');
          f.sawElse = true;
          f.active = f.parentActive && !f.taken;
          f.taken = true;
          break;
        }
        case 'endif':
          if (stack.pop() === undefined) throw badShader(fileName, lineNo, '#endif without #if');
          break;
        default:
          if (!active()) break;
          if (name === 'define') {
            const d = parseDefine(rest, fileName, lineNo);
            macros.set(d.name, d.macro);
          } else if (name === 'undef') {
            const id = /^[A-Za-z_][A-Za-z0-9_]*/.exec(rest)?.[0];
            if (id !== undefined) macros.delete(id);
          } else if (name === 'error') {
            throw badShader(fileName, lineNo, `#error ${rest.slice(0, 200)}`);
          } else if (name === 'include') {
            throw badShader(fileName, lineNo, '#include is not supported');
          } else if (
            name === 'version' ||
            name === 'extension' ||
            name === 'pragma' ||
            name === 'line' ||
            name === ''
          ) {
            // Ignored: Strata compiles one dialect.
          } else {
            throw badShader(fileName, lineNo, `unknown directive #${name.slice(0, 40)}`);
          }
      }
      continue;
    }
    if (!active()) continue;

    const ui = UI_LINE.exec(raw);
    const uiText = ui ? uiValueText(ui[3]) : undefined;
    if (ui && uiText !== undefined) {
      const type = ui[1] as UiParamType;
      const value = parseUiDefault(type, expand(uiText, [], st));
      if (value === undefined)
        throw badShader(fileName, lineNo, `${ui[2]}: default value '${uiText.slice(0, 40)}' is not a ${type}`);
      let tooltip = (lineComments.get(i) ?? '').trim();
      if (tooltip.endsWith(';')) tooltip = tooltip.slice(0, -1).trim();
      uiParams.push({ name: ui[2], type, defaultValue: value, tooltip, line: lineNo });
      out[i] = `uniform ${type} ${ui[2]};`;
      continue;
    }

    // Expand macros; a function-like invocation may continue on the following lines.
    let text = raw;
    let joined = i;
    for (;;) {
      try {
        out[i] = expand(text, [], st);
        break;
      } catch (e) {
        if (!(e instanceof NeedMoreInput)) throw e;
        if (joined + 1 >= lines.length || joined - i >= MAX_JOINED_LINES || /^\s*#/.test(lines[joined + 1])) {
          // Not a call after all (or unterminated): leave the text unexpanded at the end.
          out[i] = expandTolerant(text, st);
          break;
        }
        joined++;
        text += ' ' + lines[joined];
        lines[joined] = '';
      }
    }
    // Joined lines stay as blank lines, so the following lines keep their numbers.
    st.size += out[i].length;
  }
  if (stack.length > 0) throw badShader(fileName, stack[stack.length - 1].line, '#if without #endif');
  const text = out.map(mangleHazards).join('\n');
  return { text, uiParams };
}

/**
 * Names of Object.prototype members break the parser's scope tables (plain objects). GLSL reserves
 * identifiers containing '__', so appending `__s` cannot clash with a legal user identifier.
 */
const HAZARDS =
  /(?<![A-Za-z0-9_])(constructor|__proto__|toString|toLocaleString|valueOf|hasOwnProperty|isPrototypeOf|propertyIsEnumerable|__defineGetter__|__defineSetter__|__lookupGetter__|__lookupSetter__)(?![A-Za-z0-9_])/g;

function mangleHazards(line: string): string {
  return line.replace(HAZARDS, '$1__s');
}

/** The shader's own spelling of an identifier (undoes mangleHazards) for messages. */
export function unmangle(name: string): string {
  return name.replace(/__s$/, '');
}

/** Expansion that treats a function-like macro name without arguments as a plain identifier. */
function expandTolerant(src: string, st: ExpandState): string {
  const saved = st.macros;
  const onlyObjects = new Map<string, Macro>();
  for (const [k, v] of saved) if (v.params === undefined) onlyObjects.set(k, v);
  st.macros = onlyObjects;
  try {
    return expand(src, [], st);
  } finally {
    st.macros = saved;
  }
}
