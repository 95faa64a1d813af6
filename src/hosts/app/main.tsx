import { EXPERT_KEY, mountLuxbox } from '../embed/mountLuxbox';
import { fetchCatalogFolder } from '../embed/fetchCatalogFolder';
import { parseAdaptation } from '../../engines/view/adaptationSetting';
import type { LuxboxInstance } from '../embed/types';
import { isQualityLevel } from '../../engines/relight/qualityLevels';
import { isEv100 } from '../../engines/view/photographicExposure';
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
// `?exposure=5.5` starts the 3D view locked at that EV100, `?exposure=auto` as by default (docs/viewer.md, "Exposure"); anything else is ignored.
const exposureParam = params.get('exposure');
const exposure = exposureParam === 'auto' ? 'auto' : exposureParam !== null && exposureParam.trim() !== '' && isEv100(Number(exposureParam)) ? Number(exposureParam) : undefined;
// `?adapt=eye|none|camera:3000` starts the 3D view with that chromatic adaptation (docs/viewer.md, "Adaptation"); anything else is ignored.
const adaptParam = params.get('adapt');
const adapt = adaptParam !== null && parseAdaptation(adaptParam) ? adaptParam : undefined;
// The expert tools (DMX live control, Radiance download, photometric data notes): off for shoppers, with
// the Expert switch in the side panel, remembered; `?expert=1` / `?expert=0` sets the switch as a tap would.
const expertParam = params.get('expert');
if (expertParam === '1' || expertParam === '0') writeLocal(EXPERT_KEY, expertParam);
// `?catalog=<url of a catalog.json>` opens on a catalog folder as `luxbox catalog import` writes it
// (docs/gldf.md): the JSON as the embedding API's `catalog`, its folder as `assetBase` (the
// photometry lies beside it), and an autosave of its own so the demo catalog's plan is not mixed in.
const catalogUrl = params.get('catalog');
async function mount(host: HTMLElement): Promise<void> {
  let folder = {};
  if (catalogUrl) {
    folder = { ...(await fetchCatalogFolder(catalogUrl, location.href)), storageKey: 'luxbox.autosave.catalog.v1' };
  }
  window.luxbox = mountLuxbox(host, {
    storageKey: 'luxbox.autosave.v1',
    ...folder,
    shareLinks: true,
    rememberQuality: true,
    expert: 'switch',
    rememberExpert: true,
    demo,
    locale,
    languageSwitch: true,
    // The app is the whole page: its header is the banner, the plan the main landmark.
    landmarks: 'page',
    onLanguageChange: (language) => {
      writeLocal(LANGUAGE_KEY, language);
      document.documentElement.lang = language;
    },
    ...(isQualityLevel(quality) ? { quality } : {}),
    ...(exposure !== undefined ? { exposure } : {}),
    ...(adapt !== undefined ? { adapt } : {}),
  });
  // The page's own language follows the configurator's (screen readers and hyphenation read it from <html>).
  document.documentElement.lang = window.luxbox.getLanguage().language;
}
void mount(root).catch((e: Error) => (root.textContent = `The catalog ${catalogUrl} could not be loaded: ${e.message}`));
