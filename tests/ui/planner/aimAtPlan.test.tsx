/**
 * Aim at from the plan (docs/aiming.md): with aim-at mode on for an adjustable module, a tap on
 * the plan aims it at that floor point (one undoable aimAt: its axis through the point) and ends
 * the mode, instead of selecting; with the mode off a tap selects as before. The aim options show
 * the aim and offer aim at only for adjustable modules.
 */
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { modulePlacements } from '../../../src/core/model/rails/geometry';
import { aimAxis } from '../../../src/core/model/modules/aim';
import { modulePosition } from '../../../src/core/model/actions/aimActions';
import { aimAtMode } from '../../../src/ui/shared/aimAtMode';
import { AimOptions } from '../../../src/ui/planner/AimOptions';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import { TestPlanner, catalog } from './testPlanner';

const spotOf = (t: TestPlanner) => {
  for (const s of t.config.systems) for (const r of s.rails) for (const m of r.modules) if (catalog.moduleTypes.find((x) => x.id === m.type)?.adjustable) return { system: s, module: m };
  throw new Error('the demo has no adjustable module');
};

describe('aim at in the plan', () => {
  it('a tap aims the module at the floor point and ends the mode; the next tap only selects', () => {
    const t = new TestPlanner();
    const { system, module } = spotOf(t);
    const mode = aimAtMode(t.store);
    mode.set(module.id);
    const from = modulePosition(t.config, module.id, catalog);
    // A floor point 1.2 m from the module in plan, inside the room.
    const target = { x: Math.min(t.config.room.width - 0.2, from[0] + 1.2), z: from[2] };
    const at = t.screenOf(target);
    const past = t.store.getState().history.past.length;
    t.controller.pointerDown(at);
    t.controller.pointerUp(at);
    expect(mode.get()).toBeNull();
    expect(t.store.getState().history.past).toHaveLength(past + 1);
    const aimed = t.config.systems
      .find((s) => s.id === system.id)!
      .rails.flatMap((r) => r.modules)
      .find((m) => m.id === module.id)!;
    expect(aimed.aim).toBeDefined();
    const heading = modulePlacements(system, catalog).find((p) => p.moduleId === module.id)!.heading;
    const axis = aimAxis(heading, aimed.aim);
    // The axis goes through the tapped floor point (screen rounding: a few mm at this zoom).
    const s = -from[1] / axis[1];
    expect(from[0] + s * axis[0]).toBeCloseTo(target.x, 1);
    expect(from[2] + s * axis[2]).toBeCloseTo(target.z, 1);
    // Mode off: a tap selects as usual (whatever lies there) and aims nothing.
    const config = t.config;
    t.controller.pointerDown(at);
    t.controller.pointerUp(at);
    expect(t.config).toBe(config);
  });

  it('aim options: the aim in degrees, straight down, and the aim-at toggle with its status while on', () => {
    const t = new TestPlanner();
    const { module } = spotOf(t);
    t.store.getState().dispatch('setAim', { moduleId: module.id, aim: { rotation: 30, tilt: 25 } });
    const aimed = t.config.systems.flatMap((s) => s.rails.flatMap((r) => r.modules)).find((m) => m.id === module.id)!;
    expect(aimed.aim).toEqual({ rotation: 30, tilt: 25 });
    const gate = createActionGate(
      t.config,
      catalog,
      () => {},
      () => {},
    );
    const mode = aimAtMode(t.store);
    const html = () => renderToStaticMarkup(<AimOptions module={aimed} catalog={catalog} gate={gate} aimMode={mode} />);
    expect(html()).toContain('data-rotation="30" data-tilt="25"');
    expect(html()).toContain('data-testid="aim-straight-down"');
    expect(html()).toContain('aria-pressed="false"');
    expect(html()).not.toContain('aim-at-status');
    mode.set(module.id);
    expect(html()).toContain('aim-at-status');
    expect(html()).toContain('aria-pressed="true"');
    mode.set(null);
  });

  it('no aim options for a fixed module', () => {
    const t = new TestPlanner();
    const fixed = t.config.systems.flatMap((s) => s.rails.flatMap((r) => r.modules)).find((m) => !catalog.moduleTypes.find((x) => x.id === m.type)?.adjustable);
    expect(fixed).toBeDefined();
    const gate = createActionGate(
      t.config,
      catalog,
      () => {},
      () => {},
    );
    expect(renderToStaticMarkup(<AimOptions module={fixed!} catalog={catalog} gate={gate} aimMode={aimAtMode(t.store)} />)).toBe('');
  });
});
