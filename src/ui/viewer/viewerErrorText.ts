import { codePhotometryError } from '../../core/photometry/photometryCodes';
import type { MessageKey, Translate } from '../i18n/messageTypes';
import { translateCoded } from '../i18n/translateCoded';
import './registerView3dEnglish';

/**
 * The 3D view's errors are English sentences (they also go to window.luxbox.view3d().error, which
 * scripts and tests read); on screen the known ones are shown in the UI language: the sentence's
 * fixed English opening is replaced by its translation, and the engine's detail after it (a file
 * name, a WebGL message) is kept as it is.
 */
const KNOWN: readonly [prefix: string, key: MessageKey][] = [
  ['The 3D view could not start: ', 'view3d.couldNotStart'],
  ['Could not prepare the furniture for the light calculation: ', 'view3d.furnitureFailed'],
  ['Could not load the photometric data: ', 'view3d.photometryFailed'],
];

export function viewerErrorText(t: Translate, english: string): string {
  for (const [prefix, key] of KNOWN) {
    if (!english.startsWith(prefix)) continue;
    const detail = english.slice(prefix.length);
    // A photometric file's error names the file and line and says what is wrong: coded by its sentence (photometryCodes.ts).
    const coded = key === 'view3d.photometryFailed' ? codePhotometryError(detail) : null;
    return t(key, { problem: coded ? translateCoded(t, 'photometry', coded) : detail });
  }
  return english;
}
