import { InputError, type Coding } from '../../inputError';
import { oneLine } from '../../untrustedJson';

/** A scene file (or share link) luxbox refuses: one line, coded (docs/i18n.md). */
export class SceneFileError extends InputError {
  override name = 'SceneFileError';
  constructor(message: string, coded?: Coding) {
    super(oneLine(message), coded);
  }
}

/** A field a later scene-file version added, in a file that says it is older (coded: docs/i18n.md). */
export function needsVersion(path: string, needed: number, version: number): SceneFileError {
  return new SceneFileError(`${path}: needs "version": ${needed} (this file says version ${version})`, { code: 'fileNeedsVersion', params: { path, needed, version } });
}
