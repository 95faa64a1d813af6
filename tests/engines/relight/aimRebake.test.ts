/**
 * Aiming rebakes one module only (docs/aiming.md): a group is one module's geometry, so a new aim
 * (a setAim through the model, toLightingScene's new yaw/pitch/roll) bakes exactly that module's
 * basis again, and the preview's "module out of the maps" (dimming 0, withoutModule) is a relight.
 * Counted with the relight engine's counters on headless-gl.
 */
import { describe, expect, it } from 'vitest';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import { toLightingScene } from '../../../src/core/model/files/toLightingScene';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import { withoutModule } from '../../../src/engines/view/createSpotlight';
import type { Configuration } from '../../../src/core/model/configuration/configuration';
import { catalog, run } from '../../core/model/helpers';
import { loadReal } from '../../core/photometry/helpers';
import { withHeadlessGL } from '../bake/withHeadlessGL';

const gl = withHeadlessGL();
const SETTINGS = { texelSize: 0.25, maxTextureSize: 32, samples: 8, bounces: 1, samplesPerDraw: 8, blurRadius: 1, seed: 3 };
const files = new Map<string, ReturnType<typeof loadReal>>();
function bakeScene(config: Configuration): { scene: BakeScene; ids: string[] } {
  const ls = toLightingScene(config, catalog);
  return {
    ids: ls.luminaires.map((l) => l.id!),
    scene: {
      room: ls.room,
      luminaires: ls.luminaires.map((l) => {
        const name = l.photometry.replace(/^ies\//, '');
        if (!files.has(name)) files.set(name, loadReal(name));
        return { photometry: files.get(name)!, position: l.position, yaw: l.yaw, pitch: l.pitch, roll: l.roll, dimming: l.dimming ?? 1, color: l.color ?? [1, 1, 1] };
      }),
    },
  };
}

describe('aiming rebakes one module', () => {
  it('a new aim bakes one group; dimming the dragged module out of the maps bakes none', () => {
    const base = run(createConfiguration({ width: 4, depth: 3, height: 2.8 }), 'placePreset', { presetId: 'single', x: 1, z: 1.5, rotation: 0 });
    const [m1, m2] = base.systems[0].rails[0].modules.map((m) => m.id);
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      const a = bakeScene(base);
      engine.setScene(a.scene);
      engine.finish();
      const start = { ...engine.counters };
      expect(start.groupBakes).toBe(3);
      // The preview's overlay: a relight, no bake.
      engine.setScene(withoutModule(a.scene, a.ids, m2));
      engine.finish();
      expect(engine.counters.groupBakes).toBe(start.groupBakes);
      // Released: the model's new aim, and the overlay still on for the new scene, then off.
      const aimed = run(base, 'aimAt', { moduleId: m2, point: [3.5, 0, 2.5] });
      const b = bakeScene(aimed);
      expect(b.scene.luminaires[1].pitch).toBeGreaterThan(0);
      engine.setScene(withoutModule(b.scene, b.ids, m2));
      engine.finish();
      engine.setScene(b.scene);
      engine.finish();
      expect(engine.counters.groupBakes).toBe(start.groupBakes + 1);
      // Aiming another module: one more.
      engine.setScene(bakeScene(run(aimed, 'setAim', { moduleId: m1, aim: { rotation: 180, tilt: 35 } })).scene);
      engine.finish();
      expect(engine.counters.groupBakes).toBe(start.groupBakes + 2);
    } finally {
      engine.dispose();
    }
  });
});
