/**
 * A recall weights each module's light by its colour, and a filtered module's colour needs the
 * colour-filter spectra (docs/colour-filters.md, "Two files"). On a fresh module graph (spectra
 * not loaded, as in a browser that has not needed them yet) a recall waits for them and succeeds.
 */
import { describe, expect, it, vi } from 'vitest';
import { allModules } from '../../../src/core/model/cues/lightScenes';
import { catalog, run, withPreset } from '../../core/model/helpers';

describe('scene player and the colour-filter spectra', () => {
  it('a recall before the spectra are loaded loads them, then recalls', async () => {
    let s = withPreset('single', 1, 1);
    s = run(s, 'recordScene', { name: 'White', fade: 0 });
    s = run(s, 'setModuleFilter', { moduleId: allModules(s)[0].id, filter: 'lee-106' });
    s = run(s, 'recordScene', { name: 'Red', fade: 0 });
    s = run(s, 'recallScene', { sceneId: s.lightScenes![0].id });

    vi.resetModules();
    const spectra = await import('../../../src/core/colour/colourFilterSpectra');
    const { createConfiguratorStore } = await import('../../../src/core/store/createConfiguratorStore');
    const { createScenePlayer } = await import('../../../src/ui/scenes/createScenePlayer');
    expect(spectra.colourFilterSpectraLoaded()).toBe(false);
    const store = createConfiguratorStore({ catalog, initial: s });
    const player = createScenePlayer(store, { feed: () => null, frame: () => () => undefined, now: () => 0 });
    const red = s.lightScenes![1].id;
    // With a fade: the player works out the light's luminous output through the red filter.
    const recalled = player.recall(red, { fade: 2 });
    await vi.waitFor(() => expect(player.getState().fading).not.toBeNull());
    player.finish();
    await expect(recalled).resolves.toEqual({ ok: true });
    expect(spectra.colourFilterSpectraLoaded()).toBe(true);
    expect(player.getState().current).toBe(red);
    expect(allModules(store.getState().config)[0].filter).toBe('lee-106');
  });
});
