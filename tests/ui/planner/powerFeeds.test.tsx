/**
 * The planner's power and mounting controls (issue 11): load per feed where the user works,
 * driver choices and feed removal gated by the model with its reasons, the installation-needs
 * summary next to the bill of materials, and the derived fixings and feeds drawn in the plan.
 */
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../src/core/model/actions/actionDefinitions';
import { billOfMaterials } from '../../../src/core/model/power/billOfMaterials';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { installationNeeds } from '../../../src/core/model/power/installationNeeds';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import { BomPanel } from '../../../src/ui/planner/BomPanel';
import { SystemOptions } from '../../../src/ui/planner/SystemOptions';
import { catalog } from './testPlanner';

const run = (s: Configuration, name: string, params: unknown) => {
  const a = bindAction(name, params, catalog);
  expect(a.isEnabled(s)).toBe(true);
  return a.perform(s);
};
// The single preset: three 43 W spots on a 1.5 m rail, fed at its start by the 240 W HLG-240H-48 it ships with (room for two more).
const config = run(createConfiguration({ width: 6, depth: 4, height: 3 }), 'placePreset', { presetId: 'single', x: 1, z: 1 });
const system = config.systems[0];
const feed = system.feeds[0];
const html = renderToStaticMarkup(
  <SystemOptions
    system={system}
    catalog={catalog}
    gate={createActionGate(
      config,
      catalog,
      () => {},
      () => {},
    )}
    onClose={() => {}}
  />,
);
const control = (testId: string) => new RegExp(`<button[^>]*data-testid="${testId}"[^>]*>`).exec(html)?.[0] ?? '';

describe('system options: power and mounting', () => {
  it('shows the load per feed and what is left', () => {
    expect(html).toContain('Feed 1: 129 / 240 W');
    expect(html).toContain('at the chain start, 111 W left');
  });
  it("drivers too small for the load are disabled with the model's reason; the current one is pressed", () => {
    expect(control(`driver-${feed.id}-lpv-60-48`)).toContain('aria-disabled="true"');
    expect(control(`driver-${feed.id}-lpv-60-48`)).toContain('cannot carry the 129 W on Feed 1');
    expect(control(`driver-${feed.id}-hlg-240h-48`)).toContain('aria-pressed="true"');
    expect(control(`driver-${feed.id}-hlg-150h-48`)).not.toContain('aria-disabled');
    expect(control(`remove-feed-${feed.id}`)).toContain('a system keeps at least one power feed');
    // the only free position on one rail is its end
    expect(control('add-feed-end')).not.toContain('aria-disabled');
    expect(html).not.toContain('add-feed-start');
  });
  it('mounting: suspended is current, the ceiling surface is offered', () => {
    expect(control('mounting-suspended')).toContain('aria-pressed="true"');
    expect(control('mounting-surface')).not.toContain('aria-disabled');
  });
});

describe('bill of materials panel: installation needs', () => {
  it('lists feeds with load and capacity, the ceiling fixings and the total load', () => {
    const out = renderToStaticMarkup(<BomPanel bom={billOfMaterials(config, catalog)} needs={installationNeeds(config, catalog)} locale="en-GB" />);
    expect(out).toContain('MW-HLG-240H-48');
    // 1.5 m rail: suspensions at 0.375 and 1.125 m
    expect(out).toContain('1 power feed, 2 ceiling fixings, 129 W in total');
    expect(out).toContain('Feed 1: 129 / 240 W (Mean Well HLG-240H-48, 48 V DC)');
  });
});
