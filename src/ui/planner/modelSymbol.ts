/**
 * A module with an L3D body drawn in the plan as its outline from above (footprintSource
 * `outline`, l3dPlanOutline), instead of the rail-width rectangle: the outline's [x, z] (metres,
 * x along the rail) turned by the rail's heading about the photometric centre. The mount frame
 * is Ry(heading) (docs/viewer.md "Luminaires"): local x → plan (cos h, −sin h), local z → (sin h, cos h).
 */
export function modelSymbolPoints(outline: readonly [number, number][], centre: readonly [number, number], headingDeg: number): [number, number][] {
  const h = (headingDeg * Math.PI) / 180;
  const c = Math.cos(h);
  const s = Math.sin(h);
  return outline.map(([x, z]) => [centre[0] + x * c + z * s, centre[1] - x * s + z * c]);
}
