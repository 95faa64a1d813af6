/**
 * The 3D view's camera mode (docs/aiming.md, "Spotlight view"): a camera preset leaves the
 * spotlight view, so the spotlight button reads "Spotlight view" (not pressed) again and the
 * preset shows pressed; leaving the module in the selection ends its spotlight view too.
 */
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';
import { demoConfiguration } from '../../../src/core/catalog/demoConfiguration';
import { INITIAL_CAMERA_MODE, nextCameraMode, presetPressed, type CameraMode } from '../../../src/ui/viewer/cameraMode';
import { SpotlightControls } from '../../../src/ui/viewer/SpotlightControls';
import { catalog } from '../planner/testPlanner';

function adjustableStore() {
  const store = createConfiguratorStore({ catalog, initial: demoConfiguration(catalog) });
  const module = store
    .getState()
    .config.systems.flatMap((s) => s.rails.flatMap((r) => r.modules))
    .find((m) => catalog.moduleTypes.find((t) => t.id === m.type)?.adjustable);
  if (!module) throw new Error('the demo has no adjustable module');
  store.getState().select({ kind: 'module', id: module.id });
  // A static render reads zustand's server snapshot (the initial state): hand it the current one, with the selection.
  return { store: { ...store, getInitialState: store.getState }, moduleId: module.id };
}

/** The spotlight button as the 3D panel draws it for a camera mode. */
function spotlightButton(store: ReturnType<typeof adjustableStore>['store'], mode: CameraMode): { label: string; pressed: string } {
  const html = renderToStaticMarkup(<SpotlightControls store={store} controllerRef={{ current: null }} ready={0} spotlight={mode.spotlight} onCameraMode={() => {}} />);
  const m = /<button[^>]*aria-pressed="(true|false)"[^>]*data-testid="spotlight-view"[^>]*>([^<]*)<\/button>/.exec(html);
  if (!m) throw new Error(`no spotlight button in ${html}`);
  return { pressed: m[1], label: m[2] };
}

describe('camera mode: presets and the spotlight view', () => {
  it('a preset picked in the spotlight view leaves it: the button says "Spotlight view" again and the preset is pressed', () => {
    const { store, moduleId } = adjustableStore();
    let mode = INITIAL_CAMERA_MODE;
    expect(spotlightButton(store, mode)).toEqual({ label: 'Spotlight view', pressed: 'false' });
    expect(presetPressed(mode, 'corner')).toBe(true);

    mode = nextCameraMode(mode, { kind: 'spotlight', moduleId });
    expect(spotlightButton(store, mode)).toEqual({ label: 'Leave spotlight view', pressed: 'true' });
    // In the spotlight view no preset is the view.
    expect(['eye', 'top', 'corner'].filter((p) => presetPressed(mode, p as 'eye'))).toEqual([]);

    mode = nextCameraMode(mode, { kind: 'preset', name: 'top' });
    expect(mode).toEqual({ preset: 'top', spotlight: null });
    expect(spotlightButton(store, mode)).toEqual({ label: 'Spotlight view', pressed: 'false' });
    expect(presetPressed(mode, 'top')).toBe(true);
    expect(presetPressed(mode, 'corner')).toBe(false);
  });

  it('the selection leaving the module ends its spotlight view; the same module again keeps it', () => {
    const { moduleId } = adjustableStore();
    const on = nextCameraMode(INITIAL_CAMERA_MODE, { kind: 'spotlight', moduleId });
    expect(nextCameraMode(on, { kind: 'selection', moduleId })).toBe(on);
    expect(nextCameraMode(on, { kind: 'selection', moduleId: null })).toEqual({ preset: 'corner', spotlight: null });
    expect(nextCameraMode(on, { kind: 'selection', moduleId: 'm999' }).spotlight).toBeNull();
    // Leaving with the button keeps the preset the orbit camera came from.
    expect(nextCameraMode(on, { kind: 'spotlight', moduleId: null })).toEqual(INITIAL_CAMERA_MODE);
  });
});
