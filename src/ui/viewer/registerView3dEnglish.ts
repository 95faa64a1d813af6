import lazyEnglish from '../i18n/messages/en/lazy';
import { registerEnglishAreas } from '../i18n/loadMessages';

// Imported by every component of the 3D chunk that shows text: the English texts of the 3D view
// and live control travel with that chunk instead of the first screen's (docs/i18n.md, "Bundles").
registerEnglishAreas(lazyEnglish);
