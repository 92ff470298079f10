/**
 * Public API of the shader compiler: compile IceSL infill shader source (GLSL) once, then create
 * instances that evaluate the label (colour key) of `vec4 cellular(vec3 world)` at points in mm.
 */
import { parse } from '@shaderfrog/glsl-parser/index.js';
import { StrataError } from '../errors.js';
import { Ctx } from './compiler-context.js';
import { compileProgram } from './compile-program.js';
import type { EntryKind, UniformSlot } from './compile-program.js';
import { assertSafeJs } from './js-guard.js';
import { makeMathTable } from './math-table.js';
import { preprocessGlsl } from './preprocess.js';
import type { UiParamType } from './preprocess.js';
import { badShader } from './shader-error.js';

/** A `ui_` parameter of an infiller, as IceSL shows it in its UI. */
export interface ShaderParam {
  name: string;
  type: UiParamType;
  default: number | boolean;
  tooltip: string;
}

export type ParamValues = Readonly<Record<string, number | boolean>> | ReadonlyMap<string, number | boolean>;

export interface CompileOptions {
  /** Name used in error messages (default 'shader.glsl'). */
  fileName?: string;
  /** 'cellular' (infill shader, default) or 'density' (`float density(vec3)` density-field shader). */
  entry?: EntryKind;
  /** Loop iterations + function calls allowed per evaluation (default 100 000). */
  evalBudget?: number;
  /** Loop iterations + function calls allowed between resetWork() calls, e.g. per layer (default 2e9). */
  layerBudget?: number;
}

/** What an instance needs from the host for one layer. */
export interface ShaderEnv {
  /** Pass index, 0 … numPasses-1 (default 0). */
  pass?: number;
  /** Overrides of ui_ parameter defaults (names with or without the `ui_` prefix). */
  params?: ParamValues;
  /** Infill density in percent (0–100) at a point in mm; default 20. */
  density?: (x: number, y: number, z: number) => number;
  /** Nozzle diameter, mm (default 0.4). */
  nozzleDiameter?: number;
  /** Layer height, mm (default 0.2). */
  layerHeight?: number;
}

export interface ShaderInstance {
  /** Set pass, parameters and host values; runs the global initialisers. */
  configure(env: ShaderEnv): void;
  /** numPasses declared by the shader (1 if none), after configure(). */
  numPasses(): number;
  /**
   * Label at a point (mm): equal colours give equal labels. For density shaders, the density value.
   * Throws StrataError('LIMIT_EXCEEDED') when the shader exceeds its budgets.
   */
  label(x: number, y: number, z: number): number;
  /** The RGBA colour of the last label() call (cellular shaders returning a vector). */
  lastColor(): [number, number, number, number];
  /** Reset the work counter (call once per layer). */
  resetWork(): void;
  /** Work (loop iterations + calls) since the last reset. */
  work(): number;
}

export interface CompiledShader {
  readonly fileName: string;
  readonly entry: EntryKind;
  readonly params: readonly ShaderParam[];
  /** numPasses when it is a compile-time constant. */
  readonly numPassesConst: number | undefined;
  /** Whether the shader calls density(). */
  readonly usesDensity: boolean;
  readonly warnings: readonly string[];
  /** The generated JavaScript (for inspection and tests). */
  readonly js: string;
  instantiate(): ShaderInstance;
}

export const DEFAULT_EVAL_BUDGET = 100_000;
export const DEFAULT_LAYER_BUDGET = 2_000_000_000;
/** Largest shader source accepted, characters (IceSL shaders are a few kB; the parser is slow on big inputs). */
export const MAX_SOURCE_LENGTH = 256_000;
/** Largest preprocessed code (comments removed, macros expanded) handed to the parser, characters. */
export const MAX_CODE_LENGTH = 100_000;
/** Largest generated code accepted, characters. */
const MAX_JS_LENGTH = 16_000_000;

function parseError(fileName: string, e: unknown): StrataError {
  if (e instanceof StrataError) return e;
  if (e instanceof RangeError) return badShader(fileName, undefined, 'the shader is nested too deeply');
  const err = e as { location?: { start?: { line?: number } }; message?: string };
  const line = err.location?.start?.line;
  const first = String(err.message ?? e)
    .split('\n')[0]
    .replace(/^Error:\s*/, '')
    .slice(0, 300);
  return badShader(fileName, line, `syntax error: ${first}`);
}

/** Find the uniform slot of a parameter given with or without the `ui_` prefix. */
function paramEntries(values: ParamValues | undefined): [string, number | boolean][] {
  if (values === undefined) return [];
  if (values instanceof Map) return [...values.entries()];
  return Object.entries(values as Record<string, number | boolean>);
}

/** Check and convert a parameter value for its declared type. */
export function checkParamValue(
  fileName: string,
  p: { name: string; type: UiParamType },
  v: unknown,
): number | boolean {
  if (p.type === 'bool') {
    if (typeof v === 'boolean') return v;
    if (v === 0 || v === 1) return v === 1;
  } else if (typeof v === 'number' && Number.isFinite(v)) {
    if (p.type === 'float') return v;
    if (Number.isInteger(v) && Math.abs(v) <= 2147483647) return v;
  }
  throw new StrataError(
    'BAD_SETTING',
    `${fileName}: parameter ${p.name} must be ${p.type === 'bool' ? 'true or false' : `a${p.type === 'int' ? 'n integer' : ' number'}`}`,
  );
}

/** Parse a CLI-style value (`--infill-param NAME=VALUE`) for a parameter. */
export function parseParamValue(p: ShaderParam, text: string): number | boolean {
  const t = text.trim().toLowerCase();
  if (p.type === 'bool') {
    if (t === 'true' || t === '1' || t === 'yes' || t === 'on') return true;
    if (t === 'false' || t === '0' || t === 'no' || t === 'off') return false;
    throw new StrataError(
      'BAD_SETTING',
      `infill parameter ${p.name} must be true or false, got '${text.slice(0, 40)}'`,
    );
  }
  const n = Number(t);
  if (t === '' || !Number.isFinite(n) || (p.type === 'int' && !Number.isInteger(n))) {
    throw new StrataError(
      'BAD_SETTING',
      `infill parameter ${p.name} must be a${p.type === 'int' ? 'n integer' : ' number'}, got '${text.slice(0, 40)}'`,
    );
  }
  return n;
}

/** Resolve a user-given parameter name (`scale` or `ui_scale`) to a declared parameter. */
export function findParam(params: readonly ShaderParam[], name: string): ShaderParam | undefined {
  return params.find((p) => p.name === name) ?? params.find((p) => p.name === `ui_${name}`);
}

/** Parse `NAME=VALUE` strings (CLI `--infill-param`) against an infiller's parameters. */
export function parseInfillParams(
  params: readonly ShaderParam[],
  assignments: readonly string[],
): Record<string, number | boolean> {
  const out: Record<string, number | boolean> = {};
  for (const a of assignments) {
    const eq = a.indexOf('=');
    if (eq <= 0) throw new StrataError('BAD_SETTING', `--infill-param expects NAME=VALUE, got '${a.slice(0, 60)}'`);
    const name = a.slice(0, eq).trim();
    const p = findParam(params, name);
    if (p === undefined) {
      const known = params.map((q) => q.name).join(', ') || 'none';
      throw new StrataError('BAD_SETTING', `unknown infill parameter '${name.slice(0, 60)}' (parameters: ${known})`);
    }
    out[p.name] = parseParamValue(p, a.slice(eq + 1));
  }
  return out;
}

function uniformValues(
  fileName: string,
  uniforms: UniformSlot[],
  params: readonly ShaderParam[],
  env: ShaderEnv,
): Float64Array {
  const overrides = new Map<string, number | boolean>();
  for (const [k, v] of paramEntries(env.params)) {
    const p = findParam(params, k);
    if (p === undefined) {
      const known = params.map((q) => q.name).join(', ') || 'none';
      throw new StrataError(
        'BAD_SETTING',
        `${fileName}: unknown infill parameter '${k.slice(0, 60)}' (parameters: ${known})`,
      );
    }
    overrides.set(p.name, checkParamValue(fileName, p, v));
  }
  const out: number[] = [];
  for (const u of uniforms) {
    if (u.kind === 'pass') out.push(env.pass ?? 0);
    else if (u.kind === 'param' && overrides.has(u.name)) {
      const v = overrides.get(u.name) as number | boolean;
      out.push(typeof v === 'boolean' ? (v ? 1 : 0) : v);
    } else for (const d of u.defaults) out.push(typeof d === 'boolean' ? (d ? 1 : 0) : d);
  }
  return Float64Array.from(out);
}

type Factory = (
  table: Readonly<Record<string, unknown>>,
) => [
  (x: number, y: number, z: number) => number,
  (a: Float64Array, d: (x: number, y: number, z: number) => number, n: number, t: number) => void,
  () => number,
  (v: number) => void,
  () => number,
  Float64Array,
];

/** Compile infill shader source. Throws StrataError('BAD_SHADER', 'shader.glsl line N: …'). */
export function compileShader(source: string, options: CompileOptions = {}): CompiledShader {
  const fileName = options.fileName ?? 'shader.glsl';
  const entry: EntryKind = options.entry ?? 'cellular';
  const evalBudget = Math.max(1, Math.floor(options.evalBudget ?? DEFAULT_EVAL_BUDGET));
  const layerBudget = Math.max(evalBudget, Math.floor(options.layerBudget ?? DEFAULT_LAYER_BUDGET));
  if (typeof source !== 'string') throw badShader(fileName, undefined, 'shader source must be text');
  if (source.length > MAX_SOURCE_LENGTH)
    throw badShader(fileName, undefined, `the shader is larger than ${MAX_SOURCE_LENGTH} characters`);
  const pre = preprocessGlsl(source, fileName);
  if (pre.text.replace(/\s+/g, ' ').length > MAX_CODE_LENGTH) {
    throw badShader(fileName, undefined, `the shader has more than ${MAX_CODE_LENGTH} characters of code`);
  }
  let ast: { program: unknown[] };
  try {
    ast = parse(pre.text, {
      includeLocation: true,
      quiet: true,
      grammarSource: fileName,
      failOnWarn: false,
    }) as unknown as { program: unknown[] };
  } catch (e) {
    throw parseError(fileName, e);
  }
  const ctx = new Ctx(fileName);
  ctx.host = entry === 'cellular' ? { density: true, machine: true } : { density: false, machine: true };
  let prog;
  try {
    prog = compileProgram(ctx, ast.program, { entry, evalBudget, layerBudget, uiParams: pre.uiParams });
  } catch (e) {
    if (e instanceof StrataError) throw e;
    if (e instanceof RangeError) throw badShader(fileName, ctx.line, 'the shader is too complex (nested too deeply)');
    throw badShader(fileName, ctx.line, `cannot compile: ${String((e as Error)?.message ?? e).slice(0, 200)}`);
  }
  if (prog.body.length > MAX_JS_LENGTH)
    throw badShader(fileName, undefined, 'the shader is too complex (generated code too large)');
  assertSafeJs(prog.body);
  let factory: Factory;
  try {
    factory = new Function('M', prog.body) as Factory;
  } catch (e) {
    throw badShader(
      fileName,
      undefined,
      `internal compiler error: ${String((e as Error)?.message ?? e).slice(0, 200)}`,
    );
  }
  const params: ShaderParam[] = pre.uiParams.map((p) => ({
    name: p.name,
    type: p.type,
    default: p.defaultValue,
    tooltip: p.tooltip,
  }));
  const uniforms = prog.uniforms;
  const body = prog.body;
  return {
    fileName,
    entry,
    params,
    numPassesConst: prog.numPassesConst,
    usesDensity: prog.usesDensity,
    warnings: ctx.warnings.slice(),
    js: body,
    instantiate(): ShaderInstance {
      const table = makeMathTable({ fileName, evalBudget, layerBudget });
      const [E, S, NP, WR, WG, R] = factory(table);
      let configured = false;
      const inst: ShaderInstance = {
        configure(env: ShaderEnv): void {
          const u = uniformValues(fileName, uniforms, params, env);
          const den = env.density ?? (() => 20);
          S(u, den, env.nozzleDiameter ?? 0.4, env.layerHeight ?? 0.2);
          configured = true;
        },
        numPasses(): number {
          if (!configured) inst.configure({});
          const n = NP();
          return Number.isFinite(n) ? Math.max(1, Math.min(16, Math.floor(n))) : 1;
        },
        label: (x: number, y: number, z: number): number => {
          if (!configured) inst.configure({});
          inst.label = E;
          return E(x, y, z);
        },
        lastColor: () => [R[0], R[1], R[2], R[3]],
        resetWork: () => WR(0),
        work: () => WG(),
      };
      return inst;
    },
  };
}
