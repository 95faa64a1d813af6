/**
 * The part of Radiance's standard `source.cal` (ray/src/cal/cal/source.cal, Greg Ward) that the
 * exported scene uses, shipped in the export folder so `rtrace` and `rpict` find it whatever
 * RAYPATH says. The definitions are Radiance's own, unchanged:
 * - src_theta: angle from the nadir (the source's −Z), 0–180°;
 * - src_phi: angle from +X toward +Y, 0–360°;
 * - corr(v): the data value times the optional multiplier A1 (used for sphere sources, as
 *   `ies2rad` writes for a spherical source: A1 = 1 / projected area).
 * In a light source's `brightdata`, D is the direction of the ray arriving at the source, so the
 * emitted direction is −D; that is why theta is acos(Dz) and phi atan2(−Dy, −Dx).
 */
export const SOURCE_CAL = `{ source.cal: source distribution coordinates (degrees), the definitions of
  Radiance's standard source.cal that this export uses.
  Theta is measured from the negative z-axis (the nadir), phi from the positive
  x-axis (0 degrees) towards the positive y-axis (90 degrees). }

corr(v) = if(AC-.5, A1*v, v);		{ multiplier correction }

src_theta = Acos(Dz) / DEGREE;			{ 0-180 }
src_phi = mod( Atan2(-Dy, -Dx) / DEGREE, 360 );	{ 0-360 }
`;
