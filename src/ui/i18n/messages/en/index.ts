// English: the source of every key. One line per area; de, fr and it register the same areas.
// The 3D view's own areas (live, view3d) are in ./lazy.ts: they ship with the 3D chunk (docs/i18n.md, "Bundles").
// The core's codes (refusals, fileErrors, photometry) are in ./core.ts: fetched with another language (English shows the core's own sentences).
import a11y from './a11y';
import aim from './aim';
import app from './app';
import commands from './commands';
import common from './common';
import connectors from './connectors';
import exposure from './exposure';
import files from './files';
import filters from './filters';
import finishes from './finishes';
import furniture from './furniture';
import notices from './notices';
import options from './options';
import planner from './planner';
import rooms from './rooms';
import scenes from './scenes';
import shared from './shared';
import viewer from './viewer';

export default {
  a11y,
  aim,
  app,
  commands,
  common,
  connectors,
  exposure,
  files,
  filters,
  finishes,
  furniture,
  notices,
  options,
  planner,
  rooms,
  scenes,
  shared,
  viewer,
};
