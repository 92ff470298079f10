/**
 * The template language of start, end, layer-change, colour-change and pause G-code: one reader for
 * Strata's `{key}`, PrusaSlicer's and OrcaSlicer's macros and Cura's `{key}` / `{key, extruder}`.
 * template-parse.ts reads a template (its syntax is described there); this runs it.
 *
 * - Text is written as it stands; `{expression}` writes the expression's value and `[name]` a variable;
 *   `{if}` keeps the first branch whose condition holds.
 * - Functions: `min(a, b…)`, `max`, `int` (towards zero), `round(x)` / `round(x, digits)`, `abs`,
 *   `floor` / `ceil` (also `math.floor` / `math.ceil`), `digits(x, width[, decimals])`, `zdigits` (zero
 *   padded), `is_nil(var)`, `empty(var)`, `size(var)`, `one_of(x, "text", /regex/…)` and
 *   `interpolate_table(x, (x0, y0), (x1, y1)…)` (held at the ends outside the table).
 * - `+` adds numbers and joins text; comparisons compare numbers (equal within 1e-9, TEMPLATE_NUMBER_EPS) or, where text is
 *   involved, text; `=~` matches the whole text. Conditions take booleans, numbers (not 0) and text (not
 *   empty). `/` divides exactly, as Cura's Python does (PrusaSlicer divides two whole numbers as whole
 *   numbers: `int(a / b)` gives that).
 * - Values are written as numbers with up to 5 decimals and no trailing zeros, booleans as 1 / 0, text as
 *   it is.
 *
 * A template is parsed once (`parseTemplate`) and run as often as needed (`runTemplate`). Every problem
 * (an unknown variable, a value of the wrong kind, a brace left in a line) is a StrataError BAD_SETTING
 * naming the template and the line: `startGcode line 3: …`.
 */
import { StrataError } from '../errors.js';
import { compact } from './format.js';
import { legacyIsText, ON_VARIABLES, type Expr, type ParsedTemplate, type TemplateNode } from './template-parse.js';
import { TEMPLATE_NUMBER_EPS } from '../geometry/tolerances.js';

export type TemplateValue = number | string | boolean;

/** What a running template asks of its caller. */
export interface TemplateContext {
  /** Whether a variable of this name exists. */
  has(name: string): boolean;
  /**
   * The value of a variable that exists (`index` when the template indexes it), or null when it has
   * none (an empty setting). Throws TemplateProblem for an index the variable does not take.
   */
  value(name: string, index: number | undefined): TemplateValue | null;
  /** How many values a variable holds (1 for a single value). */
  size(name: string): number;
}

/** A problem found while running a template, before the line is known. */
export class TemplateProblem extends Error {}
/** A variable that does not exist. */
class UnknownVariable extends TemplateProblem {
  constructor(readonly variable: string) {
    super(`unknown placeholder ${variable}`);
  }
}
/** A variable with no value. */
class NoValue extends TemplateProblem {
  constructor(readonly variable: string) {
    super(`placeholder ${variable} has no value (the setting is empty)`);
  }
}

/** A value as the G-code gets it: numbers compact (5 decimals at most), booleans 1 / 0. */
export function valueText(v: TemplateValue): string {
  if (typeof v === 'number') return compact(v);
  if (typeof v === 'boolean') return v ? '1' : '0';
  return v;
}

const kind = (v: TemplateValue): string =>
  typeof v === 'number' ? 'a number' : typeof v === 'boolean' ? 'a boolean' : 'text';

function truthy(v: TemplateValue): boolean {
  return typeof v === 'boolean' ? v : typeof v === 'number' ? v !== 0 : v !== '';
}

function num(v: TemplateValue, what: string): number {
  if (typeof v !== 'number')
    throw new TemplateProblem(`${what} needs a number, not ${kind(v)}${typeof v === 'string' ? ` ("${v}")` : ''}`);
  return v;
}

function compare(op: string, a: TemplateValue, b: TemplateValue): boolean {
  // -1, 0 or 1: numbers as numbers (equal within TEMPLATE_NUMBER_EPS), text (or text and a value) as text, booleans for (in)equality
  let sign: number;
  if (typeof a === 'number' && typeof b === 'number') sign = Math.abs(a - b) < TEMPLATE_NUMBER_EPS ? 0 : a < b ? -1 : 1;
  else if (typeof a === 'boolean' && typeof b === 'boolean' && (op === '==' || op === '!=')) sign = a === b ? 0 : 1;
  else if (typeof a === 'string' || typeof b === 'string') {
    const x = valueText(a);
    const y = valueText(b);
    sign = x === y ? 0 : x < y ? -1 : 1;
  } else throw new TemplateProblem(`cannot compare ${kind(a)} with ${kind(b)} by ${op}`);
  switch (op) {
    case '==':
      return sign === 0;
    case '!=':
      return sign !== 0;
    case '<':
      return sign < 0;
    case '>':
      return sign > 0;
    case '<=':
      return sign <= 0;
    default:
      return sign >= 0;
  }
}

function formatDigits(x: number, width: number, decimals: number | undefined, zeros: boolean): string {
  let text = decimals === undefined ? String(Math.round(x)) : x.toFixed(Math.max(0, Math.min(20, decimals)));
  const w = Math.max(0, Math.min(64, width));
  if (zeros) {
    const negative = text.startsWith('-');
    let digits = negative ? text.slice(1) : text;
    while (digits.length + (negative ? 1 : 0) < w) digits = '0' + digits;
    text = (negative ? '-' : '') + digits;
  } else text = text.padStart(w, ' ');
  return text;
}

function variable(ctx: TemplateContext, name: string, index: number | undefined): TemplateValue {
  if (!ctx.has(name)) throw new UnknownVariable(name);
  const v = ctx.value(name, index);
  if (v === null) throw new NoValue(name);
  return v;
}

function evaluate(e: Expr, ctx: TemplateContext): TemplateValue {
  switch (e.k) {
    case 'num':
    case 'str':
    case 'bool':
      return e.v;
    case 'var': {
      if (!e.index) return variable(ctx, e.name, undefined);
      if (!ctx.has(e.name)) throw new UnknownVariable(e.name);
      const i = num(evaluate(e.index, ctx), `the index of ${e.name}`);
      if (!Number.isInteger(i) || i < 0)
        throw new TemplateProblem(`${e.name}[${valueText(i)}]: an index is a whole number from 0`);
      return variable(ctx, e.name, i);
    }
    case 'un': {
      const a = evaluate(e.a, ctx);
      if (e.op === '!') return !truthy(a);
      const n = num(a, `"${e.op}"`);
      return e.op === '-' ? -n : n;
    }
    case 'bin': {
      if (e.op === 'and') return truthy(evaluate(e.a, ctx)) ? truthy(evaluate(e.b, ctx)) : false;
      if (e.op === 'or') return truthy(evaluate(e.a, ctx)) ? true : truthy(evaluate(e.b, ctx));
      const a = evaluate(e.a, ctx);
      const b = evaluate(e.b, ctx);
      switch (e.op) {
        case '+':
          if (typeof a === 'string' || typeof b === 'string') return valueText(a) + valueText(b);
          return num(a, '"+"') + num(b, '"+"');
        case '-':
          return num(a, '"-"') - num(b, '"-"');
        case '*':
          return num(a, '"*"') * num(b, '"*"');
        case '/':
        case '%': {
          const x = num(a, `"${e.op}"`);
          const y = num(b, `"${e.op}"`);
          if (y === 0) throw new TemplateProblem('division by zero');
          return e.op === '/' ? x / y : x % y;
        }
        default:
          return compare(e.op, a, b);
      }
    }
    case 'match': {
      const a = evaluate(e.a, ctx);
      if (typeof a !== 'string') throw new TemplateProblem(`=~ and !~ match text, not ${kind(a)}`);
      return e.re.test(a) !== e.negate;
    }
    case 'cond':
      return truthy(evaluate(e.c, ctx)) ? evaluate(e.a, ctx) : evaluate(e.b, ctx);
    case 'oneOf': {
      const x = evaluate(e.x, ctx);
      if (typeof x !== 'string') throw new TemplateProblem(`one_of() matches text, not ${kind(x)}`);
      return e.patterns.some((p) => (p instanceof RegExp ? p.test(x) : valueText(evaluate(p, ctx)) === x));
    }
    case 'table': {
      const x = num(evaluate(e.x, ctx), 'interpolate_table()');
      const pts = e.pairs
        .map(
          ([px, py]) =>
            [num(evaluate(px, ctx), 'interpolate_table()'), num(evaluate(py, ctx), 'interpolate_table()')] as const,
        )
        .sort((p, q) => p[0] - q[0]);
      if (x <= pts[0]![0]) return pts[0]![1];
      for (let i = 1; i < pts.length; i++) {
        const [x1, y1] = pts[i]!;
        if (x <= x1) {
          const [x0, y0] = pts[i - 1]!;
          return x1 === x0 ? y1 : y0 + ((y1 - y0) * (x - x0)) / (x1 - x0);
        }
      }
      return pts[pts.length - 1]![1];
    }
    case 'call':
      return call(e.fn, e.args, ctx);
  }
}

function call(fn: string, args: readonly Expr[], ctx: TemplateContext): TemplateValue {
  if (ON_VARIABLES.has(fn)) {
    const v = args[0] as Extract<Expr, { k: 'var' }>;
    if (!ctx.has(v.name)) throw new UnknownVariable(v.name);
    if (fn === 'size') return ctx.size(v.name);
    if (fn === 'empty') return ctx.size(v.name) === 0;
    const index = v.index ? num(evaluate(v.index, ctx), `the index of ${v.name}`) : undefined;
    return ctx.value(v.name, index) === null;
  }
  const values = args.map((a) => evaluate(a, ctx));
  const n = (i: number) => num(values[i]!, `${fn}()`);
  switch (fn) {
    case 'min':
      return Math.min(...values.map((_, i) => n(i)));
    case 'max':
      return Math.max(...values.map((_, i) => n(i)));
    case 'int':
      return Math.trunc(n(0));
    case 'round': {
      if (values.length === 1) return Math.round(n(0));
      const scale = 10 ** Math.max(0, Math.min(9, Math.trunc(n(1))));
      return Math.round(n(0) * scale) / scale;
    }
    case 'abs':
      return Math.abs(n(0));
    case 'floor':
    case 'math.floor':
      return Math.floor(n(0));
    case 'ceil':
    case 'math.ceil':
      return Math.ceil(n(0));
    case 'digits':
    case 'zdigits':
      return formatDigits(n(0), Math.trunc(n(1)), values.length > 2 ? Math.trunc(n(2)) : undefined, fn === 'zdigits');
    default:
      throw new TemplateProblem(`unknown function ${fn}()`);
  }
}

/** One line of a template's output and the template line it came from. */
export interface OutputLine {
  text: string;
  line: number;
}

/**
 * Run a parsed template. Returns its output lines (split at line ends, as written; a final line end
 * leaves no empty line). Throws StrataError BAD_SETTING naming the line for any problem, and for an
 * output line with a brace left in it.
 */
export function runTemplate(t: ParsedTemplate, ctx: TemplateContext): OutputLine[] {
  const out: OutputLine[] = [];
  let current = '';
  let currentLine = 0;
  const write = (text: string, line: number): void => {
    let from = 0;
    for (;;) {
      if (current === '' && currentLine === 0) currentLine = line;
      const nl = text.indexOf('\n', from);
      if (nl < 0) {
        current += text.slice(from);
        return;
      }
      current += text.slice(from, nl);
      out.push({ text: current, line: currentLine || line });
      current = '';
      currentLine = 0;
      from = nl + 1;
      if (from >= text.length) return;
      line += 1;
    }
  };
  const problem = (line: number, src: string, e: unknown): never => {
    if (!(e instanceof TemplateProblem)) throw e;
    // a macro that is just the variable: "unknown placeholder {foo}"; else "… foo in {foo + 1}"
    if (e instanceof UnknownVariable || e instanceof NoValue) {
      const alone = src === `{${e.variable}}` || src === `[${e.variable}]`;
      const what =
        e instanceof UnknownVariable
          ? `unknown placeholder ${alone ? src : e.variable}`
          : `placeholder ${alone ? src : e.variable} has no value (the setting is empty)`;
      throw new StrataError('BAD_SETTING', `${t.name} line ${line}: ${what}${alone ? '' : ` in ${src}`}`);
    }
    throw new StrataError('BAD_SETTING', `${t.name} line ${line}: ${e.message} in ${src}`);
  };
  const run = (nodes: readonly TemplateNode[]): void => {
    for (const n of nodes) {
      switch (n.k) {
        case 'text':
          write(n.text, n.line);
          break;
        case 'out':
          try {
            write(valueText(evaluate(n.expr, ctx)), n.line);
          } catch (e) {
            problem(n.line, n.src, e);
          }
          break;
        case 'legacy':
          try {
            write(legacyValue(n, ctx), n.line);
          } catch (e) {
            problem(n.line, n.src, e);
          }
          break;
        case 'if': {
          let taken: TemplateNode[] = n.otherwise;
          for (const b of n.branches) {
            let yes = false;
            try {
              yes = truthy(evaluate(b.cond, ctx));
            } catch (e) {
              problem(b.line, b.src, e);
            }
            if (yes) {
              taken = b.body;
              break;
            }
          }
          run(taken);
          break;
        }
      }
    }
  };
  run(t.nodes);
  if (current !== '') out.push({ text: current, line: currentLine });
  for (const l of out) {
    if (/[{}]/.test(l.text)) {
      const shown = l.text.trim().length > 60 ? l.text.trim().slice(0, 57) + '…' : l.text.trim();
      throw new StrataError(
        'BAD_SETTING',
        `${t.name} line ${l.line}: "${shown}" still has a brace after its placeholders were filled in`,
      );
    }
  }
  return out;
}

/** The text of `[name]`, `[name[index]]` or `[name_N]`. */
function legacyValue(n: Extract<TemplateNode, { k: 'legacy' }>, ctx: TemplateContext): string {
  if (ctx.has(n.name)) {
    const index =
      n.index === null
        ? undefined
        : /^\d+$/.test(n.index)
          ? Number(n.index)
          : num(variable(ctx, n.index, undefined), `the index of ${n.name}`);
    return valueText(variable(ctx, n.name, index));
  }
  const suffix = /^(.+)_(\d+)$/.exec(n.name);
  if (suffix && n.index === null && ctx.has(suffix[1]!)) return valueText(variable(ctx, suffix[1]!, Number(suffix[2])));
  if (legacyIsText(n)) return n.src;
  throw new UnknownVariable(n.name);
}
