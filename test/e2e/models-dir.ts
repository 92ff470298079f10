/**
 * Where the tests find the shared real models: `../shared/models` beside the repository (or
 * STRATA_MODELS). Without them, tests that need them skip on a developer's machine but fail under
 * CI=true, so a CI run can never pass by skipping its end-to-end tests.
 */
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

/** The shared models folder, with a trailing separator (dist/e2e → repo → ../shared/models). */
export const MODELS_DIR = process.env.STRATA_MODELS
  ? join(process.env.STRATA_MODELS, '/')
  : fileURLToPath(new URL('../../../../shared/models/', import.meta.url));

export function modelsAvailable(): boolean {
  return existsSync(join(MODELS_DIR, 'CalibrationCube.stl'));
}

/** True when running in CI (CI=true or CI=1, as CI services set it). */
export function inCi(): boolean {
  const v = process.env.CI;
  return v !== undefined && v !== '' && v !== '0' && v.toLowerCase() !== 'false';
}

/**
 * For a test's `skip` option: false when the models are there; otherwise a reason to skip, or, under
 * CI, an error (the test file fails).
 */
export function skipWithoutModels(): string | false {
  if (modelsAvailable()) return false;
  if (inCi())
    throw new Error(
      `the shared models are missing (${MODELS_DIR}): under CI the end-to-end tests fail rather than skip`,
    );
  return `shared models not found in ${MODELS_DIR}`;
}

/** Path of one shared model. */
export function modelPath(name: string): string {
  return join(MODELS_DIR, name);
}
