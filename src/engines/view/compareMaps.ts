import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import type { BakeScene } from '../bake/bakeScene';
import type { RelightEngine } from '../relight/RelightEngine';
import type { LitMaps } from '../relight/relightMaps';

/** A copy of relit maps that outlives the engine's next relight (the engine reuses its output buffers). */
export function copyLitMaps(lit: LitMaps): LitMaps {
  const maps = Object.fromEntries(Object.entries(lit.maps).map(([name, m]) => [name, { ...m, direct: m.direct.slice(), total: m.total.slice() }])) as LitMaps['maps'];
  return { layouts: lit.layouts, maps };
}

/**
 * The relit maps of light scenes that differ from the engine's scene only in dimming and colour
 * (recorded light scenes, docs/light-scenes.md), for the A/B compare: each through the engine's
 * crossfade at e = 0 (a relight: Σ weight · direct basis, and the indirect solution of those
 * weights when it was solved, else the last solve scaled by the reflected flux), copied; the
 * engine's fade is ended afterwards. Null when a scene does not match the engine's luminaires
 * (a module added since), so the compare cannot be drawn.
 */
export function litMapsOf(engine: RelightEngine, scenes: readonly BakeScene[]): LitMaps[] | null {
  try {
    return scenes.map((from) => {
      engine.setFade({ from, e: 0 });
      return copyLitMaps(engine.maps());
    });
  } catch {
    return null;
  } finally {
    engine.setFade(null);
  }
}

/** Each luminaire's weight (dimming × colour) by module id: the glow of a compared scene's luminaires. */
export function moduleWeightsOf(scene: BakeScene, ids: readonly string[]): Map<string, Rgb> {
  const weights = new Map<string, Rgb>();
  scene.luminaires.forEach((l, i) => {
    if (!ids[i]) return;
    const d = Math.max(0, l.dimming ?? 1);
    const c = l.color ?? [1, 1, 1];
    weights.set(ids[i], [d * c[0], d * c[1], d * c[2]]);
  });
  return weights;
}
