import { mountLuxbox } from '../embed/mountLuxbox';
import type { LuxboxInstance } from '../embed/types';
import { isQualityLevel } from '../../engines/relight/qualityLevels';
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
window.luxbox = mountLuxbox(root, { storageKey: 'luxbox.autosave.v1', shareLinks: true, rememberQuality: true, demo, ...(isQualityLevel(quality) ? { quality } : {}) });
