import panelExtrasEnglish from '../i18n/messages/en/panelExtras';
import { registerEnglishAreas } from '../i18n/loadMessages';

// Imported by the side panel's on-demand parts (ShareLinkField, ImportPreview): their English texts
// travel with their chunks instead of the first screen's (docs/i18n.md, "Bundles").
registerEnglishAreas(panelExtrasEnglish);
