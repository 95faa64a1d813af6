// Coded messages from outside React, keyed by their code: the core's refusals (Refusal.code) and status-line notices (docs/i18n.md, "Messages from the core").
export default {
  shareLinkNotice: 'Share link: {notice}',
  driverFull: 'the {capacity} W driver is full: {used} W used; choose the {larger} W driver in the system options or add a second feed',
  driverFullAddFeed: 'the {capacity} W driver is full: {used} W used; add a second feed in the system options',
  feedOverload: 'Feed {n} would carry {load} W, more than its {capacity} W driver; add a second feed or choose a larger driver',
  driverTooSmall: 'the {capacity} W {driver} cannot carry the {load} W on Feed {n}; choose a larger driver or add a feed',
  noFreeSpace: "no free space for '{name}' in this room",
  noRoomForModule: 'no room for another {name} ({length} m) on this rail',
  noFreeGap: 'no free gap on this rail holds a {name} ({length} m): the largest is {gap} m; move modules apart or choose a distribution',
  'outside-room': 'system {id} reaches outside the {width} × {depth} m room',
  'self-overlap': 'system {id} runs into itself',
  'system-overlap': 'system {id} overlaps system {other}',
  'suspension-range': 'suspension must be between {min} and {max} m (got {value})',
  'suspension-floor': 'modules would hang at {hang} m, below the minimum {min} m above the floor',
  'rail-length-range': 'rail length must be between {min} and {max} m (got {value})',
  'rail-length-grid': 'rail length must be a multiple of {step} m (got {value})',
  'modules-do-not-fit': "the modules of rail {rail} do not fit its {length} m with distribution '{distribution}'",
};
