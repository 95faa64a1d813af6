import guidanceEnglish from '../i18n/messages/en/guidance';
import { registerEnglishAreas } from '../i18n/loadMessages';

// Imported by every module of the guidance chunk that shows text (first run, remedies): their English
// texts travel with that chunk instead of the first screen's (docs/i18n.md, "Bundles").
registerEnglishAreas({ guidance: guidanceEnglish });
