// Entry of the single-file script build (lib/standalone/luxbox-element.js, vite.lib.config.ts):
// `<script type="module" src=".../luxbox-element.js">` registers `<luxbox-configurator>` with its
// own UI runtime (preact) bundled. The photometry of the bundled demo catalog is copied beside
// the script (ies/), so without a catalog URL or asset-base the element finds it there.
import { LuxboxConfiguratorElement } from './LuxboxConfiguratorElement';

LuxboxConfiguratorElement.defaultAssetBase = new URL('./', import.meta.url).href;
export * from './element';
