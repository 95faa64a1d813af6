// English areas used only inside the lazily loaded options panel (settings of the selection): they
// ship in its chunk, not in the first screen's (registered by src/ui/planner/registerOptionsEnglish.ts;
// docs/i18n.md, "Bundles"). `aim` is also in ./lazy.ts: the 3D view's spotlight controls show it.
import aim from './aim';
import connectors from './connectors';
import filters from './filters';
import options from './options';

export default {
  aim,
  connectors,
  filters,
  options,
};
