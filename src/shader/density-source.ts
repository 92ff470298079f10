/**
 * Where density() gets its value: a constant percentage, a per-layer list, a JS field function, or
 * a density shader (`float density(vec3 world)` returning 0–100).
 */
import { StrataError } from '../errors.js';
import type { DensitySource } from './paths.js';
import type { CompiledShader, ShaderInstance } from './shader.js';

export type DensityInput = number | readonly number[] | ((x: number, y: number, z: number) => number) | CompiledShader;

/** Turns a DensityInput into a per-layer DensitySource; keeps one shader instance for all layers. */
export function densityResolver(input: DensityInput): (layerIndex: number) => DensitySource {
  if (typeof input === 'number') {
    checkPercent(input);
    return () => input;
  }
  if (typeof input === 'function') return () => input;
  if (Array.isArray(input)) {
    const list = input as readonly number[];
    if (list.length === 0) throw new StrataError('BAD_SETTING', 'custom infill: the per-layer density list is empty');
    list.forEach(checkPercent);
    return (i) => list[Math.max(0, Math.min(list.length - 1, i))];
  }
  const shader = input as CompiledShader;
  if (shader.entry !== 'density')
    throw new StrataError('BAD_SETTING', `${shader.fileName}: a density shader must define float density(vec3 world)`);
  let inst: ShaderInstance | undefined;
  return () => {
    if (inst === undefined) {
      const made = shader.instantiate();
      made.configure({});
      inst = made;
    }
    const i = inst;
    i.resetWork();
    return (x, y, z) => i.label(x, y, z);
  };
}

function checkPercent(v: number): void {
  if (!Number.isFinite(v) || v < 0 || v > 100)
    throw new StrataError('BAD_SETTING', `custom infill: density must be 0–100 %, got ${v}`);
}
