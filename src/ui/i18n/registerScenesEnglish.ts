import scenesEnglish from './messages/en/scenes';
import { registerEnglishAreas } from './loadMessages';

// Imported by the light-scene panel and the 3D view's dimmer rows, both lazy chunks: the scenes'
// English travels with them instead of the first screen's (docs/i18n.md, "Bundles").
registerEnglishAreas({ scenes: scenesEnglish });
