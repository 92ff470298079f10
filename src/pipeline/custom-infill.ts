/**
 * Custom infill in IceSL's infiller format (a GLSL cellular() shader or a cells.png image), as plain
 * data that crosses a worker boundary: each thread compiles it once into a per-layer generator.
 */
import { customInfillGenerator, loadInfiller, type CustomInfillGenerator, type InfillerFiles } from '../shader/index.js';
import type { Config } from '../settings/resolve.js';

export interface CustomInfillSpec extends InfillerFiles {
  /** Values for the shader's ui_ parameters (names with or without the ui_ prefix). */
  params?: Readonly<Record<string, number | boolean>>;
}

/** Compile the spec into the generator the layer work calls instead of a built-in pattern. */
export function customGenerator(spec: CustomInfillSpec, cfg: Config): CustomInfillGenerator {
  return customInfillGenerator(loadInfiller(spec), { params: spec.params, pixelSize: cfg.infillImagePixelSize });
}
