import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { demoConfiguration } from '../../../src/core/catalog/demoConfiguration';
import type { Configuration } from '../../../src/core/model/configuration/configuration';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import { GatedButton } from '../../../src/ui/planner/GatedButton';
import { OptionsPanel } from '../../../src/ui/planner/OptionsPanel';
import type { SelectionPath } from '../../../src/ui/planner/selection';
import { catalog } from './testPlanner';

const config = demoConfiguration(catalog);
const system = config.systems[0];
const gate = (c: Configuration = config, runs: [string, unknown][] = []) =>
  createActionGate(
    c,
    catalog,
    (n, p) => runs.push([n, p]),
    () => {},
  );
const panel = (path: SelectionPath) => renderToStaticMarkup(<OptionsPanel config={config} catalog={catalog} path={path} gate={gate()} onClose={() => {}} />);
const title = (html: string) => /<h2[^>]*>([^<]*)<\/h2>/.exec(html)?.[1];

describe('options panel: one component per selection kind', () => {
  it('the deepest selected part decides: module, rail, system, else the room', () => {
    const rail = system.rails[1];
    const module = system.rails[0].modules[0];
    const type = catalog.moduleTypes.find((t) => t.id === module.type)!;
    expect(title(panel({ systemId: system.id, railId: system.rails[0].id, moduleId: module.id }))).toBe(`Module: ${type.name}`);
    const railHtml = panel({ systemId: system.id, railId: rail.id });
    expect(title(railHtml)).toBe('Rail 2');
    // Any rail of a chain of two or more can be removed (a middle one splits the chain: docs/model.md "Removing a rail").
    expect(railHtml).toContain('aria-label="Remove this rail"');
    expect(panel({ systemId: system.id, railId: system.rails[0].id })).toContain('Remove this rail');
    expect(title(panel({ systemId: system.id }))).toBe('Lighting system');
    const room = panel({});
    expect(title(room)).toBe('Room');
    expect(room).toContain('aria-label="Room width (m)"');
    expect(room).toContain('aria-label="Room height (m)"');
  });
});

describe('GatedButton: the gate pattern in one place', () => {
  it("enabled as the model says, with the model's reason as the disabled title; the current choice is pressed and never refused", () => {
    const g = gate();
    const enabled = renderToStaticMarkup(<GatedButton gate={g} action="rotateSystem" params={{ systemId: system.id, by: 15 }} label="Turn" />);
    const refused = renderToStaticMarkup(<GatedButton gate={g} action="deleteSystem" params={{ systemId: 'nope' }} label="Delete" />);
    const reason = g.reason('deleteSystem', { systemId: 'nope' })!;
    expect(reason).toBeTruthy();
    expect(refused).toContain('aria-disabled="true"');
    expect(refused).toContain(`title="Delete: ${reason.replace(/'/g, '&#x27;')}"`);
    expect(enabled).not.toContain('aria-disabled');
    const current = renderToStaticMarkup(<GatedButton gate={g} action="deleteSystem" params={{ systemId: 'nope' }} label="Current" current />);
    expect(current).toContain('aria-pressed="true"');
    expect(current).not.toContain('aria-disabled');
  });

  it('attempt runs an enabled action and returns null, or returns the reason and runs nothing', () => {
    const runs: [string, unknown][] = [];
    const g = gate(config, runs);
    expect(g.attempt('setSuspension', { systemId: system.id, suspension: 0.5 })).toBeNull();
    expect(runs).toEqual([['setSuspension', { systemId: system.id, suspension: 0.5 }]]);
    const tooLong = g.reason('setSuspension', { systemId: system.id, suspension: 99 });
    expect(tooLong).not.toBeNull();
    expect(g.attempt('setSuspension', { systemId: system.id, suspension: 99 })).toBe(tooLong);
    expect(runs).toHaveLength(1);
  });
});
