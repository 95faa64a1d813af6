/**
 * Light-scene playback (src/ui/scenes/createScenePlayer.ts): a recall with a fade jumps the
 * configuration to the end state (one undoable action) and shows the levels at the eased fraction
 * frame by frame; the 3D light gets a relight per frame (setFade) and the fade ends with null; the
 * promise resolves when the fade ends; GO / BACK follow list order; an edit during a fade ends it.
 * Frames and the clock are the test's (no timing).
 */
import { describe, expect, it } from 'vitest';
import type { Configuration } from '../../../src/core/model/configuration/configuration';
import { allModules } from '../../../src/core/model/cues/lightScenes';
import { fadeFraction, fadeLevels, luminousOutput } from '../../../src/core/model/cues/sceneFade';
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
    expect(player.stop('back')).toBe('firstScene');
    expect(await player.back()).toEqual({ ok: false, reason: 'no previous scene', code: 'firstScene' });
    const going = player.go();
    expect(player.getState().fading?.seconds).toBe(evening.fade);
    clock.advance(evening.fade * 1000);
    expect(await going).toEqual({ ok: true });
    expect(player.next()).toBeNull();
    // GO at the last scene does not wrap round to the first (a console stops at the end of its cue list); it says why.
    expect(player.stop('go')).toBe('lastScene');
    expect(await player.go()).toEqual({ ok: false, reason: 'no next scene', code: 'lastScene' });
    expect(player.getState().current).toBe(evening.id);
  });

  it('GO / BACK stops: no scenes, nothing recalled yet', async () => {
    const empty = createScenePlayer(createConfiguratorStore({ catalog, initial: withPreset('single', 1, 1) }));
    expect([empty.stop('go'), empty.stop('back')]).toEqual(['noScenes', 'noScenes']);
    expect(await empty.go()).toEqual({ ok: false, reason: 'no light scenes', code: 'noScenes' });
    const fresh = createScenePlayer(createConfiguratorStore({ catalog, initial: twoScenes() }));
    expect([fresh.stop('go'), fresh.stop('back')]).toEqual([null, 'nothingRecalled']);
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

  it('a recall during a fade starts from the look on screen (the mix at that instant), not from the end of the running fade', async () => {
    // Three spots: A = m1 only, B = m2 only (equal output: the old fade is linear, e = t), C = m2 and m3.
    let c = withPreset('single', 1, 1);
    const [m1, m2, m3] = allModules(c).map((m) => m.id);
    const look = (on: [boolean, boolean, boolean]) => [m1, m2, m3].forEach((id, i) => (c = run(c, 'setModuleOn', { moduleId: id, on: on[i] })));
    look([true, false, false]);
    c = run(c, 'recordScene', { name: 'A', fade: 2 });
    look([false, true, false]);
    c = run(c, 'recordScene', { name: 'B', fade: 2 });
    look([false, true, true]);
    c = run(c, 'recordScene', { name: 'C', fade: 2 });
    const [a, b, cue] = c.lightScenes!;
    c = run(c, 'recallScene', { sceneId: a.id });
    const store = createConfiguratorStore({ catalog, initial: c });
    const clock = manualFrames();
    const { feed, fades } = recordingFeed([m1, m2, m3]);
    const player = createScenePlayer(store, { frame: clock.frame, now: clock.now, feed: () => feed });
    const levels = () => [m1, m2, m3].map((id) => player.levels()?.get(id));

    const first = player.recall(b.id);
    clock.advance(1000); // half of A → B: m1 0.5, m2 0.5, m3 0
    expect(levels()).toEqual([0.5, 0.5, 0]);
    const second = player.recall(cue.id);
    expect(await first).toEqual({ ok: true }); // the interrupted fade's promise resolves
    // t = 0 of the new fade: exactly what was on screen (before the fix: B's end state 0, 1, 0).
    expect(levels()).toEqual([0.5, 0.5, 0]);
    // The 3D view's scene faded from carries the same mix (dimming; the colours are equal here).
    const lit: BakeScene = { room: { width: 1, height: 1, depth: 1, reflectance: {} as BakeScene['room']['reflectance'] }, luminaires: [0, 1, 2].map(() => ({ dimming: 1 }) as BakeScene['luminaires'][number]) };
    expect(fades[fades.length - 1]!.from(lit).luminaires.map((l) => l.dimming)).toEqual([0.5, 0.5, 0]);
    // t = 0.5: from output L to 2 L, e = 0.442746 (tests/core/model/cues/sceneFade.test.ts, by hand):
    // m1 0.5·(1 − e) = 0.278627, m2 0.5 + 0.5·e = 0.721373, m3 e = 0.442746.
    clock.advance(1000);
    const half = levels();
    expect(half[0]).toBeCloseTo(0.278627, 6);
    expect(half[1]).toBeCloseTo(0.721373, 6);
    expect(half[2]).toBeCloseTo(0.442746, 6);
    // t = 1: C, and the fade is over; the configuration is C throughout.
    clock.advance(1000);
    expect(await second).toEqual({ ok: true });
    expect(player.levels()).toBeNull();
    expect(allModules(store.getState().config).map((m) => m.on !== false)).toEqual([false, true, true]);
  });
});
