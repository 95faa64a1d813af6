import daylight from '../i18n/messages/en/daylight';
import { registerEnglishAreas } from '../i18n/loadMessages';

// Imported by the daylight panel (a chunk of its own): its English texts travel with it instead
// of the first screen's (docs/i18n.md, "Bundles").
registerEnglishAreas({ daylight });
