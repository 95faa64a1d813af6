import optionsEnglish from '../i18n/messages/en/optionsPanel';
import { registerEnglishAreas } from '../i18n/loadMessages';

// Imported by every component of the options panel's chunk that shows text: the English texts of
// the selection's settings travel with that chunk instead of the first screen's (docs/i18n.md, "Bundles").
registerEnglishAreas(optionsEnglish);
