/**
 * Custom infill from IceSL-style infillers: GLSL shaders compiled to JavaScript and cell images.
 * Browser-safe entry point (no file I/O); the Node folder adapter is ./node-folder.js.
 */
export {
  compileShader,
  parseParamValue,
  parseInfillParams,
  findParam,
  checkParamValue,
  DEFAULT_EVAL_BUDGET,
  DEFAULT_LAYER_BUDGET,
  MAX_SOURCE_LENGTH,
} from './shader.js';
export type { CompileOptions, CompiledShader, ShaderInstance, ShaderEnv, ShaderParam, ParamValues } from './shader.js';
export { labelBoundaries, shaderPaths, shaderPathsByPass } from './paths.js';
export type { DensitySource, ExtractOptions, ShaderLayerInput } from './paths.js';
export { decodeCellsPng, loadCellImage, imageLabelFn, mergeAntialiased, MAX_IMAGE_PIXELS } from './image.js';
export type { CellImage, ImageLoadOptions } from './image.js';
export {
  infillerFromShader,
  infillerFromImage,
  loadInfiller,
  loadInfillers,
  describeInfiller,
  DEFAULT_PIXEL_SIZE,
} from './infiller.js';
export type { Infiller, InfillerFiles, InfillerInfo, InfillerKind, InfillerOptions } from './infiller.js';
export { densityResolver } from './density-source.js';
export type { DensityInput } from './density-source.js';
export type { LabelFn } from './label-grid.js';
