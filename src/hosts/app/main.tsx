import { mountLuxbox } from '../embed/mountLuxbox';
import type { LuxboxInstance } from '../embed/types';
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
const demo = import.meta.env.DEV || new URLSearchParams(location.search).has('demo');
window.luxbox = mountLuxbox(root, { storageKey: 'luxbox.autosave.v1', shareLinks: true, demo });
