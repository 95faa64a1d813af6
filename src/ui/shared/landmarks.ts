/**
 * Which landmarks luxbox draws (docs/accessibility.md, "Landmarks"). 'page': luxbox is the whole
 * page (the standalone app), so its header is the page's banner and the plan (or the room setup)
 * its one main. 'region': luxbox is embedded in a shop's page, which owns the banner and the main;
 * luxbox is one region named "luxbox lighting configurator" (in the UI language) and draws neither.
 */
export type Landmarks = 'page' | 'region';
