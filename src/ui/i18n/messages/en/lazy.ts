// English areas used only inside the lazily loaded 3D view: they ship in its chunk, not in the
// first screen's (registered by src/ui/viewer/registerView3dEnglish.ts; docs/i18n.md, "Bundles").
import live from './live';
import view3d from './view3d';

export default {
  live,
  view3d,
};
