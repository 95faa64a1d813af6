import { InputError } from '../inputError';
import { oneLine } from '../untrustedJson';

/**
 * A GLDF (or other uploaded container) that is refused: one line naming the file and, where
 * there is one, the entry inside it (`spot.gldf: entry ldc/spot.ldt: …`). Nothing of a refused
 * file lands in a catalog.
 */
export class GldfError extends InputError {
  override name = 'GldfError';
  constructor(message: string) {
    super(oneLine(message));
  }
}

/** An entry name or id quoted in a message: bounded, control characters shown escaped. */
export function quoteName(name: string, max = 60): string {
  const shown = JSON.stringify(name.length > max ? `${name.slice(0, max)}…` : name);
  return `'${shown.slice(1, -1)}'`;
}
