import { systemBounds } from '../../core/model/rails/geometry';
import type { ConfiguratorState } from '../../core/store/createConfiguratorStore';
import { selectionPath } from './selection';
import { type PlanView, type ScreenPoint, type Viewport, worldToScreen } from './viewTransform';

/**
 * Where buttons and keys zoom about: the selected system's centre when it is on screen (so zooming
 * in on it reaches the module level without panning), else the middle of the plan.
 */
export function zoomAnchor(state: Pick<ConfiguratorState, 'config' | 'catalog' | 'selection'>, view: PlanView, viewport: Viewport): ScreenPoint {
  const { config, catalog, selection } = state;
  const { width, height } = viewport;
  const systemId = selectionPath(config, selection).systemId;
  const system = config.systems.find((s) => s.id === systemId);
  if (system) {
    const b = systemBounds(system, catalog);
    const c = worldToScreen(view, { x: (b.minX + b.maxX) / 2, z: (b.minZ + b.maxZ) / 2 });
    if (c.sx >= 0 && c.sy >= 0 && c.sx <= width && c.sy <= height) return c;
  }
  return { sx: width / 2, sy: height / 2 };
}
