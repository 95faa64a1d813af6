// Aiming adjustable spots: the module's aim options, aim at, the spotlight view (docs/aiming.md).
export default {
  title: 'Aim',
  rotation: 'Rotation {degrees}°',
  tilt: 'Tilt {degrees}°',
  limits: 'Turns {rotationMin}–{rotationMax}°, tilts {tiltMin}–{tiltMax}°',
  straightDown: 'Straight down',
  aimAt: 'Aim at…',
  aimAtActive: 'Tap the floor or a surface to aim',
  aimAtHint: 'Tap a point in the plan or the 3D view: the spot turns to it',
  cancel: 'Cancel',
  spotlightView: 'Spotlight view',
  spotlightLeave: 'Leave spotlight view',
  spotlightHint: 'Drag to pan and tilt the spot; the light follows, the full calculation runs when you let go',
  spotlightNeedsModule: 'Select an adjustable spot to look from it',
  outlines: 'Beam 50 % and field 10 % outlines',
};
