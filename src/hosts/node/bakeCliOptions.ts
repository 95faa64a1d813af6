import { InputError } from '../../core/inputError';
import type { BakeSettings } from '../../engines/bake/bakeSettings';

/** Flags shared by `bake` and `probe` (docs/baker.md "Command line": --samples, --bounces, --texel) plus a few extras. */
const NUMERIC_FLAGS: Record<string, keyof BakeSettings> = {
  '--samples': 'samples',
  '--bounces': 'bounces',
  '--texel': 'texelSize',
  '--max-texture': 'maxTextureSize',
  '--blur': 'blurRadius',
  '--seed': 'seed',
  '--bright-patches': 'brightPatches',
  '--supersample': 'texelSupersampling',
};

/** `--near-field split|point`: overrides the scene file's `nearField` (docs/baker.md, "Luminous openings"). */
const NEAR_FIELD_FLAG = '--near-field';

export interface ParsedCli {
  positional: string[];
  settings: Partial<BakeSettings>;
  options: Record<string, string>;
}

/**
 * Split arguments into positionals, quality settings and other `--name value`
 * options (`valueFlags`). `--no-tail` switches the ρ→1 tail estimate off;
 * `--near-field split|point` picks the near-field model. Unknown flags, bad
 * near-field names and non-numbers are input errors.
 */
export function parseBakeCli(command: string, args: string[], valueFlags: string[]): ParsedCli {
  const positional: string[] = [];
  const settings: Partial<BakeSettings> = {};
  const options: Record<string, string> = {};
  for (let i = 0; i < args.length; i++) {
    const arg = args[i];
    if (!arg.startsWith('--')) {
      positional.push(arg);
      continue;
    }
    const [name, inline] = arg.includes('=') ? [arg.slice(0, arg.indexOf('=')), arg.slice(arg.indexOf('=') + 1)] : [arg, undefined];
    if (name === '--no-tail') {
      settings.tail = false;
      continue;
    }
    const key = NUMERIC_FLAGS[name];
    if (!key && name !== NEAR_FIELD_FLAG && !valueFlags.includes(name)) {
      throw new InputError(`${command}: unknown option ${name} (options: ${[...Object.keys(NUMERIC_FLAGS), NEAR_FIELD_FLAG, ...valueFlags, '--no-tail'].join(', ')})`);
    }
    const value = inline ?? args[++i];
    if (value === undefined) throw new InputError(`${command}: ${name} needs a value`);
    if (name === NEAR_FIELD_FLAG) {
      if (value !== 'split' && value !== 'point') throw new InputError(`${command}: ${NEAR_FIELD_FLAG} must be split or point, got "${value}"`);
      settings.nearField = value;
    } else if (key) {
      const n = Number(value);
      if (value.trim() === '' || !Number.isFinite(n)) throw new InputError(`${command}: ${name} must be a number, got "${value}"`);
      (settings as Record<string, number>)[key] = n;
    } else {
      options[name] = value;
    }
  }
  return { positional, settings, options };
}
