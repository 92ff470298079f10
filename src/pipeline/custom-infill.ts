/**
 * Custom infill in IceSL's infiller format (a GLSL cellular() shader or a cells.png image), as plain
 * data that crosses a worker boundary: each thread compiles it once into a per-layer generator.
 */
import {
  compileShader,
  customInfillGenerator,
  loadInfiller,
  type CustomInfillGenerator,
  type DensityInput,
  type InfillerFiles,
} from '../shader/index.js';
import type { Config } from '../settings/resolve.js';

/** What density() returns (0–100): a constant, one value per layer, a density shader, or a JS field. */
export type CustomDensity =
  | number
  | readonly number[]
  | { shader: string; fileName?: string }
  | ((x: number, y: number, z: number) => number);

export interface CustomInfillSpec extends InfillerFiles {
  /** Values for the shader's ui_ parameters (names with or without the ui_ prefix). */
  params?: Readonly<Record<string, number | boolean>>;
  /**
   * The field density(world) reads; default: the infillDensity setting. A JS function cannot be
   * sent to worker threads, so a slice that uses one runs on the calling thread.
   */
  density?: CustomDensity;
}

export { isTransferable } from './custom-infill-loader.js';

function densityInput(d: CustomDensity | undefined): DensityInput | undefined {
  if (d === undefined || typeof d === 'number' || typeof d === 'function' || Array.isArray(d))
    return d as DensityInput | undefined;
  const s = d as { shader: string; fileName?: string };
  return compileShader(s.shader, { entry: 'density', fileName: s.fileName ?? 'density.glsl' });
}

/** Compile the spec into the generator the layer work calls instead of a built-in pattern. */
export function customGenerator(spec: CustomInfillSpec, cfg: Config): CustomInfillGenerator {
  return customInfillGenerator(loadInfiller(spec), {
    params: spec.params,
    pixelSize: cfg.infillImagePixelSize,
    // empty: the infiller default (nozzle / 4 for shaders, one pixel for images)
    resolution: cfg.infillShaderResolution ?? undefined,
    density: densityInput(spec.density),
  });
}
