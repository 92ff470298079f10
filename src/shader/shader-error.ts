/** Error helpers: every shader error names the file and line, as `shader.glsl line 12: …`. */
import { StrataError } from '../errors.js';

export function badShader(fileName: string, line: number | undefined, message: string): StrataError {
  const where = line !== undefined && line > 0 ? `${fileName} line ${line}` : fileName;
  return new StrataError('BAD_SHADER', `${where}: ${message}`);
}

export function limitExceeded(fileName: string, line: number | undefined, message: string): StrataError {
  const where = line !== undefined && line > 0 ? `${fileName} line ${line}` : fileName;
  return new StrataError('LIMIT_EXCEEDED', `${where}: ${message}`);
}
