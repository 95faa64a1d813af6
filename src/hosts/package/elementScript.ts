// Entry of the single-file script build (lib/standalone/luxbox-element.js, vite.lib.config.ts):
// `<script type="module" src=".../luxbox-element.js">` registers `<luxbox-configurator>` with its
// own UI runtime (preact) bundled. The photometry of the bundled demo catalog is copied beside
// the script (ies/), so without a catalog URL or asset-base the element finds it there.
import { LuxboxConfiguratorElement } from './LuxboxConfiguratorElement';

// The script's folder, cut from its URL by hand: Vite's library build takes `new URL('./', import.meta.url)`
// for an asset reference and inlined this very file as a `data:` URL there, so the demo's photometry
// was looked for under `data:…/ies/` (checkPackage.mjs now checks the built script for it).
const scriptUrl = import.meta.url;
LuxboxConfiguratorElement.defaultAssetBase = scriptUrl.slice(0, scriptUrl.lastIndexOf('/') + 1);
export * from './element';
