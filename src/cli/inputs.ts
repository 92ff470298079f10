/**
 * What the slicing commands read: model files, JSON configs, custom infillers, each recorded so the
 * output can be checked against them (an output that is one of the inputs is refused).
 */
import { basename } from 'node:path';
import { StrataError } from '../errors.js';
import { PATTERN_IDS } from '../infill/types.js';
import { loadModelFile, mergeObjects, type LoadedFile } from '../mesh/index.js';
import type { MeshObject, MeshVolume } from '../mesh/types.js';
import type { ModelInput } from '../mesh/place.js';
import type { CustomInfillSpec } from '../infill/patterns/custom.js';
import type { Config } from '../settings/resolve.js';
import { importProfile } from '../profiles/index.js';
import type { SliceOptions } from '../settings/schema.js';
import { iceslInfillersDirs, shippedInfillersDir } from '../shader/infiller-dirs.js';
import { FLAG_TO_KEY, type ParsedArgs } from './args.js';
import { checkKey, parseDecimal, parseSettingText } from '../settings/resolve.js';
import type { NamedInput } from './output.js';
import { readInput, type InputKind } from './read-input.js';

const MiB = 1024 * 1024;

/** Reads files and remembers which it read. */
export class InputReader {
  readonly read: NamedInput[] = [];

  /** A file's bytes ('-': standard input), within the limit of its kind (read-input.ts); `what` names it in messages. */
  bytes(path: string, what: string, kind: InputKind): Promise<Uint8Array> {
    this.read.push({ path, what });
    return readInput(path, kind, what);
  }

  async text(path: string, what: string, kind: InputKind): Promise<string> {
    return new TextDecoder().decode(await this.bytes(path, what, kind));
  }

  /** One file's objects (and a project's print settings), within the config's unpack budget. */
  async #file(path: string, what: string, cfg: Config): Promise<LoadedFile> {
    return loadModelFile(await this.bytes(path, what, 'model'), path === '-' ? undefined : basename(path), {
      maxInflatedBytes: cfg.inflateBudget * MiB,
    });
  }

  async #objects(path: string, what: string, cfg: Config): Promise<MeshObject[]> {
    return (await this.#file(path, what, cfg)).objects;
  }

  /**
   * One model per file, named after it; the flags that follow a file (`--object`, `--modifier`, `--negative`,
   * `--support-blocker`, `--support-enforcer`, `--layer-range`) give every object of that file its
   * settings and volumes.
   */
  async models(
    paths: readonly string[],
    cfg: Config,
    modelFlags: ParsedArgs['modelFlags'] = [],
  ): Promise<ModelInput[]> {
    const early = modelFlags.find((f) => f.model < 0);
    if (early)
      throw new StrataError(
        'BAD_SETTING',
        `--${early.flag} belongs to a model: give it after the model file it applies to`,
      );
    const models: ModelInput[] = [];
    for (const [k, p] of paths.entries()) {
      const name = p === '-' ? 'standard input' : basename(p);
      const file = await this.#file(p, 'model', cfg);
      const flags = modelFlags.filter((f) => f.model === k);
      const objects: MeshObject[] = [];
      for (const o of file.objects) objects.push(flags.length ? await this.#withFlags(o, flags, cfg) : o);
      const model: ModelInput = { name, objects };
      if (file.projectSettings) model.projectSettings = file.projectSettings;
      if (file.warnings.length) model.warnings = file.warnings;
      models.push(model);
    }
    return models;
  }

  async #withFlags(o: MeshObject, flags: ParsedArgs['modelFlags'], cfg: Config): Promise<MeshObject> {
    const out: MeshObject = { ...o, volumes: [...(o.volumes ?? [])], layerRanges: [...(o.layerRanges ?? [])] };
    const own: Record<string, unknown> = { ...(o.settings?.format === 'strata' ? o.settings.values : {}) };
    const volumeMesh = async (path: string, what: string) => mergeObjects(await this.#objects(path, what, cfg));
    for (const { flag, value } of flags) {
      if (flag === 'object') Object.assign(own, parseSettingList(value, `--object ${value}`));
      else if (flag === 'layer-range') {
        const m = /^\s*([0-9.]+)\s*-\s*([0-9.]+)\s*:(.*)$/.exec(value);
        const fromZ = parseDecimal(m?.[1] ?? ''),
          toZ = parseDecimal(m?.[2] ?? '');
        if (!m || !Number.isFinite(fromZ) || !Number.isFinite(toZ) || !(toZ > fromZ)) {
          throw new StrataError(
            'BAD_SETTING',
            `--layer-range expects FROM-TO:KEY=VALUE,… (mm from the bed, FROM < TO), got "${value}"`,
          );
        }
        out.layerRanges!.push({
          fromZ,
          toZ,
          settings: { format: 'strata', values: parseSettingList(m[3], `--layer-range ${value}`) },
        });
      } else {
        const colon = flag === 'modifier' ? value.lastIndexOf(':') : -1;
        // a Windows drive letter (C:\…) is not a settings list
        const split = colon > 1 && /=/.test(value.slice(colon + 1));
        const path = split ? value.slice(0, colon) : value;
        const kind =
          flag === 'modifier'
            ? 'modifier'
            : flag === 'negative'
              ? 'negative'
              : flag === 'support-blocker'
                ? 'support-blocker'
                : 'support-enforcer';
        const volume: MeshVolume = { kind, name: basename(path), mesh: await volumeMesh(path, `--${flag} mesh`) };
        if (split)
          volume.settings = {
            format: 'strata',
            values: parseSettingList(value.slice(colon + 1), `--${flag} ${value}`),
          };
        out.volumes!.push(volume);
      }
    }
    if (Object.keys(own).length) out.settings = { format: 'strata', values: own };
    if (!out.volumes!.length) delete out.volumes;
    if (!out.layerRanges!.length) delete out.layerRanges;
    return out;
  }

  /** Settings from a Strata JSON file or another slicer's profile (profiles/); what is left out is in `warnings`. */
  async config(path: string): Promise<{ settings: Record<string, unknown>; warnings: string[] }> {
    const profile = importProfile(await this.text(path, 'config file', 'config'), path);
    return { settings: profile.settings, warnings: profile.warnings };
  }
}

export function infillerDirs(args: ParsedArgs): string[] {
  const extra = typeof args.flags.infillers === 'string' ? args.flags.infillers.split('\n') : [];
  return [...extra, shippedInfillersDir(), ...iceslInfillersDirs()];
}

/** A custom infiller named by --infill-shader, --infill-image, or an --infill-pattern that is not built in. */
async function customInfillFrom(
  args: ParsedArgs,
  opts: Record<string, unknown>,
  input: InputReader,
): Promise<CustomInfillSpec | undefined> {
  let spec: CustomInfillSpec | undefined;
  const shader = args.flags['infill-shader'];
  const image = args.flags['infill-image'];
  if (typeof shader === 'string' && typeof image === 'string')
    throw new StrataError('BAD_SETTING', '--infill-shader and --infill-image exclude each other');
  if (typeof shader === 'string')
    spec = { name: basename(shader), shader: await input.text(shader, 'infill shader', 'shader') };
  else if (typeof image === 'string')
    spec = { name: basename(image), image: await input.bytes(image, 'infill image', 'image') };
  else if (typeof opts.infillPattern === 'string' && !(PATTERN_IDS as readonly string[]).includes(opts.infillPattern)) {
    const name = opts.infillPattern;
    for (const dir of infillerDirs(args)) {
      // the shader compiler loads only when a custom infill is used
      const { readInfillersFolder } = await import('../shader/node-folder.js');
      const found = (await readInfillersFolder(dir)).find((f) => f.name === name);
      if (found) {
        spec = found;
        break;
      }
    }
    if (!spec) {
      throw new StrataError(
        'BAD_SETTING',
        `infillPattern "${name}" is neither a built-in pattern (${PATTERN_IDS.join(', ')}) nor an infiller folder (see strata infillers)`,
      );
    }
    delete opts.infillPattern;
  }
  const assignments = typeof args.flags['infill-param'] === 'string' ? args.flags['infill-param'].split('\n') : [];
  const densityShader = args.flags['infill-density-shader'];
  const densityLayers = args.flags['infill-density-layers'];
  if (!spec) {
    if (assignments.length || densityShader || densityLayers) {
      throw new StrataError(
        'BAD_SETTING',
        '--infill-param and --infill-density-shader/-layers need a custom infiller (--infill-shader, --infill-image or an infiller --infill-pattern)',
      );
    }
    return undefined;
  }
  if (assignments.length) {
    const { loadInfiller, parseInfillParams } = await import('../shader/index.js');
    spec.params = parseInfillParams(loadInfiller(spec).params, assignments);
  }
  if (typeof densityShader === 'string')
    spec.density = {
      shader: await input.text(densityShader, 'density shader', 'shader'),
      fileName: basename(densityShader),
    };
  else if (typeof densityLayers === 'string') {
    const list = densityLayers.split(',').map(parseDecimal);
    if (!list.length || list.some((v) => !Number.isFinite(v) || v < 0 || v > 100))
      throw new StrataError(
        'BAD_SETTING',
        '--infill-density-layers expects comma-separated percentages 0-100, one per layer',
      );
    spec.density = list;
  }
  return spec;
}

/**
 * The slicer options the command line asks for: configs, presets, settings and a custom infiller.
 * `warn` hears what an imported profile leaves out.
 */
export async function optionsFrom(
  args: ParsedArgs,
  input: InputReader,
  warn: (w: string) => void,
): Promise<SliceOptions & { customInfill?: CustomInfillSpec }> {
  // no prototype: a config's "__proto__" key stays a key, refused by the slicer as the library refuses it
  const opts: Record<string, unknown> = Object.create(null) as Record<string, unknown>;
  const configs = typeof args.flags.config === 'string' ? args.flags.config.split('\n') : [];
  for (const f of configs) {
    const { settings, warnings } = await input.config(f);
    Object.assign(opts, settings);
    for (const w of warnings) warn(w);
  }
  if (typeof args.flags.printer === 'string') opts.printer = args.flags.printer;
  if (typeof args.flags.filament === 'string') opts.filament = args.flags.filament;
  Object.assign(opts, args.settings);
  const customInfill = await customInfillFrom(args, opts, input);
  return { ...(opts as SliceOptions), ...(customInfill ? { customInfill } : {}) };
}

/** `key=value,key=value` (keys as flags, `infill-density`, or as settings, `infillDensity`) parsed by type. */
export function parseSettingList(text: string, where: string): Record<string, unknown> {
  const out: Record<string, unknown> = {};
  for (const part of text.split(',')) {
    if (part.trim() === '') continue;
    const eq = part.indexOf('=');
    if (eq <= 0)
      throw new StrataError(
        'BAD_SETTING',
        `${where}: expected KEY=VALUE pairs separated by commas, got "${part.trim()}"`,
      );
    const raw = part.slice(0, eq).trim();
    const key = FLAG_TO_KEY.get(raw) ?? checkKey(raw, 'setting');
    out[key] = parseSettingText(key, part.slice(eq + 1));
  }
  return out;
}
