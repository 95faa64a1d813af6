// Coded messages from outside React, keyed by their code: the core's refusals (Refusal.code) and status-line notices (docs/i18n.md, "Messages from the core").
export default {
  shareLinkNotice: 'Share link: {notice}',
  driverFull: 'the {capacity} W driver is full: {used} W used; add a second feed or choose a larger driver',
  feedOverload: 'Feed {n} would carry {load} W, more than its {capacity} W driver; add a second feed or choose a larger driver',
  driverTooSmall: 'the {capacity} W {driver} cannot carry the {load} W on Feed {n}; choose a larger driver or add a feed',
  noFreeSpace: "no free space for '{name}' in this room",
  noRoomForModule: 'no room for another {name} ({length} m) on this rail',
  noFreeGap: 'no free gap on this rail holds a {name} ({length} m): the largest is {gap} m; move modules apart or choose a distribution',
};
