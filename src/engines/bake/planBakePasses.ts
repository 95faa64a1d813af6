import type { Rgb, Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { FragmentPass } from '../../../shaders/fragmentPass.glsl';
import { blurPass } from '../../../shaders/blurPass.glsl';
import { combinePass } from '../../../shaders/combinePass.glsl';
import { combineTailPass } from '../../../shaders/combineTailPass.glsl';
import type { BakeSettings } from './bakeSettings';
import { chartBlurPass } from '../../../shaders/chartBlurPass.glsl';
import { chartDilatePass } from '../../../shaders/chartDilatePass.glsl';
import { generateDirectShader, generateShadowedDirectShader, type DirectLamp, type DirectPass, type directUniforms } from './generateDirectShader';
import { generateGatherShader, generateObjectAwareGatherShader, generateObjectGatherShader, type GatherObjects, type gatherUniforms, type objectGatherUniforms } from './generateGatherShader';
import { generateObjectDirectShader, type objectDirectUniforms } from './objects/objectPassDirectShader';
import { lampReachesSurface } from './lampReach';
import type { SurfaceLayout } from './surfaceLayout';

/** Which passes a bake runs, known before any is drawn. */
export interface BakePlan {
  /** Per surface: its direct pass, or null (no luminaire reaches it, or the direct maps are given). */
  direct: (DirectPass<typeof directUniforms> | null)[];
  /** Whether any light enters the room and bounces (bounces > 0, some ρ > 0). */
  indirectEnabled: boolean;
  /** Per surface: its gather pass (empty when indirect is off). */
  gather: FragmentPass<typeof gatherUniforms>[];
  blur: boolean;
  /** Every fragment source the bake will use, to start their compiles together (glResources.startPrograms). */
  sources: string[];
  /** With objects: the atlas's direct pass (null without luminaires) and gather pass (null when indirect is off). */
  objectDirect: DirectPass<typeof objectDirectUniforms> | null;
  objectGather: FragmentPass<typeof objectGatherUniforms> | null;
}

/** What the plan needs to know of a scene's objects (null: none, the empty room's passes exactly). */
export interface PlanObjects extends GatherObjects {
  /** Largest reflectance of any covered atlas texel (any channel). */
  maxReflectance: number;
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
  /** Given direct maps (startFromDirect), per surface and, with objects, the atlas's: no direct passes. */
  directOverride: Readonly<Record<string, Float32Array>> | null,
  objects: PlanObjects | null = null,
  /**
   * The six surfaces are a shaped room's black sinks (shapedRoom/encloseShapedRoom.ts): no direct
   * pass (light that reaches them leaves the room and reflects nothing; the lamps sit inside the
   * room's own surfaces), which spares compiling up to six shadowed programs for one texel each.
   */
  sinks = false,
): BakePlan {
  // With objects, a lamp still reaches every surface it reaches in the empty room (objects only
  // take light away, per point, in the shader); the atlas gets its own pass with every lamp.
  const direct = layouts.map((layout) => {
    if (directOverride || sinks) return null;
    const reaching = lamps.filter((l) => lampReachesSurface(l.sources, l.rotation, l.profile.gammaMin, l.profile.gammaMax, layout));
    if (reaching.length === 0) return null;
    // settings.lampUniforms (a relighting basis): lamps as uniforms, one program per surface and photometry.
    const asUniforms = settings.lampUniforms === true;
    return objects ? generateShadowedDirectShader(layout, reaching, settings.texelSupersampling, objects.bvhWidth, asUniforms) : generateDirectShader(layout, reaching, settings.texelSupersampling, asUniforms);
  });
  const objectDirect = objects && !directOverride && lamps.length > 0 ? generateObjectDirectShader([...lamps], objects.bvhWidth, settings.lampUniforms === true) : null;
  const anyDirect = directOverride ? Object.values(directOverride).some((rgb) => rgb.some((v) => v > 0)) : direct.some((pass) => pass !== null) || objectDirect !== null;
  const maxReflectance = Math.max(...reflectance.flat(), objects ? objects.maxReflectance : 0);
  const indirectEnabled = settings.bounces > 0 && maxReflectance > 0 && anyDirect;
  const gather = indirectEnabled ? layouts.map((layout) => (objects ? generateObjectAwareGatherShader(layout, room, reflectance, objects) : generateGatherShader(layout, room, reflectance))) : [];
  const objectGather = objects && indirectEnabled ? generateObjectGatherShader(room, reflectance, objects) : null;
  const blur = indirectEnabled && settings.blurRadius > 0;
  const sources = [
    ...direct.flatMap((pass) => (pass ? [pass.source] : [])),
    combinePass.source,
    ...(indirectEnabled ? [combineTailPass.source, ...gather.map((pass) => pass.source)] : []),
    ...(blur ? [blurPass.source] : []),
    ...(objectDirect ? [objectDirect.source] : []),
    ...(objectGather ? [objectGather.source] : []),
    ...(objects ? [chartDilatePass.source, ...(blur ? [chartBlurPass.source] : [])] : []),
  ];
  return { direct, indirectEnabled, gather, blur, sources, objectDirect, objectGather };
}
