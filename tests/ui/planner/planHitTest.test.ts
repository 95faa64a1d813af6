import { describe, expect, it } from 'vitest';
import { demoConfiguration } from '../../../src/core/catalog/demoConfiguration';
import { modulePlacements, railPlacements } from '../../../src/core/model/rails/geometry';
import { HIT_HALF_WIDTH_PX, planHitTest } from '../../../src/ui/planner/planHitTest';
import { worldToScreen } from '../../../src/ui/planner/viewTransform';
import { catalog } from './testPlanner';

const config = demoConfiguration(catalog);
const system = config.systems[0];
const view = { scale: 150, offsetX: 40, offsetY: 30 };

/** A point `px` screen pixels to the side of the first rail, a tenth of the way along it (before its first module). */
function besideRail(px: number) {
  const r = railPlacements(system, catalog)[0];
  const a = worldToScreen(view, { x: r.start[0], z: r.start[1] });
  const b = worldToScreen(view, { x: r.end[0], z: r.end[1] });
  const len = Math.hypot(b.sx - a.sx, b.sy - a.sy);
  const [ux, uy] = [(b.sx - a.sx) / len, (b.sy - a.sy) / len];
  return { sx: a.sx + ux * len * 0.02 - uy * px, sy: a.sy + uy * len * 0.02 + ux * px };
}

describe('planHitTest: what the drawn plan has under a point', () => {
  it('a rail is hit within its 22 px strip on either side, not beyond', () => {
    const rail = { systemId: system.id, railId: system.rails[0].id };
    expect(planHitTest(config, catalog, view, besideRail(0))).toEqual(rail);
    expect(planHitTest(config, catalog, view, besideRail(HIT_HALF_WIDTH_PX - 1))).toEqual(rail);
    expect(planHitTest(config, catalog, view, besideRail(-(HIT_HALF_WIDTH_PX - 1)))).toEqual(rail);
    expect(planHitTest(config, catalog, view, besideRail(HIT_HALF_WIDTH_PX + 2))).toEqual({});
  });

  it('modules lie above their rail; the empty floor hits nothing', () => {
    const m = modulePlacements(system, catalog)[1];
    expect(planHitTest(config, catalog, view, worldToScreen(view, { x: m.centre[0], z: m.centre[1] }))).toEqual({ systemId: system.id, moduleId: m.moduleId });
    expect(planHitTest(config, catalog, view, worldToScreen(view, { x: 0.05, z: 0.05 }))).toEqual({});
  });
});
