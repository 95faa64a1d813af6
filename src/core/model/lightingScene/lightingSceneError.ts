import { InputError } from '../../inputError';
import { oneLine } from '../../untrustedJson';

/** A lighting scene the reader refuses: one line `source: path: problem` (parseLightingScene.ts, parseDaylight.ts). */
export class LightingSceneError extends InputError {
  override name = 'LightingSceneError';
  constructor(message: string) {
    super(oneLine(message));
  }
}
