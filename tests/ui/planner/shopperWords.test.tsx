/**
 * Words and pictures for shoppers (issue 27; docs/planner.md, "Words for shoppers"): distribution
 * options as pictures of the rail drawn from the model's own layout, Extend-the-chain buttons named
 * by direction with an arrow that points where the model puts the new rail on the plan, the 3D
 * statistics as one table of a row per quantity, in English and German (react-dom/server markup).
 */
import { renderToStaticMarkup } from 'react-dom/server';
import type { ReactElement } from 'react';
import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { railPlacements } from '../../../src/core/model/rails/geometry';
import { createI18n } from '../../../src/ui/i18n/createI18n';
import { I18nProvider } from '../../../src/ui/i18n/I18nProvider';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import DistributionButtons from '../../../src/ui/planner/DistributionButtons';
import { distributionPictureOffsets } from '../../../src/ui/planner/DistributionPicture';
import { SystemOptions } from '../../../src/ui/planner/SystemOptions';
import { turnArrowPoints } from '../../../src/ui/planner/TurnArrow';
import { worldToScreen } from '../../../src/ui/planner/viewTransform';
import { IlluminanceTable } from '../../../src/ui/viewer/IlluminanceTable';
import { catalog } from './testPlanner';

const run = (s: Configuration, name: string, params: unknown) => {
  const a = bindAction(name, params, catalog);
  expect(a.isEnabled(s)).toBe(true);
  return a.perform(s);
};

async function inGerman(el: ReactElement): Promise<string> {
  const de = createI18n({ locale: 'de-DE', currency: 'EUR' });
  await de.ready;
  return renderToStaticMarkup(<I18nProvider i18n={de}>{el}</I18nProvider>);
}

/** The accessible names of the buttons in some markup, in order. */
const names = (html: string) => [...html.matchAll(/<button[^>]*aria-label="([^"]*)"/g)].map((m) => m[1]);

describe('distribution pictures', () => {
  // The picture: a 1 m rail over 44 px from x = 2, three 0.18 m modules (7.92 px).
  const px = (m: number) => 2 + m * 44;
  it('put three modules where the model lays them out (by hand: packed, mirrored, cells of 1/3, ends)', () => {
    const close = (a: number[], b: number[]) => a.forEach((v, i) => expect(v).toBeCloseTo(b[i], 9));
    close(distributionPictureOffsets('start'), [px(0), px(0.18), px(0.36)]);
    close(distributionPictureOffsets('end'), [px(0.46), px(0.64), px(0.82)]);
    // Each module centred in its third: centres 1/6, 1/2, 5/6.
    close(distributionPictureOffsets('inside-centred'), [px(1 / 6 - 0.09), px(0.5 - 0.09), px(5 / 6 - 0.09)]);
    // Outer ones at the ends, centres equally spaced: 0.09, 0.5, 0.91.
    close(distributionPictureOffsets('outside-centred'), [px(0), px(0.41), px(0.82)]);
  });

  it('are buttons named in shopper words, in English and German, with a picture each', async () => {
    const config = run(createConfiguration({ width: 5, depth: 4, height: 2.8 }), 'placePreset', { presetId: 'single', x: 1, z: 1 });
    const rail = config.systems[0].rails[0];
    const gate = createActionGate(
      config,
      catalog,
      () => {},
      () => {},
    );
    const en = renderToStaticMarkup(<DistributionButtons railId={rail.id} current="inside-centred" gate={gate} />);
    expect(names(en)).toEqual([
      'Line the modules up from the start of the rail',
      'Line the modules up against the end of the rail',
      'Space the modules evenly, with room at both ends',
      'Space the modules evenly, the outer ones at the rail ends',
    ]);
    expect(en.match(/<svg class="distribution-picture"/g)).toHaveLength(4);
    expect(en).toContain('From the start');
    expect(en).not.toMatch(/inside-centred<|▮/);
    const de = await inGerman(<DistributionButtons railId={rail.id} current="inside-centred" gate={gate} compact />);
    expect(names(de)).toEqual([
      'Module ab dem Anfang der Schiene reihen',
      'Module an das Ende der Schiene reihen',
      'Module gleichmäßig verteilen, mit Abstand zu beiden Enden',
      'Module gleichmäßig verteilen, die äußeren an den Schienenenden',
    ]);
    // Compact (on the plan): the picture alone; the current one pressed.
    expect(de).not.toContain('Ab Anfang');
    expect(de).toMatch(/aria-pressed="true"[^>]*data-testid="distribution-[^"]*-inside-centred"/);
  });
});

describe('Extend the chain: by direction', () => {
  const base = run(createConfiguration({ width: 8, depth: 6, height: 3 }), 'placePreset', { presetId: 'single', x: 2, z: 3 });
  const view = { scale: 80, offsetX: 20, offsetY: 10 };

  /** The new rail's direction on screen, from the model's placement after addRail. */
  function modelDirection(config: Configuration, connector: string, turn: number): [number, number] {
    const after = run(config, 'addRail', { systemId: config.systems[0].id, connector, turn });
    const r = railPlacements(after.systems[0], catalog).at(-1)!;
    const a = worldToScreen(view, { x: r.start[0], z: r.start[1] });
    const b = worldToScreen(view, { x: r.end[0], z: r.end[1] });
    const len = Math.hypot(b.sx - a.sx, b.sy - a.sy);
    return [(b.sx - a.sx) / len, (b.sy - a.sy) / len];
  }

  for (const rotation of [0, 30, 90, 200]) {
    it(`each arrow points where the model puts the new rail on the plan (system turned ${rotation}°)`, () => {
      const config = rotation === 0 ? base : run(base, 'rotateSystem', { systemId: base.systems[0].id, by: rotation });
      const heading = railPlacements(config.systems[0], catalog).at(-1)!.heading;
      for (const [connector, turn] of [
        ['straight', 0],
        ['corner90', 90],
        ['corner90', -90],
        ['flex', 45],
        ['flex', -45],
      ] as const) {
        const p = turnArrowPoints(heading, turn);
        const len = Math.hypot(p.to[0] - p.joint[0], p.to[1] - p.joint[1]);
        const arrow = [(p.to[0] - p.joint[0]) / len, (p.to[1] - p.joint[1]) / len];
        const model = modelDirection(config, connector, turn);
        expect(arrow[0], `${connector} ${turn}`).toBeCloseTo(model[0], 9);
        expect(arrow[1], `${connector} ${turn}`).toBeCloseTo(model[1], 9);
      }
    });
  }

  it('a left turn on a rail heading +x points up the screen (−y): the plan is the view from above', () => {
    const p = turnArrowPoints(0, 90);
    expect(p.to[0]).toBeCloseTo(p.joint[0], 9);
    expect(p.to[1]).toBeLessThan(p.joint[1]);
  });

  it('names each button by its direction and connector, straight on first, in English and German', async () => {
    const gate = createActionGate(
      base,
      catalog,
      () => {},
      () => {},
    );
    const el = <SystemOptions system={base.systems[0]} catalog={catalog} gate={gate} onClose={() => {}} />;
    const en = names(renderToStaticMarkup(el)).filter((n) => n.startsWith('Add a rail'));
    expect(en).toEqual([
      'Add a rail: Straight on (Straight connector)',
      'Add a rail: Left 90° (90° corner connector)',
      'Add a rail: Left 45° (Flexible-angle connector)',
      'Add a rail: Left 90° (T-connector)',
      'Add a rail: Left 90° (X-connector)',
      'Add a rail: Right 90° (90° corner connector)',
      'Add a rail: Right 45° (Flexible-angle connector)',
      'Add a rail: Right 90° (T-connector)',
      'Add a rail: Right 90° (X-connector)',
    ]);
    const deHtml = await inGerman(el);
    const de = names(deHtml).filter((n) => n.startsWith('Schiene anfügen'));
    expect(de[0]).toMatch(/^Schiene anfügen: Geradeaus \(/);
    expect(de[1]).toMatch(/^Schiene anfügen: Links 90° \(/);
    expect(de).toHaveLength(9);
    expect(deHtml).not.toMatch(/[↰↱]/);
    expect(deHtml.match(/<svg class="turn-arrow"/g)).toHaveLength(9);
  });
});

describe('illuminance statistics: a row per quantity, a column per surface', () => {
  const floor = { avg: 123.4, min: 56.78, max: 234.5, u0: 0.46, points: 400 };
  it('floor alone, then floor and plane; lux as a meter shows them', async () => {
    const one = renderToStaticMarkup(<IlluminanceTable floor={floor} plane={null} />);
    expect(one.match(/<tr>/g)).toHaveLength(5);
    expect(one).toContain('data-columns="1"');
    expect(one).toContain('<caption>Illuminance in lux</caption>');
    expect(one).toMatch(/data-testid="stats-floor-avg">123</);
    expect(one).toMatch(/data-testid="stats-floor-min">56.8</);
    expect(one).toMatch(/data-testid="stats-floor-u0">0.46</);
    const two = await inGerman(<IlluminanceTable floor={floor} plane={{ height: 0.75, stats: null }} />);
    expect(two).toContain('data-columns="2"');
    expect(two).toContain('Ebene 0,75 m');
    expect(two).toMatch(/data-testid="stats-plane-avg">–</);
    // The long German word breaks only at its soft hyphens (Gleich-mäßig-keit).
    expect(two).toContain('Gleich\u00admäßig\u00adkeit U₀');
  });
});
