/**
 * The on-plan controls follow a drag live (docs/planner.md, "Moving a module"): a module's type
 * button sits under the module as the plan draws it while it is dragged, not where it was before
 * the press; a dragged system's move fields go with the system and show where it would land.
 * Screen positions by hand from the view (px = metres · scale + offset); tolerance 1e-6 px.
 */
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import { detailLevel } from '../../../src/ui/planner/detailLevel';
import { PlanControls } from '../../../src/ui/planner/PlanControls';
import { selectionPath } from '../../../src/ui/planner/selection';
import { zoomAt } from '../../../src/ui/planner/viewTransform';
import { TestPlanner, catalog, twoRailSystem } from './testPlanner';

/** The controls as the planner renders them now, with the controller's drag. */
function controls(t: TestPlanner): string {
  const config = t.config;
  const gate = createActionGate(
    config,
    catalog,
    () => {},
    () => {},
  );
  const path = selectionPath(config, t.store.getState().selection);
  return renderToStaticMarkup(
    <PlanControls config={config} catalog={catalog} view={t.view} viewport={t.controller.viewport} level={detailLevel(t.view.scale)} selection={path} gate={gate} onSelect={() => {}} onOpenOptions={() => {}} drag={t.controller.drag} />,
  );
}

/** The screen point a control with this test id is placed at (its translate(x px, y px)). */
function placedAt(html: string, testId: string): { sx: number; sy: number } {
  const m = new RegExp(`style="transform:translate\\(([-\\d.e]+)px, ?([-\\d.e]+)px\\)[^"]*" data-plan-control="[^"]*" data-testid="${testId}"`).exec(html);
  if (!m) throw new Error(`no control ${testId} in ${html.slice(0, 400)}`);
  return { sx: Number(m[1]), sy: Number(m[2]) };
}

describe('on-plan controls during a drag', () => {
  it("a module's type button follows the module while it is dragged, before the release", () => {
    const t = new TestPlanner(twoRailSystem());
    t.controller.setView(zoomAt(t.view, t.screenOf({ x: 1.75, z: 1 }), 2.5), false);
    expect(detailLevel(t.view.scale)).toBe('module');
    const { scale, offsetX, offsetY } = t.view;
    // The rail runs along +x at z = 1, so "below" it (the type buttons' side) is +34 px on screen.
    const below = (x: number) => ({ sx: x * scale + offsetX, sy: 1 * scale + offsetY + 34 });
    // Before: the linear m4 spans 0.15–0.75 m of the rail from x = 1: centre x = 1.45 m.
    let p = placedAt(controls(t), 'module-m4');
    expect(p.sx).toBeCloseTo(below(1.45).sx, 6);
    expect(p.sy).toBeCloseTo(below(1.45).sy, 6);

    // Drag it 0.33 m along the rail: moveModule snaps the start 0.48 → 0.5 m, centre 0.8 m along = x 1.8 m.
    const from = t.moduleCentre(1);
    t.controller.pointerDown(from);
    t.controller.pointerMove({ sx: from.sx + 0.33 * scale, sy: from.sy + 0.2 * scale });
    expect(t.config.systems[0].rails[0].modules[1].offset).toBeUndefined(); // not committed yet
    p = placedAt(controls(t), 'module-m4');
    expect(p.sx).toBeCloseTo(below(1.8).sx, 6);
    expect(p.sy).toBeCloseTo(below(1.8).sy, 6);
    // The spot m3 did not move: its button stays at its centre 0.075 m along.
    expect(placedAt(controls(t), 'module-m3').sx).toBeCloseTo(below(1.075).sx, 6);

    // After the release the committed configuration puts it at the same place.
    t.controller.pointerUp({ sx: from.sx + 0.33 * scale, sy: from.sy + 0.2 * scale });
    expect(t.controller.drag).toBeNull();
    expect(placedAt(controls(t), 'module-m4').sx).toBeCloseTo(below(1.8).sx, 6);
  });

  it("a dragged system's move fields go with it and show where it would land", () => {
    const t = new TestPlanner(twoRailSystem());
    t.store.getState().select({ kind: 'system', id: 's1' });
    expect(detailLevel(t.view.scale)).toBe('system');
    const before = placedAt(controls(t), 'move-s1');
    const k = t.view.scale;
    const from = t.railCentre(0);
    t.controller.pointerDown(from);
    t.controller.pointerMove({ sx: from.sx + 0.5 * k, sy: from.sy + 0.25 * k });
    const d = t.controller.drag;
    expect(d && 'systemId' in d ? [d.delta.x, d.delta.z] : null).toEqual([expect.closeTo(0.5, 9), expect.closeTo(0.25, 9)]);
    const html = controls(t);
    const during = placedAt(html, 'move-s1');
    expect(during.sx - before.sx).toBeCloseTo(0.5 * k, 6);
    expect(during.sy - before.sy).toBeCloseTo(0.25 * k, 6);
    // The fields read the position the drop would commit: x 1 + 0.5, z 1 + 0.25 (two decimals).
    expect(html).toContain('value="1.50"');
    expect(html).toContain('value="1.25"');
  });
});
