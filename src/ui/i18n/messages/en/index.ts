// English: the source of every key. One line per area; de, fr and it register the same areas.
// The 3D view's own areas (live, view3d, exposure, aim) are in ./lazy.ts: they ship with the 3D chunk; the options
// panel's (options, connectors, filters, aim) in ./optionsPanel.ts, with its chunk (docs/i18n.md, "Bundles").
// The light scenes' (scenes) with the scene panel and the 3D view (src/ui/i18n/registerScenesEnglish.ts), the
// screen-reader announcements' (a11y) with theirs (registerA11yEnglish.ts).
// The core's codes (refusals, fileErrors, photometry) are in ./core.ts: fetched with another language (English shows the core's own sentences).
import app from './app';
import commands from './commands';
import common from './common';
import files from './files';
import finishes from './finishes';
import furniture from './furniture';
import notices from './notices';
import planner from './planner';
import rooms from './rooms';
import shared from './shared';
import viewer from './viewer';

export default {
  app,
  commands,
  common,
  files,
  finishes,
  furniture,
  notices,
  planner,
  rooms,
  shared,
  viewer,
};
