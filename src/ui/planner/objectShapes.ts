import type { Configuration } from '../../core/model/configuration';
import { placedBounds, sourceMesh } from '../../core/model/objectGeometry';
import type { PlanPoint } from './viewTransform';

/** TEMPORARY until the model's objectOutline lands. */
export function objectPolygons(config: Configuration, objectId: string): PlanPoint[][] {
  const o = config.objects.find((x) => x.id === objectId);
  if (!o) return [];
  const mesh = sourceMesh(config, o.source);
  if (!mesh) return [];
  const b = placedBounds(o, mesh, config.room);
  return [[{ x: b.min[0], z: b.min[2] }, { x: b.max[0], z: b.min[2] }, { x: b.max[0], z: b.max[2] }, { x: b.min[0], z: b.max[2] }]];
}
