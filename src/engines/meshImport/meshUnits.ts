/**
 * Length units of an imported model and their automatic detection (docs/scene-format.md,
 * "Importing meshes"). OBJ has no unit at all (exporters write metres, centimetres or millimetres);
 * glTF is metres by specification (glTF 2.0, §3.4 "Coordinate System and Units").
 */
export const MESH_UNITS = ['m', 'cm', 'mm', 'in'] as const;
export type MeshUnit = (typeof MESH_UNITS)[number];
export type MeshUnitsOption = 'auto' | MeshUnit;

/** Metres per file unit. */
export const METRES_PER_UNIT: Record<MeshUnit, number> = { m: 1, cm: 0.01, mm: 0.001, in: 0.0254 };

/**
 * The range of plausible sizes for furniture, fixtures and kitchens: the largest bounding-box edge
 * of a real object lies between a 5 cm vase and a 30 m shop counter.
 */
export const PLAUSIBLE_EXTENT_M = { min: 0.05, max: 30 } as const;

/**
 * The unit that makes a model's largest extent `extent` (in file units) a plausible object size,
 * trying metres, then centimetres, millimetres and inches in that order; null when none does
 * (the caller keeps metres and warns). Metres first: a model that fits in metres is taken as
 * metres even if it would also fit in centimetres (0.05–30 file units). Inches are therefore only
 * picked where no metric unit fits, which never happens for a plausible size (their range is
 * covered by m and cm); the user overrides the choice when the file was written in inches.
 */
export function detectUnits(extent: number): MeshUnit | null {
  if (!(extent > 0) || !Number.isFinite(extent)) return null;
  for (const unit of MESH_UNITS) {
    const metres = extent * METRES_PER_UNIT[unit];
    if (metres >= PLAUSIBLE_EXTENT_M.min && metres <= PLAUSIBLE_EXTENT_M.max) return unit;
  }
  return null;
}
