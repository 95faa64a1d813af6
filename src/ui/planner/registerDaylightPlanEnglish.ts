import daylightPlan from '../i18n/messages/en/daylightPlan';
import { registerEnglishAreas } from '../i18n/loadMessages';

// Imported by the plan's daylight-factor overlay (a chunk of its own): its English texts travel with it instead
// of the first screen's (docs/i18n.md, "Bundles").
registerEnglishAreas({ daylightPlan });
