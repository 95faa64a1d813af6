/**
 * The always-ready bake's service on a real relight engine (docs/viewer.md, "Always ready: the bake
 * service"; headless-gl): paused while the page is hidden, resumed when visible, the luminaires'
 * weights, a new scene replacing the pending work, quality changes, the light sources shown, and
 * low-memory devices.
 */
import { describe, expect, it } from 'vitest';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import type { VisibilitySource } from '../../../src/engines/view/createBakeService';
import { uniformRoom } from '../bake/bakeTestKit';
import { headlessBakeService, lum, manualQueue, room, scene, type ManualQueue } from './bakeServiceKit';

describe('createBakeService on a real engine (headless-gl)', () => {
  function fakePage(hidden = false) {
    const listeners = new Set<() => void>();
    const page = {
      hidden,
      addEventListener: (_type: string, l: () => void) => listeners.add(l),
      removeEventListener: (_type: string, l: () => void) => listeners.delete(l),
      set(h: boolean) {
        page.hidden = h;
        for (const l of [...listeners]) l();
      },
      get listeners() {
        return listeners.size;
      },
    };
    return page;
  }
  /** A service at 'fast' quality on its own headless-gl context, on `page`. */
  const service = (page: ReturnType<typeof fakePage>, q: ManualQueue, lowMemory = false) => headlessBakeService(q, { visibility: page as unknown as VisibilitySource, lowMemory });

  /** A service on a visible page with a real-delay queue, the types of its events recorded. */
  function watchedService() {
    const q = manualQueue(true);
    const { s, dispose } = service(fakePage(), q);
    const events: string[] = [];
    s.subscribe((e) => events.push(e.type));
    return { s, q, events, dispose };
  }

  it('pauses while the page is hidden (counters and maps stay still, nothing queued) and resumes when visible', () => {
    const page = fakePage();
    const q = manualQueue(true);
    const { s, dispose } = service(page, q);
    try {
      s.setScene(scene);
      expect(s.status()).toMatchObject({ running: true, paused: false, done: false, quality: 'fast' });
      q.drain(1); // one slice: the first group's direct basis
      expect(s.status().groupBakes).toBe(1);
      page.set(true);
      expect(s.status()).toMatchObject({ paused: true, running: false });
      q.drain();
      const still = { ...s.status(), version: s.engine!.version, fraction: s.engine!.progress.fraction };
      // Nothing is left queued while hidden (no polling either), and a new request waits too.
      expect(q.size).toBe(0);
      s.setScene(scene);
      q.drain();
      expect(s.engine!.progress.fraction).toBe(still.fraction);
      expect(s.status().groupBakes).toBe(still.groupBakes);
      expect(still.done).toBe(false);
      page.set(false);
      expect(s.status().paused).toBe(false);
      q.drain();
      expect(s.status()).toMatchObject({ running: false, paused: false, done: true, groupBakes: 2 });
      expect(s.engine!.progress.done).toBe(true);
    } finally {
      dispose();
    }
    expect(page.listeners).toBe(0);
  });

  it("luminaireWeights: the scene's dimming × colour, with the overlay, and during a crossfade (1 − e)·from + e·scene (the glow follows them)", () => {
    const q = manualQueue();
    const { s, dispose } = service(fakePage(), q);
    try {
      expect(s.luminaireWeights()).toBeNull();
      const coloured: BakeScene = { ...scene, luminaires: [{ ...scene.luminaires[0], dimming: 0.5, color: [1, 0.8, 0.6] }, scene.luminaires[1]] };
      s.setScene(coloured);
      expect(s.luminaireWeights()).toEqual([
        [0.5, 0.4, 0.3],
        [1, 1, 1],
      ]);
      s.setOverlay((sc) => ({ ...sc, luminaires: sc.luminaires.map((l) => ({ ...l, dimming: 0 })) }));
      expect(s.luminaireWeights()).toEqual([
        [0, 0, 0],
        [0, 0, 0],
      ]);
      s.setOverlay(null);
      s.setFade({ from: (sc) => ({ ...sc, luminaires: sc.luminaires.map((l) => ({ ...l, dimming: 1, color: [1, 1, 1] as [number, number, number] })) }), e: 0.25 });
      const w = s.luminaireWeights()!;
      [0.75 + 0.25 * 0.5, 0.75 + 0.25 * 0.4, 0.75 + 0.25 * 0.3].forEach((v, k) => expect(w[0][k]).toBeCloseTo(v, 12));
      expect(w[1]).toEqual([1, 1, 1]);
      s.setFade(null);
    } finally {
      dispose();
    }
  });

  it('a new scene replaces the pending work: groups of the old scene not yet baked never are', () => {
    const { s, q, events, dispose } = watchedService();
    try {
      // Three groups in one room; after one slice, another room with one luminaire.
      s.setScene({ room, luminaires: [lum(1, 1), lum(2, 2), lum(1.5, 0.5)] });
      q.drain(1);
      expect(s.status().groupBakes).toBe(1);
      const other: BakeScene = { room: uniformRoom(2, 2.5, 2, 0.5), luminaires: [lum(1, 1)] };
      s.setScene(other);
      q.drain();
      expect(s.engine!.progress).toMatchObject({ groups: 1, groupsDone: 1, done: true });
      // One bake for the first scene's first group, one for the new scene: the other two were cancelled.
      expect(s.status().groupBakes).toBe(2);
      expect(s.scene).toBe(other);
      // The same scene again is a relight at most: nothing is baked.
      const before = s.status();
      s.setScene({ ...other });
      q.drain();
      expect(s.status().groupBakes).toBe(before.groupBakes);
      expect(s.status().indirectSolves).toBe(before.indirectSolves);
      expect(events).toContain('slice');
    } finally {
      dispose();
    }
  });

  it('a quality change makes a fresh engine with that level and rebakes; counters run on', () => {
    const { s, q, events, dispose } = watchedService();
    try {
      s.setScene(scene);
      q.drain();
      expect(s.status().groupBakes).toBe(2);
      const first = s.engine;
      s.setQuality('balanced');
      expect(events).toContain('engine');
      expect(s.engine).not.toBe(first);
      expect(s.engine!.settings.texelSize).toBe(0.05);
      q.drain();
      expect(s.status()).toMatchObject({ done: true, groupBakes: 4, quality: 'balanced' });
    } finally {
      dispose();
    }
  });

  it('light sources: the engine shows what the service was told (a relight, announced at once, no bake), also after a quality change', () => {
    const { s, q, events, dispose } = watchedService();
    try {
      s.setScene(scene);
      q.drain();
      const before = s.status();
      events.length = 0;
      s.setLightSources('daylight');
      expect(events).toEqual(['slice']);
      expect(s.lightSources).toBe('daylight');
      expect(s.engine!.lightSources).toBe('daylight');
      q.drain();
      // No daylight in this scene: the luminaires are off, nothing is baked, the dark weights are solved at once (no light, no solve).
      expect(s.status().groupBakes).toBe(before.groupBakes);
      const lit = s.engine!.maps().maps.floor.total.reduce((a, b) => a + b, 0);
      expect(lit).toBe(0);
      expect(() => s.setLightSources('moon' as never)).toThrow(/not one of/);
      expect(s.lightSources).toBe('daylight');
      s.setQuality('balanced');
      expect(s.engine!.lightSources).toBe('daylight');
      s.setLightSources('both');
      q.drain();
      expect(s.engine!.maps().maps.floor.total.reduce((a, b) => a + b, 0)).toBeGreaterThan(0);
    } finally {
      dispose();
    }
  });

  it('on a low-memory device the baker pooled targets are freed once per finished bake, and the next bake still works', () => {
    for (const lowMemory of [true, false]) {
      const q = manualQueue(true);
      const { s, dispose } = service(fakePage(), q, lowMemory);
      try {
        s.setScene(scene);
        const engine = s.engine!;
        let released = 0;
        const release = engine.releaseTargets.bind(engine);
        engine.releaseTargets = () => {
          expect(engine.progress.done).toBe(true);
          released++;
          release();
        };
        q.drain();
        expect(released).toBe(lowMemory ? 1 : 0);
        // A moved luminaire: one more group, baked on freshly allocated targets.
        s.setScene({ room, luminaires: [lum(1, 1), lum(2.2, 1.8)] });
        q.drain();
        expect(s.status()).toMatchObject({ done: true, groupBakes: 3 });
        expect(released).toBe(lowMemory ? 2 : 0);
      } finally {
        dispose();
      }
    }
  });
});
