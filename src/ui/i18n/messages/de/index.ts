import type { MessageTree } from '../../messageTypes';
import a11y from './a11y';
import aim from './aim';
import app from './app';
import commands from './commands';
import common from './common';
import connectors from './connectors';
import exposure from './exposure';
import fileErrors from './fileErrors';
import files from './files';
import modelImport from './modelImport';
import filters from './filters';
import finishes from './finishes';
import furniture from './furniture';
import guidance from './guidance';
import live from './live';
import notices from './notices';
import options from './options';
import photometry from './photometry';
import planner from './planner';
import refusals from './refusals';
import rooms from './rooms';
import roomShape from './roomShape';
import daylight from './daylight';
import daylightPlan from './daylightPlan';
import scenes from './scenes';
import expert from './expert';
import sharing from './sharing';
import shared from './shared';
import view3d from './view3d';
import viewer from './viewer';

export default {
  a11y,
  aim,
  app,
  commands,
  common,
  connectors,
  exposure,
  fileErrors,
  files,
  modelImport,
  filters,
  finishes,
  furniture,
  guidance,
  live,
  notices,
  options,
  photometry,
  planner,
  refusals,
  rooms,
  roomShape,
  daylight,
  daylightPlan,
  scenes,
  expert,
  sharing,
  shared,
  view3d,
  viewer,
} satisfies MessageTree;
