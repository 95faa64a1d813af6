/**
 * Light-scene playback (src/ui/scenes/createScenePlayer.ts): a recall with a fade jumps the
 * configuration to the end state (one undoable action) and shows the levels at the eased fraction
 * frame by frame; the 3D light gets a relight per frame (setFade) and the fade ends with null; the
 * promise resolves when the fade ends; GO / BACK follow list order; an edit during a fade ends it.
 * Frames and the clock are the test's (no timing).
 */
import { describe, expect, it } from 'vitest';
import type { Configuration } from '../../../src/core/model/configuration';
import { allModules } from '../../../src/core/model/lightScenes';
import { fadeFraction, fadeLevels, luminousOutput } from '../../../src/core/model/sceneFade';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import type { ServiceFade } from '../../../src/engines/view/createBakeService';
import { createScenePlayer } from '../../../src/ui/scenes/createScenePlayer';
import type { BakeFeed } from '../../../src/ui/viewer/startBakeFeed';
import { catalog, run, withPreset } from '../../core/model/helpers';

function twoScenes(): Configuration {
  let s = withPreset('single', 1, 1);
  s = run(s, 'recordScene', { name: 'Day', fade: 0 });
  for (const m of allModules(s)) s = run(s, 'setModuleDimming', { moduleId: m.id, dimming: 0.2 });
  s = run(s, 'setModuleOn', { moduleId: allModules(s)[0].id, on: false });
  s = run(s, 'recordScene', { name: 'Evening', fade: 2 });
  return run(s, 'recallScene', { sceneId: s.lightScenes![0].id });
}

/** A clock and a frame queue the test advances by hand. */
function manualFrames() {
  let time = 0;
  let queued: (() => void) | null = null;
  return {
    now: () => time,
    frame(cb: () => void) {
      queued = cb;
      return () => {
        if (queued === cb) queued = null;
      };
    },
    advance(ms: number) {
      time += ms;
      const cb = queued;
      queued = null;
      cb?.();
    },
  };
}

/** A bake feed stand-in that records the fades handed to its service. */
function recordingFeed(ids: string[]) {
  const fades: (ServiceFade | null)[] = [];
  const feed = { service: { setFade: (f: ServiceFade | null) => fades.push(f) }, latest: () => ({ ids }) } as unknown as BakeFeed;
  return { feed, fades };
}

describe('scene player', () => {
  it('recall with a fade: one undoable step, eased levels per frame, a relight per frame, resolves at the end', async () => {
    const initial = twoScenes();
    const store = createConfiguratorStore({ catalog, initial });
    const clock = manualFrames();
    const ids = allModules(initial).map((m) => m.id);
    const { feed, fades } = recordingFeed(ids);
    const player = createScenePlayer(store, { frame: clock.frame, now: clock.now, feed: () => feed });
    const evening = initial.lightScenes![1];
    let resolved = false;
    const done = player.recall(evening.id).then((r) => ((resolved = true), r));
    const to = store.getState().config;
    expect(allModules(to)[1].dimming).toBe(0.2);
    expect(player.getState()).toMatchObject({ current: evening.id, fading: { t: 0, e: 0, seconds: 2 } });
    clock.advance(1000);
    const e = fadeFraction(0.5, luminousOutput(initial, catalog), luminousOutput(to, catalog));
    expect(player.getState().fading!.e).toBeCloseTo(e, 12);
    const levels = player.levels()!;
    const expected = fadeLevels(initial, to, e);
    for (const id of ids) expect(levels.get(id)).toBeCloseTo(expected.get(id)!, 12);
    // The module switched off fades from its level to 0.
    expect(levels.get(ids[0])).toBeCloseTo((1 - e) * allModules(initial)[0].dimming, 12);
    // The 3D light: the scene faded from carries the earlier dimming of each module, by id.
    const last = fades[fades.length - 1]!;
    expect(last.e).toBeCloseTo(e, 12);
    const lit: BakeScene = { room: { width: 1, height: 1, depth: 1, reflectance: {} as BakeScene['room']['reflectance'] }, luminaires: ids.map(() => ({ dimming: 0.2 }) as BakeScene['luminaires'][number]) };
    expect(last.from(lit).luminaires.map((l) => l.dimming)).toEqual(allModules(initial).map((m) => m.dimming));
    expect(resolved).toBe(false);
    clock.advance(1000);
    expect(await done).toEqual({ ok: true });
    expect(player.getState().fading).toBeNull();
    expect(fades[fades.length - 1]).toBeNull();
    expect(player.levels()).toBeNull();
    // One undo step back to where the fade started.
    store.getState().undo();
    expect(store.getState().config).toBe(initial);
  });

  it('GO and BACK follow list order with each scene’s fade; none past the ends', async () => {
    const store = createConfiguratorStore({ catalog, initial: twoScenes() });
    const clock = manualFrames();
    const player = createScenePlayer(store, { frame: clock.frame, now: clock.now });
    const [day, evening] = store.getState().config.lightScenes!;
    expect(player.next()?.id).toBe(day.id);
    expect(await player.go()).toEqual({ ok: true }); // Day: 0 s, at once
    expect(player.getState().current).toBe(day.id);
    expect(player.previous()).toBeNull();
    expect(await player.back()).toEqual({ ok: false, reason: 'no previous scene' });
    const going = player.go();
    expect(player.getState().fading?.seconds).toBe(evening.fade);
    clock.advance(evening.fade * 1000);
    expect(await going).toEqual({ ok: true });
    expect(player.next()).toBeNull();
    expect(await player.go()).toEqual({ ok: false, reason: 'no next scene' });
  });

  it('an edit during a fade ends it (the plan shows the configuration); a refused recall says why', async () => {
    const store = createConfiguratorStore({ catalog, initial: twoScenes() });
    const clock = manualFrames();
    const player = createScenePlayer(store, { frame: clock.frame, now: clock.now });
    const evening = store.getState().config.lightScenes![1];
    const fading = player.recall(evening.id, { fade: 10 });
    clock.advance(500);
    store.getState().dispatch('setModuleDimming', { moduleId: allModules(store.getState().config)[1].id, dimming: 0.9 });
    expect(await fading).toEqual({ ok: true });
    expect(player.getState().fading).toBeNull();
    expect(await player.recall('q999')).toEqual({ ok: false, reason: "no light scene with id 'q999'" });
  });
});
