import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { FURNITURE_LIBRARY } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import { OBJECT_FINISHES } from '../../../src/core/model/objects/furniture/objectFinishes';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import { FurniturePanel, itemDimensions } from '../../../src/ui/planner/FurniturePanel';
import { objectFillColour } from '../../../src/ui/planner/objectColour';
import { OptionsPanel } from '../../../src/ui/planner/OptionsPanel';
import { catalog } from './testPlanner';

function withItems(items: { item: string; x: number; z: number }[], room = {}): Configuration {
  const store = createConfiguratorStore({ catalog, initial: createConfiguration(room) });
  for (const { item, x, z } of items) {
    const r = store.getState().dispatch('addObject', { source: { kind: 'library', item }, placement: { on: 'floor', x, z } });
    if (!r.ok) throw new Error(r.reason);
  }
  return store.getState().config;
}

const gate = (c: Configuration) =>
  createActionGate(
    c,
    catalog,
    () => {},
    () => {},
  );
const decode = (html: string) => html.replace(/&#x27;/g, "'").replace(/&amp;/g, '&');

describe('object options', () => {
  it('a selected sofa shows its name, its real size in cm at its scale, rotation, a finish select per material and remove', () => {
    const config = withItems([{ item: 'sofa', x: 2.5, z: 2 }]);
    const o = config.objects[0];
    const html = decode(renderToStaticMarkup(<OptionsPanel config={config} catalog={catalog} path={{ objectId: o.id }} gate={gate(config)} onClose={() => {}} />));
    expect(html).toContain('Sofa (three seats)');
    expect(html).toContain('210 × 90 × 85 cm');
    expect(html).toContain('aria-label="Scale (× real size)"');
    expect(html).toContain('aria-label="Rotation (°)"');
    for (const m of ['frame', 'cushions', 'legs']) expect(html).toContain(`data-testid="object-finish-${m}"`);
    // The default is named after the library's finish; every object finish is offered.
    expect(html).toContain('Default: Grey fabric');
    for (const f of OBJECT_FINISHES) expect(html).toContain(`>${f.name} — reflects `);
    expect(html).toContain('aria-label="Remove Sofa (three seats)"');
  });

  it("a refused turn is disabled with the model's reason (a sofa against the north wall cannot turn)", () => {
    const config = withItems([{ item: 'sofa', x: 2.5, z: 0.45 }]);
    const o = config.objects[0];
    const g = gate(config);
    const reason = g.reason('rotateObject', { objectId: o.id, by: 15 });
    expect(reason).not.toBeNull();
    const html = decode(renderToStaticMarkup(<OptionsPanel config={config} catalog={catalog} path={{ objectId: o.id }} gate={g} onClose={() => {}} />));
    expect(html).toContain(`title="Rotate left 15°: ${reason}"`);
  });

  it('the size follows the scale: a dining table at 1.2 × is 216 × 108 × 90 cm', () => {
    const config = withItems([{ item: 'dining-table', x: 2.5, z: 2 }]);
    const scaled = { ...config, objects: [{ ...config.objects[0], scale: 1.2 }] };
    const html = renderToStaticMarkup(<OptionsPanel config={scaled} catalog={catalog} path={{ objectId: scaled.objects[0].id }} gate={gate(scaled)} onClose={() => {}} />);
    expect(html).toContain('216 × 108 × 90 cm');
  });

  it("the plan fills a table with its top's finish (oak veneer, #ba9b6f) and follows a refinish", () => {
    const config = withItems([{ item: 'dining-table', x: 2.5, z: 2 }]);
    const id = config.objects[0].id;
    expect(objectFillColour(config, id)).toBe('#ba9b6f');
    const refinished = { ...config, objects: [{ ...config.objects[0], finishes: { top: 'white-lacquer' } }] };
    expect(objectFillColour(refinished, id)).toBe('#e7e7e7');
  });
});

describe('furniture panel', () => {
  it('lists every library item with its name and real size; an item that cannot fit the room is disabled with the reason', () => {
    // A 1.5 × 1.5 m room: the 2.15 m bed and the 2.1 m sofa do not fit.
    const config = withItems([], { width: 1.5, depth: 1.5 });
    const html = decode(renderToStaticMarkup(<FurniturePanel gate={gate(config)} onAdd={() => {}} />));
    for (const item of FURNITURE_LIBRARY) expect(html).toContain(`aria-label="Add ${item.name}, ${itemDimensions(item)}"`);
    expect(itemDimensions(FURNITURE_LIBRARY.find((i) => i.id === 'dining-table')!)).toBe('180 × 90 × 75 cm');
    const bed = /<button[^>]*data-testid="furniture-bed"[^>]*>/.exec(html)![0];
    expect(bed).toContain('aria-disabled="true"');
    const chair = /<button[^>]*data-testid="furniture-chair"[^>]*>/.exec(html)![0];
    expect(chair).not.toContain('aria-disabled');
  });
});
