/**
 * What a custom infiller is, for a page that lets a user choose one and set its parameters.
 */
import { loadCustomInfill } from '../infill/registry.js';
import { resolveConfig } from '../settings/resolve.js';
import type { CustomInfillSpec } from '../exports.js';

/** A custom infiller as `describeCustomInfill` reads it. */
export interface CustomInfillInfo {
  name: string;
  /** A GLSL `cellular()` shader, or a cells.png image. */
  kind: 'shader' | 'image';
  /** The shader's `ui_` parameters (none for an image): a spec's `params` sets them by name. */
  params: Array<{ name: string; type: 'bool' | 'int' | 'float'; default: number | boolean; tooltip: string }>;
  warnings: string[];
}

/**
 * Compile a custom infiller (loading the shader compiler first, as `loadCustomInfill` does) and say what it
 * is: its kind, its `ui_` parameters with their defaults and tooltips, and the compiler's warnings. Throws
 * the `StrataError` a slice would for a shader that does not compile, an image that cannot be read, or
 * parameter values it does not take.
 */
export async function describeCustomInfill(spec: CustomInfillSpec): Promise<CustomInfillInfo> {
  const compiler = await loadCustomInfill();
  // in the compiler's chunk already: importing it loads nothing more
  const { describeInfiller, loadInfiller } = await import('../shader/index.js');
  const info = describeInfiller(loadInfiller(spec));
  // as a slice compiles it: with its parameters, for the default settings
  compiler.customGenerator(spec, resolveConfig());
  return {
    name: info.name,
    kind: info.kind,
    params: info.params.map((p) => ({ ...p })),
    warnings: [...info.warnings],
  };
}
