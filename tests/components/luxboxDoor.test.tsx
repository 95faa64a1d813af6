import { cleanup, render, waitFor } from '@testing-library/react';
import { afterEach, describe, expect, it } from 'vitest';
import defaultCatalogData from '../../src/core/catalog/default-catalog.json';
import type { LuxboxInstance } from '../../src/hosts/embed/types';
import { Luxbox } from '../../src/hosts/package/react';
// Modules the mounted configurator imports lazily soon after mounting (the plan's measured footprints, the English
// accessibility texts): loaded here, so that no import is still under way when the test environment is torn down.
import '../../src/core/photometry/parsePhotometry';
import '../../src/ui/i18n/registerA11yEnglish';

/**
 * `<Luxbox>` (luxbox/react) on React and on preact/compat: without a `catalog` prop it mounts the
 * bundled demo catalog, which the package's doors load as a lazy chunk since issue 33's React-door
 * budget (createMountController.ts); with catalog data it mounts that, and never needs the bundled one.
 */

afterEach(cleanup);

const ROOM = { width: 6, depth: 4.5, height: 3 };

/** Renders the door and waits for onReady (a failed mount fails the test with its error). */
async function mountDoor(catalog?: object): Promise<LuxboxInstance> {
  let instance: LuxboxInstance | null = null;
  let failure: Error | null = null;
  render(
    <Luxbox
      {...(catalog ? { catalog: catalog as never } : {})}
      room={ROOM}
      locale="en"
      onReady={(next) => {
        instance = next;
      }}
      onError={(error) => {
        failure = error;
      }}
    />,
  );
  // A wait for a condition, not a timing assertion: generous, as a loaded machine transforms the lazy chunk slowly.
  await waitFor(
    () => {
      if (failure) throw new Error(`mount failed: ${(failure as Error).message}`);
      expect(instance).not.toBeNull();
    },
    { timeout: 60_000 },
  );
  return instance!;
}

describe('the React door and its catalog', () => {
  it('mounts the bundled demo catalog, loaded on demand, when the page gives none', async () => {
    const instance = await mountDoor();
    instance.runAction('placePreset', { presetId: 'single' });
    const bom = instance.getBillOfMaterials();
    expect(bom.currency).toBe(defaultCatalogData.currency);
    // The rails are the bundled catalog's rail article cut to length (the length in mm); modules are priced too.
    const rails = bom.lines.filter((line) => line.kind === 'rail');
    expect(rails.length).toBeGreaterThan(0);
    for (const line of rails) expect(line.article).toMatch(new RegExp(`^${defaultCatalogData.rail.article}-\\d+$`));
    expect(bom.lines.filter((line) => line.kind === 'module').length).toBeGreaterThan(0);
    await instance.whenReady();
  });

  it("mounts the page's own catalog data, priced in its currency", async () => {
    const instance = await mountDoor({ ...defaultCatalogData, id: 'shop-chf', currency: 'CHF' });
    instance.runAction('placePreset', { presetId: 'single' });
    expect(instance.getBillOfMaterials().currency).toBe('CHF');
    await instance.whenReady();
  });
});
