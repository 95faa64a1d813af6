import type { ModuleTypeSpec } from '../catalogSchema/moduleTypeSchema';

/**
 * The beam a module keeps when its type changes (issue #27, "choices that stick"): the same beam
 * id where the new type offers it (a 30° spot stays 30° as a warm-dim spot); otherwise the beam
 * whose full beam angle is nearest the old one (ties: the narrower); otherwise (no angle to
 * compare: diffusers, washers) the new type's default.
 */
export function beamForType(oldType: ModuleTypeSpec | undefined, oldBeam: string, newType: ModuleTypeSpec): string {
  if (newType.beams.some((b) => b.id === oldBeam)) return oldBeam;
  const angle = oldType?.beams.find((b) => b.id === oldBeam)?.beamAngle;
  if (angle === undefined) return newType.defaultBeam;
  let best: { id: string; gap: number; angle: number } | null = null;
  for (const b of newType.beams) {
    if (b.beamAngle === undefined) continue;
    const gap = Math.abs(b.beamAngle - angle);
    if (!best || gap < best.gap || (gap === best.gap && b.beamAngle < best.angle)) best = { id: b.id, gap, angle: b.beamAngle };
  }
  return best?.id ?? newType.defaultBeam;
}
