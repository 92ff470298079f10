/**
 * Bounds on what one model may expand to, shared by every reader, so memory stays proportional to
 * what a printable model needs: 20 million triangles is ~1 GB of binary STL, beyond any printer's
 * resolution for one plate.
 */
import { StrataError } from '../errors.js';

/** Most triangles one input may hold (after polygons are split and components instanced). */
export const MAX_MODEL_TRIANGLES = 20_000_000;
/** Most vertices one input may hold. */
export const MAX_MODEL_VERTICES = 3 * MAX_MODEL_TRIANGLES;

export function tooManyTriangles(what: string, count?: number): never {
  throw new StrataError(
    'LIMIT_EXCEEDED',
    `${what}: ${count !== undefined ? `${count} triangles is` : 'the model expands to'} more than the ${MAX_MODEL_TRIANGLES} allowed`,
  );
}

export function tooManyVertices(what: string): never {
  throw new StrataError('LIMIT_EXCEEDED', `${what}: more than the ${MAX_MODEL_VERTICES} vertices allowed`);
}
