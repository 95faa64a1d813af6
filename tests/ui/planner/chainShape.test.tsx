/**
 * The planner's flexible-connector and fixing-point controls (issue 11, part 3): each flexible
 * joint's angle field and steps, gated by the model with its reasons; every fixing point listed
 * with its position (a field, or fixed at its connector).
 */
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import { SystemOptions } from '../../../src/ui/planner/SystemOptions';
import { catalog } from './testPlanner';

const run = (s: Configuration, name: string, params: unknown) => {
  const a = bindAction(name, params, catalog);
  expect(a.isEnabled(s)).toBe(true);
  return a.perform(s);
};
// The single preset (a 1.5 m rail at (1, 1) heading +x), extended by a 0.5 m rail through the flexible connector at
// 90° left: the hinge at (2.56, 1), the new rail from z = 0.94 to 0.44 (inside the 6 × 4 m room).
const placed = run(createConfiguration({ width: 6, depth: 4, height: 3 }), 'placePreset', { presetId: 'single', x: 1, z: 1 });
const config = run(placed, 'addRail', { systemId: placed.systems[0].id, connector: 'flex', turn: 90, length: 0.5 });
const render = (c: Configuration) =>
  renderToStaticMarkup(
    <SystemOptions
      system={c.systems[0]}
      catalog={catalog}
      gate={createActionGate(
        c,
        catalog,
        () => {},
        () => {},
      )}
      onClose={() => {}}
    />,
  );
const html = render(config);
const control = (testId: string) => new RegExp(`<(?:button|input)[^>]*data-testid="${testId}"[^>]*>`).exec(html)?.[0] ?? '';

describe('system options: flexible connector angle', () => {
  it('shows the angle field and steps; a step that leaves the range is disabled with the reason', () => {
    expect(control('joint-angle-field-0')).toContain('value="90"');
    expect(control('joint-right-0')).not.toContain('aria-disabled');
    expect(control('joint-straight-0')).not.toContain('aria-disabled');
    // 95° is past the connector's range: disabled, the model's reason as its title.
    expect(control('joint-left-0')).toContain('aria-disabled="true"');
    expect(control('joint-left-0')).toContain('the Flexible-angle connector turns at most ±90°');
    expect(html).toContain('Flexible-angle connector: ±90° in steps of 5°');
  });
  it('lists every fixing point: fields on rails, fixed at the connector', () => {
    // 1.5 m rail: inset 0.375; hinge at 1.56; 0.5 m rail: 1.62 + 0.5 − 0.125 = 1.995
    expect(control('fixing-field-0')).toContain('value="0.38"');
    expect(html).toContain('1.56 m, at connector 1 (a connector is always a support)');
    expect(control('fixing-field-2')).toContain('value="2.00"');
    expect(html).toContain('placed by the rules');
    const moved = run(config, 'moveFixingPoint', { systemId: config.systems[0].id, index: 0, s: 0.3 });
    expect(render(moved)).toContain('moved by hand');
  });
});
