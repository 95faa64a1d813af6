import roomShape from '../i18n/messages/en/roomShape';
import { registerEnglishAreas } from '../i18n/loadMessages';

// Imported by the room-shape editor (a chunk of its own): its English texts travel with it instead
// of the first screen's (docs/i18n.md, "Bundles").
registerEnglishAreas({ roomShape });
