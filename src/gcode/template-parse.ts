/**
 * The syntax of Strata's G-code templates (template-lang.ts runs them): text, `{expression}`, PrusaSlicer's
 * `[name]`, `[name[index]]` and `[name_0]`, and `{if cond}…{elsif cond}…{else}…{endif}` (Cura's `{elif}`
 * too), which nest; a line holding nothing but these tags leaves no line behind (as Cura does).
 * Expressions: numbers, "text" or 'text', true / false (True / False), variables with an optional
 * `[index]`, `( )`, `+ - * / %`, `== != <> < > <= >=`, `=~ /regex/` and `!~`, `and or not` / `&& || !`,
 * `c ? a : b` and Python's `a if c else b`, and the functions template-lang.ts lists. Cura's
 * `{expression, extruder}` reads the extruder number and leaves it (one extruder).
 *
 * A syntax error is a StrataError BAD_SETTING naming the template and the line: `startGcode line 3: …`.
 */
import { StrataError } from '../errors.js';

export type Expr =
  | { k: 'num'; v: number }
  | { k: 'str'; v: string }
  | { k: 'bool'; v: boolean }
  /** A variable; `start`/`end` are its offsets in the template (with the index). */
  | { k: 'var'; name: string; index: Expr | null; start: number; end: number }
  | { k: 'un'; op: '-' | '+' | '!'; a: Expr }
  | { k: 'bin'; op: string; a: Expr; b: Expr }
  | { k: 'match'; a: Expr; re: RegExp; negate: boolean }
  | { k: 'cond'; c: Expr; a: Expr; b: Expr }
  | { k: 'call'; fn: string; args: Expr[] }
  | { k: 'oneOf'; x: Expr; patterns: Array<Expr | RegExp> }
  | { k: 'table'; x: Expr; pairs: Array<[Expr, Expr]> };

export type TemplateNode =
  | { k: 'text'; text: string; line: number }
  /** `{expression}`; `src` is the macro as written. */
  | { k: 'out'; expr: Expr; line: number; src: string }
  /** `[name]`, `[name[index]]`: `index` a number or a variable name. */
  | {
      k: 'legacy';
      name: string;
      index: string | null;
      line: number;
      src: string;
      start: number;
      end: number;
      inComment: boolean;
    }
  | {
      k: 'if';
      branches: Array<{ cond: Expr; body: TemplateNode[]; line: number; src: string }>;
      otherwise: TemplateNode[];
    };

export interface ParsedTemplate {
  name: string;
  source: string;
  nodes: TemplateNode[];
}

const CONTROL = new Set(['if', 'elsif', 'elif', 'else', 'endif']);
const KEYWORDS = new Set([...CONTROL, 'and', 'or', 'not', 'true', 'false', 'True', 'False', 'then']);
/** Functions and how many arguments they take ([least, most]). */
const FUNCTIONS: Readonly<Record<string, readonly [number, number]>> = {
  min: [2, 64],
  max: [2, 64],
  int: [1, 1],
  round: [1, 2],
  abs: [1, 1],
  floor: [1, 1],
  ceil: [1, 1],
  'math.floor': [1, 1],
  'math.ceil': [1, 1],
  digits: [2, 3],
  zdigits: [2, 3],
  is_nil: [1, 1],
  empty: [1, 1],
  size: [1, 1],
};
/** Functions whose argument is a variable, not its value. */
export const ON_VARIABLES = new Set(['is_nil', 'empty', 'size']);

/** A line holding nothing but control tags (and blanks): it leaves no line behind. */
const CONTROL_LINE = /^[ \t]*(?:\{[ \t]*(?:if|elsif|elif|else|endif)\b[^{}\n]*\}[ \t]*)+\r?$/;
const LEGACY = /\[([A-Za-z_][A-Za-z0-9_]*)(?:\[([A-Za-z_][A-Za-z0-9_]*|\d+)\])?\]/y;
const NUMBER = /(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?/y;
const IDENT = /[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*/y;

interface Stop {
  kw: 'elsif' | 'else' | 'endif';
  cond: Expr | null;
  at: number;
  src: string;
}

class Parser {
  pos = 0;
  private inComment = false;
  /** Offsets of characters left out of the text (the blanks and line ends of control-only lines). */
  private readonly dropped: Uint8Array;
  private readonly lineStarts: number[] = [0];
  /** Where the macro being read starts, for messages. */
  private macroStart = -1;

  constructor(
    readonly name: string,
    readonly src: string,
  ) {
    this.dropped = new Uint8Array(src.length);
    for (let i = 0; i < src.length; i++) if (src[i] === '\n') this.lineStarts.push(i + 1);
    for (let l = 0; l < this.lineStarts.length; l++) {
      const from = this.lineStarts[l]!;
      const next = this.lineStarts[l + 1];
      const to = next === undefined ? src.length : next - 1;
      if (!CONTROL_LINE.test(src.slice(from, to))) continue;
      let depth = 0;
      for (let i = from; i < to; i++) {
        const c = src[i];
        if (c === '{') depth++;
        else if (c === '}') depth--;
        else if (depth === 0) this.dropped[i] = 1;
      }
      if (next !== undefined) this.dropped[to] = 1;
    }
  }

  lineAt(offset: number): number {
    let lo = 0;
    let hi = this.lineStarts.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (this.lineStarts[mid]! <= offset) lo = mid;
      else hi = mid - 1;
    }
    return lo + 1;
  }

  /** The macro starting at `start` as written (up to its closing brace, shortened). */
  macroText(start: number): string {
    const close = this.src.indexOf('}', start);
    const end = close < 0 ? this.src.length : close + 1;
    const text = this.src.slice(start, end).replace(/\s+/g, ' ');
    return text.length > 80 ? text.slice(0, 77) + '…' : text;
  }

  fail(at: number, problem: string): never {
    const where = this.macroStart >= 0 ? ` in ${this.macroText(this.macroStart)}` : '';
    throw new StrataError('BAD_SETTING', `${this.name} line ${this.lineAt(at)}: ${problem}${where}`);
  }

  parseNodes(inIf: boolean): { nodes: TemplateNode[]; stop?: Stop } {
    const { src } = this;
    const nodes: TemplateNode[] = [];
    let text = '';
    let textStart = this.pos;
    const flush = () => {
      if (text) nodes.push({ k: 'text', text, line: this.lineAt(textStart) });
      text = '';
    };
    while (this.pos < src.length) {
      const at = this.pos;
      const c = src[at]!;
      if (this.dropped[at]) {
        if (c === '\n') this.inComment = false;
        this.pos++;
        continue;
      }
      if (c === '{') {
        flush();
        const r = this.parseMacro(inIf);
        this.macroStart = -1;
        textStart = this.pos;
        if (r.stop) return { nodes, stop: r.stop };
        nodes.push(r.node!);
        continue;
      }
      if (c === '[') {
        LEGACY.lastIndex = at;
        const m = LEGACY.exec(src);
        if (m) {
          flush();
          this.pos = LEGACY.lastIndex;
          nodes.push({
            k: 'legacy',
            name: m[1]!,
            index: m[2] ?? null,
            line: this.lineAt(at),
            src: m[0],
            start: at,
            end: this.pos,
            inComment: this.inComment,
          });
          textStart = this.pos;
          continue;
        }
      }
      if (c === '}') this.fail(at, 'a "}" with no "{" before it');
      if (c === ';') this.inComment = true;
      else if (c === '\n') this.inComment = false;
      if (!text) textStart = at;
      text += c;
      this.pos++;
    }
    flush();
    return { nodes };
  }

  private parseMacro(inIf: boolean): { node?: TemplateNode; stop?: Stop } {
    const start = this.pos;
    this.macroStart = start;
    this.pos++;
    this.skip();
    const kw = this.controlWord();
    if (kw === 'if') {
      this.pos += 2;
      const cond = this.expression();
      this.close();
      return { node: this.parseIf(cond, start) };
    }
    if (kw !== undefined) {
      if (!inIf) this.fail(start, `{${kw}} with no {if} before it`);
      this.pos += kw.length;
      const cond = kw === 'elsif' || kw === 'elif' ? this.expression() : null;
      this.close();
      return {
        stop: {
          kw: kw === 'elif' ? 'elsif' : (kw as Stop['kw']),
          cond,
          at: start,
          src: this.src.slice(start, this.pos),
        },
      };
    }
    if (this.src[this.pos] === '}') this.fail(start, 'an empty {}');
    const expr = this.expression();
    this.skip();
    // Cura's {key, extruder}: one extruder here, so the number is read and not needed
    if (this.src[this.pos] === ',') {
      this.pos++;
      this.expression();
    }
    this.close();
    const node: TemplateNode = { k: 'out', expr, line: this.lineAt(start), src: this.src.slice(start, this.pos) };
    this.macroStart = -1;
    return { node };
  }

  private parseIf(cond: Expr, start: number): TemplateNode {
    const ifSrc = this.src.slice(start, this.pos);
    this.macroStart = -1;
    type Branch = { cond: Expr; body: TemplateNode[]; line: number; src: string };
    const branches: Branch[] = [];
    let otherwise: TemplateNode[] = [];
    let current: Branch | null = { cond, body: [], line: this.lineAt(start), src: ifSrc };
    for (;;) {
      const r = this.parseNodes(true);
      this.macroStart = -1;
      if (!r.stop) this.fail(start, `${ifSrc} has no {endif}`);
      if (current) {
        current.body = r.nodes;
        branches.push(current);
      } else otherwise = r.nodes;
      if (r.stop.kw === 'endif') break;
      if (!current) this.fail(r.stop.at, `${r.stop.src} after {else}`);
      current =
        r.stop.kw === 'else' ? null : { cond: r.stop.cond!, body: [], line: this.lineAt(r.stop.at), src: r.stop.src };
    }
    return { k: 'if', branches, otherwise };
  }

  private controlWord(): string | undefined {
    IDENT.lastIndex = this.pos;
    const m = IDENT.exec(this.src);
    return m && CONTROL.has(m[0]) ? m[0] : undefined;
  }

  private close(): void {
    this.skip();
    if (this.src[this.pos] !== '}') {
      if (this.pos >= this.src.length) this.fail(this.macroStart, 'no closing "}"');
      this.fail(this.pos, `unexpected "${this.src.slice(this.pos, this.pos + 12).split('\n')[0]}" (expected "}")`);
    }
    this.pos++;
  }

  private skip(): void {
    const { src } = this;
    while (
      this.pos < src.length &&
      (src[this.pos] === ' ' || src[this.pos] === '\t' || src[this.pos] === '\n' || src[this.pos] === '\r')
    )
      this.pos++;
  }

  private peek(text: string): boolean {
    this.skip();
    return this.src.startsWith(text, this.pos);
  }

  private eat(text: string): boolean {
    if (!this.peek(text)) return false;
    this.pos += text.length;
    return true;
  }

  /** The keyword `word` next (not the start of a longer name). */
  private eatWord(word: string): boolean {
    this.skip();
    IDENT.lastIndex = this.pos;
    const m = IDENT.exec(this.src);
    if (!m || m[0] !== word) return false;
    this.pos += word.length;
    return true;
  }

  private expect(text: string): void {
    if (!this.eat(text)) this.unexpected(`"${text}"`);
  }

  private unexpected(wanted: string): never {
    this.skip();
    if (this.pos >= this.src.length || this.src[this.pos] === '}')
      this.fail(this.pos, `the expression ends where ${wanted} was expected`);
    this.fail(this.pos, `unexpected "${this.src.slice(this.pos, this.pos + 12).split('\n')[0]}" (expected ${wanted})`);
  }

  expression(): Expr {
    const c = this.or();
    if (this.eat('?')) {
      const a = this.expression();
      this.expect(':');
      return { k: 'cond', c, a, b: this.expression() };
    }
    if (this.eatWord('if')) {
      const cond = this.or();
      if (!this.eatWord('else')) this.unexpected('"else"');
      return { k: 'cond', c: cond, a: c, b: this.expression() };
    }
    return c;
  }

  private or(): Expr {
    let a = this.and();
    while (this.eat('||') || this.eatWord('or')) a = { k: 'bin', op: 'or', a, b: this.and() };
    return a;
  }

  private and(): Expr {
    let a = this.equality();
    while (this.eat('&&') || this.eatWord('and')) a = { k: 'bin', op: 'and', a, b: this.equality() };
    return a;
  }

  private equality(): Expr {
    let a = this.relational();
    for (;;) {
      if (this.eat('==')) a = { k: 'bin', op: '==', a, b: this.relational() };
      else if (this.eat('!=') || this.eat('<>')) a = { k: 'bin', op: '!=', a, b: this.relational() };
      else if (this.eat('=~')) a = { k: 'match', a, re: this.regex(), negate: false };
      else if (this.eat('!~')) a = { k: 'match', a, re: this.regex(), negate: true };
      else if (this.peek('=')) this.fail(this.pos, 'a single "=" (compare with "==")');
      else return a;
    }
  }

  private relational(): Expr {
    let a = this.additive();
    for (;;) {
      if (this.peek('<>')) return a;
      const op = this.eat('<=') ? '<=' : this.eat('>=') ? '>=' : this.eat('<') ? '<' : this.eat('>') ? '>' : undefined;
      if (!op) return a;
      a = { k: 'bin', op, a, b: this.additive() };
    }
  }

  private additive(): Expr {
    let a = this.multiplicative();
    for (;;) {
      const op = this.eat('+') ? '+' : this.eat('-') ? '-' : undefined;
      if (!op) return a;
      a = { k: 'bin', op, a, b: this.multiplicative() };
    }
  }

  private multiplicative(): Expr {
    let a = this.unary();
    for (;;) {
      const op = this.eat('*') ? '*' : this.eat('/') ? '/' : this.eat('%') ? '%' : undefined;
      if (!op) return a;
      a = { k: 'bin', op, a, b: this.unary() };
    }
  }

  private unary(): Expr {
    if (this.eat('-')) return { k: 'un', op: '-', a: this.unary() };
    if (this.eat('+')) return { k: 'un', op: '+', a: this.unary() };
    if (this.peek('!') && !this.peek('!=') && !this.peek('!~')) {
      this.pos++;
      return { k: 'un', op: '!', a: this.unary() };
    }
    if (this.eatWord('not')) return { k: 'un', op: '!', a: this.unary() };
    return this.primary();
  }

  private primary(): Expr {
    this.skip();
    const { src } = this;
    const at = this.pos;
    const c = src[at];
    if (c === '(') {
      this.pos++;
      const e = this.expression();
      this.expect(')');
      return e;
    }
    if (c === '"' || c === "'") return { k: 'str', v: this.string(c) };
    NUMBER.lastIndex = at;
    const n = NUMBER.exec(src);
    if (n) {
      this.pos = NUMBER.lastIndex;
      return { k: 'num', v: Number(n[0]) };
    }
    IDENT.lastIndex = at;
    const id = IDENT.exec(src);
    if (!id) this.unexpected('a value');
    const name = id[0];
    if (name === 'true' || name === 'True' || name === 'false' || name === 'False') {
      this.pos += name.length;
      return { k: 'bool', v: name === 'true' || name === 'True' };
    }
    if (KEYWORDS.has(name)) this.fail(at, `"${name}" where a value was expected`);
    this.pos += name.length;
    if (this.peek('(')) return this.call(name, at);
    if (name.includes('.')) this.fail(at, `"${name}" is not a variable`);
    let index: Expr | null = null;
    if (this.eat('[')) {
      index = this.expression();
      this.expect(']');
    }
    return { k: 'var', name, index, start: at, end: this.pos };
  }

  private call(fn: string, at: number): Expr {
    this.pos++; // (
    if (fn === 'one_of') {
      const x = this.expression();
      const patterns: Array<Expr | RegExp> = [];
      while (this.eat(',')) patterns.push(this.peek('/') ? this.regex() : this.expression());
      this.expect(')');
      return { k: 'oneOf', x, patterns };
    }
    if (fn === 'interpolate_table') {
      const x = this.expression();
      const pairs: Array<[Expr, Expr]> = [];
      while (this.eat(',')) {
        this.expect('(');
        const px = this.expression();
        this.expect(',');
        const py = this.expression();
        this.expect(')');
        pairs.push([px, py]);
      }
      this.expect(')');
      if (pairs.length === 0) this.fail(at, 'interpolate_table() needs at least one (x, y) pair');
      return { k: 'table', x, pairs };
    }
    const arity = FUNCTIONS[fn];
    if (!arity) this.fail(at, `unknown function ${fn}()`);
    const args: Expr[] = [];
    if (!this.peek(')')) {
      do args.push(this.expression());
      while (this.eat(','));
    }
    this.expect(')');
    if (args.length < arity[0] || args.length > arity[1]) {
      const want =
        arity[0] === arity[1] ? `${arity[0]}` : arity[1] > 3 ? `at least ${arity[0]}` : `${arity[0]} or ${arity[1]}`;
      this.fail(at, `${fn}() takes ${want} argument${want === '1' ? '' : 's'}, not ${args.length}`);
    }
    if (ON_VARIABLES.has(fn) && args[0]!.k !== 'var') this.fail(at, `${fn}() takes a variable`);
    return { k: 'call', fn, args };
  }

  private string(quote: string): string {
    const { src } = this;
    const at = this.pos;
    let out = '';
    this.pos++;
    while (this.pos < src.length && src[this.pos] !== quote) {
      if (src[this.pos] === '\\' && this.pos + 1 < src.length) this.pos++;
      out += src[this.pos];
      this.pos++;
    }
    if (this.pos >= src.length) this.fail(at, 'text with no closing quote');
    this.pos++;
    return out;
  }

  private regex(): RegExp {
    this.skip();
    const { src } = this;
    const at = this.pos;
    if (src[at] !== '/') this.unexpected('a /regular expression/');
    let body = '';
    this.pos++;
    while (this.pos < src.length && src[this.pos] !== '/') {
      if (src[this.pos] === '\\' && this.pos + 1 < src.length) {
        body += src[this.pos + 1] === '/' ? '/' : src.slice(this.pos, this.pos + 2);
        this.pos += 2;
        continue;
      }
      body += src[this.pos];
      this.pos++;
    }
    if (this.pos >= src.length) this.fail(at, 'a regular expression with no closing "/"');
    this.pos++;
    try {
      return new RegExp(`^(?:${body})$`);
    } catch (e) {
      this.fail(at, `/${body}/ is not a regular expression (${(e as Error).message})`);
    }
  }
}

/** Parse a template (the setting `name`, for messages). Throws StrataError BAD_SETTING for a syntax error. */
export function parseTemplate(name: string, source: string): ParsedTemplate {
  const p = new Parser(name, source);
  const { nodes } = p.parseNodes(false);
  return { name, source, nodes };
}

/** Every variable a template refers to, in every branch: name, index and where, in order. */
export interface VariableUse {
  name: string;
  /** `[name]` rather than inside `{…}`. */
  legacy: boolean;
  /** The index as written (an expression, or a legacy index word). */
  index: Expr | string | null;
  start: number;
  end: number;
  line: number;
  /** The macro it appears in, as written. */
  src: string;
  inComment: boolean;
}

export function variableUses(t: ParsedTemplate): VariableUse[] {
  const uses: VariableUse[] = [];
  const inExpr = (e: Expr | RegExp, line: number, src: string): void => {
    if (e instanceof RegExp) return;
    switch (e.k) {
      case 'var':
        uses.push({
          name: e.name,
          legacy: false,
          index: e.index,
          start: e.start,
          end: e.end,
          line,
          src,
          inComment: false,
        });
        if (e.index) inExpr(e.index, line, src);
        return;
      case 'un':
        return inExpr(e.a, line, src);
      case 'bin':
        inExpr(e.a, line, src);
        return inExpr(e.b, line, src);
      case 'match':
        return inExpr(e.a, line, src);
      case 'cond':
        inExpr(e.c, line, src);
        inExpr(e.a, line, src);
        return inExpr(e.b, line, src);
      case 'call':
        for (const a of e.args) inExpr(a, line, src);
        return;
      case 'oneOf':
        inExpr(e.x, line, src);
        for (const p of e.patterns) inExpr(p, line, src);
        return;
      case 'table':
        inExpr(e.x, line, src);
        for (const [x, y] of e.pairs) {
          inExpr(x, line, src);
          inExpr(y, line, src);
        }
        return;
      default:
        return;
    }
  };
  const inNodes = (nodes: readonly TemplateNode[]): void => {
    for (const n of nodes) {
      if (n.k === 'out') inExpr(n.expr, n.line, n.src);
      else if (n.k === 'legacy') {
        uses.push({
          name: n.name,
          legacy: true,
          index: n.index,
          start: n.start,
          end: n.end,
          line: n.line,
          src: n.src,
          inComment: n.inComment,
        });
        if (n.index !== null && !/^\d+$/.test(n.index))
          uses.push({
            name: n.index,
            legacy: true,
            index: null,
            start: n.start,
            end: n.end,
            line: n.line,
            src: n.src,
            inComment: false,
          });
      } else if (n.k === 'if') {
        for (const b of n.branches) {
          inExpr(b.cond, b.line, b.src);
          inNodes(b.body);
        }
        inNodes(n.otherwise);
      }
    }
  };
  inNodes(t.nodes);
  return uses;
}

/** A `[word]` that is not a variable is text when it is in a comment or is not written like a variable name. */
export function legacyIsText(use: { name: string; inComment: boolean }): boolean {
  return use.inComment || !/^[a-z][a-z0-9_]*$/.test(use.name);
}
