import type { Configuration, LightSystem } from '../../core/model/configuration/configuration';
import type { DragPreview } from './dragPreview';

/**
 * The lighting systems as the plan draws them during a drag: a dragged system moved by the
 * pointer's offset (PlanSvg translates its group by the same delta), a system whose module or
 * fixing point is dragged replaced by the controller's preview (the state the release would
 * commit). The on-plan controls are placed from these, so a module's type button, a rail's plus
 * button and a system's move fields stay with what the user sees move instead of jumping there
 * on release. Without a drag (or for an object drag) the configuration's own systems.
 */
export function drawnSystems(config: Configuration, drag: DragPreview | null): readonly LightSystem[] {
  if (!drag) return config.systems;
  if ('preview' in drag) return config.systems.map((s) => (s.id === drag.preview.id ? drag.preview : s));
  if ('systemId' in drag) return config.systems.map((s) => (s.id === drag.systemId ? { ...s, x: s.x + drag.delta.x, z: s.z + drag.delta.z } : s));
  return config.systems;
}
