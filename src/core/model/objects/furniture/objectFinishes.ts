/**
 * The finishes offered for furniture and imported models (a material's colour): linear-RGB
 * diffuse reflectance for the baker, sRGB display colour (the encoded reflectance) for swatches.
 * They live in core/model, not in src/core/catalog/surface-finishes.json: validate() must know
 * every finish id, and core/model may not import core/catalog (catalog imports model; folders may
 * not import each other, docs/architecture.md). Sources per entry; docs/furniture.md.
 */
import type { Rgb } from '../../lightingScene/lightingScene';
import { reflectanceRgb } from '../../lightingScene/reflectance';

/** Each finish's source of its reflectance is the comment above it (not runtime data: it would only weigh on the first screen). */
export interface ObjectFinishSpec {
  readonly id: string;
  readonly name: string;
  /** Grey or linear RGB, each channel in [0, 0.95]. */
  readonly reflectance: number | Rgb;
  /** sRGB '#rrggbb': the reflectance encoded with the sRGB transfer function (IEC 61966-2-1). */
  readonly display: string;
}

export const OBJECT_FINISHES: readonly ObjectFinishSpec[] = [
  // white lacquered wood or laminate about 0.8 (IES Lighting Handbook 10th ed., white finishes 0.75-0.9)
  { id: 'white-lacquer', name: 'White lacquer', reflectance: 0.8, display: '#e7e7e7' },
  // light wood 0.3-0.4 (IES Lighting Handbook 10th ed.); the light oak floor's colour, luminance 0.35
  { id: 'oak-veneer', name: 'Oak veneer', reflectance: [0.493, 0.327, 0.158], display: '#ba9b6f' },
  // dark wood 0.1-0.15 (IES Lighting Handbook 10th ed.); luminance 0.12
  { id: 'walnut-veneer', name: 'Walnut veneer', reflectance: [0.226, 0.097, 0.038], display: '#835837' },
  // black paint and powder coat 0.04-0.06 (IES Lighting Handbook 10th ed.)
  { id: 'black-metal', name: 'Black powder coat', reflectance: 0.05, display: '#3f3f3f' },
  // brushed stainless steel 0.5-0.6 total reflectance, treated as diffuse (IES Lighting Handbook 10th ed.)
  { id: 'brushed-steel', name: 'Brushed steel', reflectance: 0.55, display: '#c4c4c4' },
  // mid-grey upholstery about 0.25 (IES Lighting Handbook 10th ed., textiles 0.1-0.5)
  { id: 'grey-fabric', name: 'Grey fabric', reflectance: 0.25, display: '#898989' },
  // natural linen about 0.45 (IES Lighting Handbook 10th ed., light textiles); luminance 0.47
  { id: 'beige-linen', name: 'Beige linen', reflectance: [0.559, 0.467, 0.343], display: '#c5b69e' },
  // dark blue textiles 0.05-0.1 (IES Lighting Handbook 10th ed.); luminance 0.06
  { id: 'navy-fabric', name: 'Navy fabric', reflectance: [0.04, 0.06, 0.14], display: '#384569' },
  // white cotton 0.7-0.8 (IES Lighting Handbook 10th ed.)
  { id: 'white-linen', name: 'White bed linen', reflectance: 0.75, display: '#e1e1e1' },
  // green leaves about 0.1 averaged over the visible (Gates et al. 1965, Appl. Opt. 4:11); luminance 0.11
  { id: 'leaf-green', name: 'Leaves', reflectance: [0.06, 0.14, 0.04], display: '#456938' },
  // red clay and brick 0.2-0.3 (IES Lighting Handbook 10th ed.); luminance 0.25
  { id: 'terracotta', name: 'Terracotta', reflectance: [0.45, 0.2, 0.1], display: '#b37c59' },
  // a shelf of mixed book spines, about 0.25 on average (mixed mid-tone colours)
  { id: 'book-spines', name: 'Book spines', reflectance: [0.3, 0.22, 0.17], display: '#958173' },
  // a mid-tone printed canvas about 0.4 (IES Lighting Handbook 10th ed., mid colours 0.3-0.5)
  { id: 'canvas-print', name: 'Canvas print', reflectance: [0.45, 0.4, 0.3], display: '#b3aa95' },
  // light human skin about 0.35 in the visible (Jacquez et al. 1955, J. Appl. Physiol. 8:297); luminance 0.33
  { id: 'skin', name: 'Skin', reflectance: [0.45, 0.3, 0.23], display: '#b39584' },
  // dark blue denim about 0.07 (dark textiles 0.05-0.1, IES Lighting Handbook 10th ed.)
  { id: 'denim', name: 'Denim', reflectance: [0.05, 0.07, 0.12], display: '#3f4b61' },
  // light granite or quartz worktop 0.5-0.6 (IES Lighting Handbook 10th ed.); luminance 0.58
  { id: 'stone-worktop', name: 'Light stone', reflectance: [0.6, 0.58, 0.54], display: '#cbc8c2' },
  // mid grey paint 0.5 (IES Lighting Handbook 10th ed.)
  { id: 'mid-grey-paint', name: 'Mid grey paint', reflectance: 0.5, display: '#bcbcbc' },
];

const byId = new Map(OBJECT_FINISHES.map((f) => [f.id, f]));

/** The finish with this id, or undefined. */
export function findObjectFinish(id: string): ObjectFinishSpec | undefined {
  return byId.get(id);
}

/** Linear RGB of a known finish id (throws for an unknown one: callers validate first). */
export function objectFinishRgb(id: string): Rgb {
  const f = byId.get(id);
  if (!f) throw new Error(`unknown object finish '${id}'`);
  return reflectanceRgb(f.reflectance) as Rgb;
}
