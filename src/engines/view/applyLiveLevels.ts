/**
 * The live-control overlay on a bake scene: each listed module's dimming (and
 * colour, from its live CCT) replaced. Only dimming and colour change, never a
 * luminaire's photometry, position or angles, so the relight engine keeps every
 * basis and the change is a relight (docs/viewer.md, "Relighting without
 * rebaking"). The configuration is not involved: it stays as it was.
 */
import { cctToLinearRgb } from '../../core/photometry/cct';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import type { BakeScene } from '../bake/bakeScene';
import type { LiveLevel } from './liveLevels';

/** `ids[i]` is the module id of `scene.luminaires[i]` (toLightingScene's order). */
export function applyLiveLevels(scene: BakeScene, ids: readonly string[], levels: ReadonlyMap<string, LiveLevel>): BakeScene {
  if (levels.size === 0) return scene;
  return {
    ...scene,
    luminaires: scene.luminaires.map((l, i) => {
      const live = levels.get(ids[i]);
      if (!live) return l;
      return { ...l, dimming: live.dimming, color: live.cct === null ? l.color : (cctToLinearRgb(live.cct) as Rgb) };
    }),
  };
}
