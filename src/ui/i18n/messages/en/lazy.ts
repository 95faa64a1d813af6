// English areas used only inside the lazily loaded 3D view: they ship in its chunk, not in the
// first screen's (registered by src/ui/viewer/registerView3dEnglish.ts; docs/i18n.md, "Bundles").
import aim from './aim';
import exposure from './exposure';
import live from './live';
import view3d from './view3d';

export default {
  aim,
  exposure,
  live,
  view3d,
};
