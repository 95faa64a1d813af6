import type { Rgb } from '../../../core/model/lightingScene/lightingScene';
import type { BakeScene } from '../../bake/bakeScene';
import type { RelightEngine } from '../../relight/RelightEngine';
import { luminaireWeight } from '../luminaireWeight';

/** A crossfade as the service takes it: the scene faded from as a function of the (lit) scene. */
export interface ServiceFade {
  from: (scene: BakeScene) => BakeScene;
  e: number;
}

/** The fade on the engine, from `shown`; null (and no fade on the engine) when the scene faded from no longer matches (its luminaires changed). */
export function applyFade(engine: RelightEngine, shown: BakeScene, fade: ServiceFade): ServiceFade | null {
  try {
    engine.setFade({ from: fade.from(shown), e: fade.e });
    return fade;
  } catch {
    engine.setFade(null);
    return null;
  }
}

/** Each luminaire's weight in the light shown: `shown`'s, or during a crossfade (1 − e)·from + e·shown, as the engine mixes the bases. */
export function fadedWeights(shown: BakeScene, fade: ServiceFade | null): Rgb[] {
  const now = shown.luminaires.map(luminaireWeight);
  if (!fade) return now;
  try {
    const from = fade.from(shown).luminaires.map(luminaireWeight);
    if (from.length !== now.length) return now;
    const e = fade.e;
    return now.map((w, i) => w.map((c, k) => (1 - e) * from[i][k] + e * c) as Rgb);
  } catch {
    return now;
  }
}
