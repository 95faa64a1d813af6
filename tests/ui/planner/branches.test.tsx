/**
 * Branch editing in the planner (docs/planner.md, "Branches"): a selected rail's end shows its
 * connector, the free ports (a branch through each) and the connectors it can become, every button
 * gated by the model with its reason; a free end offers a branch through any connector. The plan's
 * elements hold the T as one node, and a tap on it selects the rail it ends.
 * The tree (tests/core/model/rails/trees.test.ts, by hand): the 1.5 m single preset at (1, 3) heading +x,
 * a T at its end (pivot (2.55, 3)), B through it to (3.6, 3), C left (−z) to (2.55, 1.95).
 */
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { systemElementTree } from '../../../src/core/model/rails/geometry';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import { planHitTest } from '../../../src/ui/planner/planHitTest';
import { RailOptions } from '../../../src/ui/planner/RailOptions';
import { worldToScreen } from '../../../src/ui/planner/viewTransform';
import { catalog } from './testPlanner';

const run = (s: Configuration, name: string, params: unknown) => {
  const a = bindAction(name, params, catalog);
  expect(a.isEnabled(s)).toBe(true);
  return a.perform(s);
};
const placed = run(createConfiguration({ width: 8, depth: 6, height: 3 }), 'placePreset', { presetId: 'single', x: 1, z: 3 });
const a = placed.systems[0].rails[0].id;
const tree = run(run(placed, 'addBranch', { railId: a, connector: 'tee', turn: 0, length: 1 }), 'addBranch', { railId: a, turn: 90, length: 1 });
const sys = tree.systems[0];
const render = (railIndex: number) =>
  renderToStaticMarkup(
    <RailOptions
      rail={sys.rails[railIndex]}
      system={sys}
      catalog={catalog}
      gate={createActionGate(
        tree,
        catalog,
        () => {},
        () => {},
      )}
      onClose={() => {}}
    />,
  );
const control = (html: string, testId: string) => new RegExp(`<button[^>]*data-testid="${testId}"[^>]*>`).exec(html)?.[0] ?? '';

describe('planner: branches of a tree', () => {
  it("a rail's connector: its free port, gated; the connectors it can become, with reasons", () => {
    const html = render(0);
    expect(html).toContain('End of rail 1');
    expect(html).toContain('T-connector: 0 of 3 ports free');
    // The right port (−90) is the only one not taken; the T has no free port, so it is disabled with the model's reason.
    expect(control(html, `branch-${a}-tee--90`)).toContain('aria-disabled="true"');
    expect(control(html, `branch-${a}-tee--90`)).toContain('the T-connector at the end of this rail has no free port; change it to one with more ports');
    expect(control(html, `branch-${a}-tee-0`)).toBe('');
    expect(control(html, `connector-${a}-cross`)).not.toContain('aria-disabled');
    expect(control(html, `connector-${a}-straight`)).toContain('the Straight connector joins 2 rail ends; 2 branches leave this connector');
    expect(control(html, `connector-${a}-tee`)).toContain('aria-pressed="true"');
  });

  it('a free end offers a branch through every connector', () => {
    const html = render(1);
    expect(html).toContain('Free end: add a branch through a connector');
    // B ends at (3.6, 3): a T's left branch runs to z = 1.9, inside the room.
    expect(control(html, `branch-${sys.rails[1].id}-tee-90`)).not.toContain('aria-disabled');
    // C ends at (2.55, 1.95) heading −z: straight on through a T the 1 m branch reaches z = 0.85, inside the room.
    expect(control(render(2), `branch-${sys.rails[2].id}-tee-0`)).not.toContain('aria-disabled');
  });

  it('the plan draws the T as one node; selecting it selects the rail it ends', () => {
    const view = { scale: 100, offsetX: 0, offsetY: 0 };
    // What PlanSvg draws: rail A, the T (its incoming arm and one arm per branch), B, C.
    const { elements, kinds } = systemElementTree(sys, catalog);
    expect(kinds).toEqual([
      { kind: 'rail', rail: 0 },
      { kind: 'node', rail: 0 },
      { kind: 'rail', rail: 1 },
      { kind: 'rail', rail: 2 },
    ]);
    expect(elements[1].length).toBe(3);
    const hit = planHitTest(tree, catalog, view, worldToScreen(view, { x: 2.55, z: 3 }));
    expect(hit).toEqual({ systemId: sys.id, railId: a });
  });
});
