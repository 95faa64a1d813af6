// The planner's guidance (issue 27): the empty plan's first step and the remedies offered at a refused
// control. Ships with the lazily loaded guidance chunk, not the first screen (registered by
// src/ui/planner/registerGuidanceEnglish.ts; docs/i18n.md, "Bundles").
export default {
  firstRunTitle: 'Start with a layout',
  firstRunHint: 'Tap a layout to place it in your room. You can change every rail and light afterwards.',
  firstRunPlace: 'Place {name}',
  firstRunAll: 'All layouts',
  useDriver: 'Use the {capacity} W driver',
  addFeed: 'Add a power feed with the {capacity} W driver',
  lengthenRail: 'Lengthen rail {rail} to {length} m',
  distribution_start: 'Line the modules up from the start',
  distribution_end: 'Line the modules up from the end',
  'distribution_inside-centred': 'Space the modules evenly',
  'distribution_outside-centred': 'Space the modules evenly, outer ones at the ends',
  and: '{first}, then {second}',
  withPrice: '{action} ({price})',
};
