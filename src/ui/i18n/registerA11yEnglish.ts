import a11yEnglish from './messages/en/a11y';
import { registerEnglishAreas } from './loadMessages';

// Imported by the plan's screen-reader announcements (src/ui/planner/planAnnouncement.ts), a lazy
// chunk: their English travels with it instead of the first screen's (docs/i18n.md, "Bundles").
registerEnglishAreas({ a11y: a11yEnglish });
