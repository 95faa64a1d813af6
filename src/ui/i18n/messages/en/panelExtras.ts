// English areas used only by parts of the side panel that load on demand (the share link's copy and
// share buttons, the import preview): they ship in those chunks, not in the first screen's
// (registered by src/ui/planner/registerPanelExtrasEnglish.ts; docs/i18n.md, "Bundles").
import modelImport from './modelImport';
import sharing from './sharing';

export default {
  modelImport,
  sharing,
};
