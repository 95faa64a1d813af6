import { mountLuxbox } from '../embed/mountLuxbox';
import type { LuxboxInstance } from '../embed/types';
import { isQualityLevel } from '../../engines/relight/qualityLevels';
import { readLocal, writeLocal } from '../embed/localStore';
import { isLanguage } from '../../ui/i18n/languages';
import { preferLanguage } from '../../ui/i18n/resolveLocale';
import '../../ui/app/page.css';

declare global {
  interface Window {
    /** The running configurator's API (docs/embedding.md); e2e tests drive the app through it. */
    luxbox?: LuxboxInstance;
  }
}

const root = document.getElementById('root');
if (!root) throw new Error('index.html lacks #root');
// The standalone app: autosave in localStorage and share links in the URL hash.
// The dev server (scripts/start.sh) and `?demo` open on the demo scene when nothing is saved;
// the built app starts with the room setup.
const params = new URLSearchParams(location.search);
const demo = import.meta.env.DEV || params.has('demo');
// `?quality=fast|balanced|best` pins the 3D bake quality (tests pin 'balanced' where they read lux values).
const quality = params.get('quality');
// The language: `?lang=de` overrides the user's stored choice, which overrides the browser's
// navigator.languages; an explicit choice keeps the browser's region ('de' + de-CH → Swiss formatting).
const LANGUAGE_KEY = 'luxbox.language';
const asked = params.get('lang');
const chosen = isLanguage(asked) ? asked : readLocal(LANGUAGE_KEY);
const locale = isLanguage(chosen) ? preferLanguage(chosen, navigator.languages) : navigator.languages;
window.luxbox = mountLuxbox(root, {
  storageKey: 'luxbox.autosave.v1',
  shareLinks: true,
  rememberQuality: true,
  demo,
  locale,
  languageSwitch: true,
  onLanguageChange: (language) => writeLocal(LANGUAGE_KEY, language),
  ...(isQualityLevel(quality) ? { quality } : {}),
});
