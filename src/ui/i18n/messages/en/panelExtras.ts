// English areas used only by parts of the side panel that load on demand (the share link's copy and
// share buttons, the import preview, the Expert switch): they ship in those chunks, not in the first screen's
// (registered by src/ui/planner/registerPanelExtrasEnglish.ts; docs/i18n.md, "Bundles").
import expert from './expert';
import modelImport from './modelImport';
import sharing from './sharing';

export default {
  expert,
  modelImport,
  sharing,
};
