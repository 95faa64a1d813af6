import type { Rgb, SurfaceName, Vec3 } from '../../core/model/lightingScene';
import type { FragmentPass } from '../../../shaders/fragmentPass.glsl';
import { blurPass } from '../../../shaders/blurPass.glsl';
import { combinePass } from '../../../shaders/combinePass.glsl';
import { combineTailPass } from '../../../shaders/combineTailPass.glsl';
import type { BakeSettings } from './bakeSettings';
import { generateDirectShader, type DirectLamp, type directUniforms } from './generateDirectShader';
import { generateGatherShader, type gatherUniforms } from './generateGatherShader';
import { lampReachesSurface } from './lampReach';
import type { SurfaceLayout } from './surfaceLayout';

/** Which passes a bake runs, known before any is drawn. */
export interface BakePlan {
  /** Per surface: its direct pass, or null (no luminaire reaches it, or the direct maps are given). */
  direct: (FragmentPass<typeof directUniforms> | null)[];
  /** Whether any light enters the room and bounces (bounces > 0, some ρ > 0). */
  indirectEnabled: boolean;
  /** Per surface: its gather pass (empty when indirect is off). */
  gather: FragmentPass<typeof gatherUniforms>[];
  blur: boolean;
  /** Every fragment source the bake will use, to start their compiles together (glResources.startPrograms). */
  sources: string[];
}

/**
 * The passes of a bake. A surface gets a direct pass only if some luminaire
 * can reach it (lampReach.ts); whether any light was emitted is known on the
 * CPU, so a dark or black room compiles no indirect code at all.
 */
export function planBakePasses(
  layouts: readonly SurfaceLayout[],
  lamps: readonly DirectLamp[],
  room: Vec3,
  reflectance: Rgb[],
  settings: BakeSettings,
  directOverride: Record<SurfaceName, Float32Array> | null,
): BakePlan {
  const direct = layouts.map((layout) => {
    if (directOverride) return null;
    const reaching = lamps.filter((l) => lampReachesSurface(l.sources, l.rotation, l.profile.gammaMin, l.profile.gammaMax, layout));
    return reaching.length > 0 ? generateDirectShader(layout, reaching, settings.texelSupersampling) : null;
  });
  const anyDirect = directOverride ? Object.values(directOverride).some((rgb) => rgb.some((v) => v > 0)) : direct.some((pass) => pass !== null);
  const indirectEnabled = settings.bounces > 0 && Math.max(...reflectance.flat()) > 0 && anyDirect;
  const gather = indirectEnabled ? layouts.map((layout) => generateGatherShader(layout, room, reflectance)) : [];
  const blur = indirectEnabled && settings.blurRadius > 0;
  const sources = [
    ...direct.flatMap((pass) => (pass ? [pass.source] : [])),
    combinePass.source,
    ...(indirectEnabled ? [combineTailPass.source, ...gather.map((pass) => pass.source)] : []),
    ...(blur ? [blurPass.source] : []),
  ];
  return { direct, indirectEnabled, gather, blur, sources };
}
