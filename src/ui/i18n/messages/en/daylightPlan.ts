// The plan's daylight-factor overlay (issue 30, docs/daylight.md "The daylight-factor map on the plan"): English ships in its
// lazy chunk (src/ui/planner/registerDaylightPlanEnglish.ts), the other languages with their language chunks.
export default {
  toggle: 'Daylight factor',
  hint: 'Daylight factor on the work plane under an overcast sky: indoor ÷ outdoor illuminance',
  computing: 'Computing…',
  noSky: 'The sun is below the horizon at this time: pick a time of day with daylight.',
  unavailable: 'The daylight factor needs 3D graphics (WebGL 2), which this browser cannot offer.',
  band: 'Blank: 0.5 m along the walls (EN 17037).',
};
