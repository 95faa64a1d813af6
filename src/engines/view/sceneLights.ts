import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import type { ModuleLight } from '../../core/model/cues/sceneFade';
import { toLightingScene } from '../../core/model/files/toLightingScene';
import type { BakeScene } from '../bake/bakeScene';

/** Dimming and colour per module id of a configuration's lighting scene (what the baker gets for it). */
export function lightsOf(config: Configuration, catalog: Catalog): Map<string, ModuleLight> {
  return new Map(toLightingScene(config, catalog).luminaires.map((l) => [l.id ?? '', { dimming: l.dimming ?? 1, color: (l.color ?? [1, 1, 1]) as Rgb }]));
}

/** The lit scene's luminaires with another state's dimming and colour (by module id): a crossfade's start, a compared light scene. */
export function fromScene(scene: BakeScene, ids: readonly string[], lights: ReadonlyMap<string, ModuleLight>): BakeScene {
  return {
    ...scene,
    luminaires: scene.luminaires.map((l, i) => {
      const f = lights.get(ids[i]);
      return f ? { ...l, dimming: f.dimming, color: [...f.color] as Rgb } : l;
    }),
  };
}
