import { act, cleanup, render, screen } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { defaultCatalog } from '../../src/core/catalog/defaultCatalog';
import { demoConfiguration } from '../../src/core/catalog/demoConfiguration';
import { createConfiguratorStore } from '../../src/core/store/createConfiguratorStore';
import { ScenePanel } from '../../src/ui/scenes/ScenePanel';

/**
 * The light-scene panel on React and on preact/compat: recording a scene, the rename field taking
 * the focus when it appears (the difference that bit: React focuses an `autoFocus` element on
 * mount, preact only sets the attribute; ScenePanel.tsx focuses it through a ref), Enter
 * committing the new name, and the panel's note going after 4 s (an effect's timer).
 */

function mountPanel() {
  const store = createConfiguratorStore({ catalog: defaultCatalog, initial: demoConfiguration(defaultCatalog) });
  render(<ScenePanel store={store} />);
  return store;
}

afterEach(() => {
  cleanup();
  vi.useRealTimers();
});

describe('scene panel', () => {
  it('records a scene under the typed name, and its rename field has the focus as soon as it shows', async () => {
    const user = userEvent.setup();
    const store = mountPanel();
    await user.type(screen.getByTestId('scene-name'), 'Dinner');
    await user.click(screen.getByTestId('scene-record'));
    expect((store.getState().config.lightScenes ?? []).map((s) => s.name)).toEqual(['Dinner']);
    expect(screen.getAllByTestId('scene-row')).toHaveLength(1);

    await user.click(screen.getByTestId('scene-rename'));
    const field = screen.getByTestId('scene-rename-input');
    expect(document.activeElement).toBe(field);
    // Typing goes straight into it, with no click first.
    await user.keyboard('{Control>}a{/Control}Late{Enter}');
    expect((store.getState().config.lightScenes ?? []).map((s) => s.name)).toEqual(['Late']);
    expect(screen.queryByTestId('scene-rename-input')).toBeNull();
  });

  it('GO with no scene leaves a note that the panel’s effect removes after 4 s', () => {
    vi.useFakeTimers({ toFake: ['setTimeout', 'clearTimeout'] });
    mountPanel();
    act(() => screen.getByTestId('scene-go').click());
    expect(screen.getByTestId('scene-note').textContent).not.toBe('');
    act(() => void vi.advanceTimersByTime(3900));
    expect(screen.queryByTestId('scene-note')).not.toBeNull();
    act(() => void vi.advanceTimersByTime(200));
    expect(screen.queryByTestId('scene-note')).toBeNull();
  });
});
