/**
 * Photometry warnings where the app shows a file's light (issue 18): the module options
 * (from the plan's photometry loader) and the PhotometryWarnings note itself. The catalog's
 * own files have no warnings, so a module is pointed at a test fixture that has some.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { renderToStaticMarkup as render } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import type { Catalog } from '../../../src/core/model/catalogSchema/catalogSchema';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import { createFootprintSource } from '../../../src/ui/planner/footprintSource';
import { modulePhotometryPath } from '../../../src/ui/planner/moduleFootprint';
import { OptionsPanel } from '../../../src/ui/planner/OptionsPanel';
import { PhotometryWarnings } from '../../../src/ui/shared/PhotometryWarnings';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';

const root = join(__dirname, '../../..');

/** Static markup without the <wbr> that let file names wrap after _ . - (asserted once below). */
const renderToStaticMarkup = (node: React.ReactElement) => render(node).replaceAll('<wbr/>', '');
const MISMATCH = 'stated lumens 34 lm and integrated flux 2047 lm differ by 5921 % (ratio 60.21); the integrated flux of the candela data is used';

/** Serves `odd/<fixture>` from tests/fixtures/photometry and everything else from public/. */
const fetchFixture: typeof fetch = async (input) => {
  const url = String(input);
  const file = url.startsWith('odd/') ? join(root, 'tests/fixtures/photometry', url.slice(4)) : join(root, 'public', url);
  return new Response(readFileSync(file));
};

/** The default catalog with every beam of every module type measured by the lumens-mismatch fixture. */
function oddCatalog(): Catalog {
  const c = structuredClone(defaultCatalog) as Catalog;
  for (const t of c.moduleTypes) for (const b of t.beams) b.photometry = 'odd/lumens_mismatch_60x.ies';
  return c;
}

function moduleOptions(catalog: Catalog) {
  const store = createConfiguratorStore({ catalog, initial: createConfiguration() });
  expect(store.getState().dispatch('placePreset', { presetId: 'corner-l' })).toEqual({ ok: true });
  const config = store.getState().config;
  const system = config.systems[0];
  const rail = system.rails.find((r) => r.modules.length > 0)!;
  const module = rail.modules[0];
  const gate = createActionGate(
    config,
    catalog,
    () => {},
    () => {},
  );
  const path = { systemId: system.id, railId: rail.id, moduleId: module.id };
  return { config, gate, path, photometry: modulePhotometryPath(module, catalog)! };
}

async function loaded(source: ReturnType<typeof createFootprintSource>, path: string) {
  source.request([path]);
  await new Promise<void>((resolve) => {
    const off = source.subscribe(() => {
      if (source.get(path) !== undefined) {
        off();
        resolve();
      }
    });
  });
}

describe('PhotometryWarnings', () => {
  it('a note (role, label) with the file name and one item per warning; nothing without warnings', () => {
    const html = renderToStaticMarkup(
      <PhotometryWarnings
        notes={[
          { file: 'ies/odd.ies', warnings: ['a & b', 'c'] },
          { file: 'ies/fine.ies', warnings: [] },
        ]}
      />,
    );
    expect(html).toContain('role="note"');
    expect(html).toContain('aria-label="Photometric data warnings"');
    expect(html).toContain('data-testid="photometry-warnings"');
    expect(html).toContain('<span aria-hidden="true">⚠ </span>odd.ies</p>');
    expect(html).toContain('<li>a &amp; b</li><li>c</li>');
    expect(html).not.toContain('fine.ies');
    expect(renderToStaticMarkup(<PhotometryWarnings notes={[{ file: 'ies/fine.ies', warnings: [] }]} />)).toBe('');
    // Long names wrap at their own separators in a narrow column.
    expect(render(<PhotometryWarnings notes={[{ file: 'ies/a_b-c.ies', warnings: ['w'] }]} />)).toContain('</span>a_<wbr/>b-<wbr/>c.<wbr/>ies</p>');
  });
});

describe("module options: the module's photometric file", () => {
  it("shows the file's warnings once the plan has loaded it", async () => {
    const catalog = oddCatalog();
    const { config, gate, path, photometry } = moduleOptions(catalog);
    const source = createFootprintSource('', fetchFixture);
    const panel = () => renderToStaticMarkup(<OptionsPanel config={config} catalog={catalog} path={path} gate={gate} onClose={() => {}} footprints={source} />);
    // Not loaded yet: no note.
    expect(panel()).not.toContain('module-photometry-warnings');
    await loaded(source, photometry);
    expect(source.warnings(photometry)).toEqual([MISMATCH]);
    const html = panel();
    expect(html).toContain('data-testid="module-photometry-warnings"');
    expect(html).toContain('lumens_mismatch_60x.ies</p>');
    expect(html).toContain(`<li>${MISMATCH}</li>`);
    // Between the beam choice and the colour temperature.
    expect(html.indexOf('module-photometry-warnings')).toBeGreaterThan(html.indexOf('aria-label="Beam"'));
    expect(html.indexOf('module-photometry-warnings')).toBeLessThan(html.indexOf('aria-label="Colour temperature"'));
  });

  it("the catalog's own files: no note", async () => {
    const { config, gate, path, photometry } = moduleOptions(defaultCatalog);
    const source = createFootprintSource('', fetchFixture);
    await loaded(source, photometry);
    expect(source.get(photometry)).not.toBeNull();
    expect(source.warnings(photometry)).toEqual([]);
    const html = renderToStaticMarkup(<OptionsPanel config={config} catalog={defaultCatalog} path={path} gate={gate} onClose={() => {}} footprints={source} />);
    expect(html).not.toContain('photometry-warnings');
  });
});

describe('PhotometryWarnings collapsed (the 3D view)', () => {
  it('one summary line counting the warnings, the text inside a closed <details>', () => {
    const html = renderToStaticMarkup(
      <PhotometryWarnings
        collapsed
        testId="view3d-photometry-warnings"
        notes={[
          { file: 'ies/a.ies', warnings: ['x', 'y'] },
          { file: 'ies/b.ldt', warnings: ['z'] },
        ]}
      />,
    );
    expect(html).toMatch(/^<div class="photometry-warnings" role="note" aria-label="Photometric data warnings" data-testid="view3d-photometry-warnings"><details><summary>/);
    expect(html).toContain('Photometric data: 3 warnings</summary>');
    expect(html).not.toContain('<details open');
    expect(html).toContain('a.ies</p><ul><li>x</li><li>y</li></ul>');
    expect(html).toContain('b.ldt</p><ul><li>z</li></ul>');
  });
});
