import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import type { BakeScene } from '../bake/bakeScene';

/** A luminaire's weight in linear RGB: its dimming (never below 0) × its colour (white when none). */
export function luminaireWeight(l: BakeScene['luminaires'][number]): Rgb {
  const d = Math.max(0, l.dimming ?? 1);
  const c = l.color ?? [1, 1, 1];
  return [d * c[0], d * c[1], d * c[2]];
}
