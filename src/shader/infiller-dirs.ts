/**
 * Where infillers live on disk (Node): the folder shipped with Strata and IceSL's own. Apart from the
 * folder reader so that naming the folders does not load the shader compiler.
 */
import { homedir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

/** The infillers shipped with Strata (the package's infillers/ folder). */
export function shippedInfillersDir(): string {
  return join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'infillers');
}

/** IceSL's own infiller folders: ~/.icesl/icesl-infillers (Linux, macOS), %APPDATA%\\IceSL\\icesl-infillers (Windows). */
export function iceslInfillersDirs(): string[] {
  const dirs = [join(homedir(), '.icesl', 'icesl-infillers')];
  const appData = process.env.APPDATA;
  if (appData) dirs.push(join(appData, 'IceSL', 'icesl-infillers'));
  return dirs;
}
