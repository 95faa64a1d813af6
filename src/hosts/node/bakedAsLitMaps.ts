import { SURFACE_NAMES, type SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { BakedMaps } from '../../engines/bake/bakedMaps';
import type { SurfaceLayout } from '../../engines/bake/surfaceLayout';
import type { LitMaps } from '../../engines/relight/relightMaps';

/** A whole bake's maps as the view takes relit ones (direct and total per surface and for the atlas; the arrays are shared, not copied). */
export function bakedAsLitMaps(maps: BakedMaps): LitMaps {
  const layouts = Object.fromEntries(SURFACE_NAMES.map((n) => [n, maps[n].layout])) as Record<SurfaceName, SurfaceLayout>;
  const surfaces = Object.fromEntries(SURFACE_NAMES.map((n) => [n, { direct: maps[n].direct, total: maps[n].total }])) as LitMaps['maps'];
  const objects = maps.objects ? { objects: { atlas: maps.objects.atlas, direct: maps.objects.direct, total: maps.objects.total } } : {};
  return { layouts, maps: { ...surfaces, ...objects } };
}
