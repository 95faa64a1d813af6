import { act, cleanup, fireEvent, render, screen } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { defaultCatalog } from '../../src/core/catalog/defaultCatalog';
import { demoConfiguration } from '../../src/core/catalog/demoConfiguration';
import { createConfiguratorStore } from '../../src/core/store/createConfiguratorStore';
import { createUiStore } from '../../src/core/store/uiStore';
import type { FootprintSource } from '../../src/ui/planner/footprintSource';
import { Planner } from '../../src/ui/planner/Planner';

/**
 * The planner as a user drives it, on React and on preact/compat (the same file runs in both
 * component projects, vite.config.ts): buttons, keys and the effects they start. happy-dom lays
 * nothing out, so the plan keeps the default viewport the planner starts with.
 */

/** A page whose user asked for reduced motion: the plan jumps to each new view (usePlanView.ts), so a zoom is seen at once. */
function reducedMotion(): void {
  vi.spyOn(window, 'matchMedia').mockImplementation((query: string) => {
    const list = new EventTarget() as MediaQueryList;
    Object.assign(list, { matches: query.includes('prefers-reduced-motion: reduce'), media: query, onchange: null, addListener: () => {}, removeListener: () => {} });
    return list;
  });
}

/** A page where no photometric file can be had (offline): every footprint and outline is unavailable, and the plan draws the catalog's beam cones and rectangles. */
function noFootprints(): FootprintSource {
  return {
    get: () => null,
    warnings: () => [],
    request: () => {},
    subscribe: () => () => {},
    version: () => 0,
    loadPhotometry: (path) => Promise.reject(new Error(`${path}: offline`)),
    outline: () => null,
    requestOutlines: () => {},
  };
}

function mountPlanner() {
  const catalog = defaultCatalog;
  const store = createConfiguratorStore({ catalog, initial: demoConfiguration(catalog) });
  const ui = createUiStore({ phase: 'planner' });
  const footprints = noFootprints();
  render(<Planner store={store} ui={ui} onNewRoom={() => {}} onShare={() => 'copied'} footprints={footprints} />);
  return { store, ui };
}

const scale = () => Number(screen.getByTestId('plan').getAttribute('data-scale'));

beforeEach(() => {
  reducedMotion();
});
afterEach(() => {
  cleanup();
  vi.restoreAllMocks();
  vi.useRealTimers();
});

describe('planner', () => {
  it('the zoom buttons zoom the plan by the zoom step (1.5) and back', async () => {
    const user = userEvent.setup();
    mountPlanner();
    const before = scale();
    await user.click(screen.getByTestId('zoom-in'));
    expect(scale() / before).toBeCloseTo(1.5, 2);
    await user.click(screen.getByTestId('zoom-out'));
    expect(scale()).toBeCloseTo(before, 2);
  });

  it('keys: Delete removes the selected system, Ctrl+Z brings it back, Ctrl+Shift+Z removes it again', async () => {
    const user = userEvent.setup();
    const { store } = mountPlanner();
    const id = store.getState().config.systems[0].id;
    act(() => store.getState().select({ kind: 'system', id }));
    await user.keyboard('{Delete}');
    expect(store.getState().config.systems.map((s) => s.id)).not.toContain(id);
    await user.keyboard('{Control>}z{/Control}');
    expect(store.getState().config.systems.map((s) => s.id)).toContain(id);
    await user.keyboard('{Control>}{Shift>}z{/Shift}{/Control}');
    expect(store.getState().config.systems.map((s) => s.id)).not.toContain(id);
  });

  it('a refusal shows on the status line, which its effect clears after 4 s', () => {
    vi.useFakeTimers({ toFake: ['setTimeout', 'clearTimeout'] });
    mountPlanner();
    fireEvent.keyDown(window, { key: 'z', ctrlKey: true });
    expect(screen.getByTestId('status-line').textContent).not.toBe('');
    act(() => void vi.advanceTimersByTime(3900));
    expect(screen.queryByTestId('status-line')).not.toBeNull();
    act(() => void vi.advanceTimersByTime(200));
    expect(screen.queryByTestId('status-line')).toBeNull();
  });
});
