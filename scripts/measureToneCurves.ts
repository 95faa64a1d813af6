/**
 * Measures the tone curves the viewer could use (ACES filmic as before issue 26, Khronos PBR
 * Neutral, AgX) on the two things a shopper must see (docs/viewer.md, "Choosing the tone curve"):
 *
 * - a gel stays its colour: a patch of a white wall (ρ 0.8) lit by a 3000 K module behind a LEE
 *   filter at 300, 1000 and 3000 lx, in a room exposed for 300 lx on ρ 0.5 (auto exposure's key
 *   0.18 over L̄ = 0.5·300/π cd/m²); the CIELAB hue angle of the pixel (D65 white) against the
 *   hue of the filtered light's own chromaticity x, y (filteredColour), in degrees;
 * - a bright pool keeps its texture: a pattern of ρ 0.4 / 0.6 under 5 000 and 9 000 lx of
 *   neutral (adapted) light at the same exposure; the standard deviation of the pattern's display
 *   values (0–255; two equal halves: |a − b| / 2).
 *
 * Every curve gets the same input: luminance × exposure, hue-preserving gamut mapping
 * (toneMap.ts gamutMap), then the curve, then the sRGB OETF.
 *
 *   npx tsx scripts/measureToneCurves.ts
 */
import { hueAngle, hueDifference, hueOfChromaticity, linearSrgbToXyz, srgbToLinear, xyzToLab } from '../src/core/colour/cielab';
import { loadColourFilterSpectra } from '../src/core/colour/colourFilterSpectra';
import { moduleColour } from '../src/core/colour/moduleColour';
import type { Rgb } from '../src/core/model/lightingScene/lightingScene';
import { acesFilmic, pbrNeutral } from '../src/engines/view/toneCurveCandidates';
import { agx, agxMaxRgb, gamutMap, linearToSrgb } from '../src/engines/view/toneMap';

const CURVES: [string, (c: Rgb) => Rgb][] = [
  ['ACES filmic (before)', acesFilmic],
  ['PBR Neutral', pbrNeutral],
  ['AgX', agx],
  ['AgX curve on max(R,G,B), ratios kept', agxMaxRgb],
];
const EXPOSURE = 0.18 / ((0.5 * 300) / Math.PI);
const display = (curve: (c: Rgb) => Rgb, L: Rgb): Rgb => curve(gamutMap(L.map((v) => v * EXPOSURE) as Rgb)).map(linearToSrgb) as Rgb;
const hueOfDisplay = (c: Rgb) => hueAngle(xyzToLab(linearSrgbToXyz(c.map(srgbToLinear) as Rgb)));

await loadColourFilterSpectra();
const rows: string[] = [];
rows.push(`| measure | ${CURVES.map(([n]) => n).join(' | ')} |`, `|---|${CURVES.map(() => '---').join('|')}|`);
for (const [filter, name] of [
  ['lee-106', 'LEE 106 Primary Red'],
  ['lee-139', 'LEE 139 Primary Green'],
  ['lee-119', 'LEE 119 Dark Blue'],
] as const) {
  const gel = moduleColour(3000, filter);
  const ref = hueOfChromaticity(gel.x, gel.y);
  // The filtered light per lux of it: its linear colour over its own luminance τ_v.
  const perLux = gel.linearRgb.map((v) => v / gel.transmission) as Rgb;
  for (const lux of [300, 1000, 3000]) {
    const L = perLux.map((v) => (0.8 * lux * v) / Math.PI) as Rgb;
    const cells = CURVES.map(([, curve]) => {
      const c = display(curve, L);
      return `${hueDifference(hueOfDisplay(c), ref).toFixed(1)}° (${c.map((v) => Math.round(v * 255)).join(', ')})`;
    });
    rows.push(`| ${name} at ${lux} lx: hue error | ${cells.join(' | ')} |`);
  }
}
for (const lux of [5000, 9000]) {
  const cells = CURVES.map(([, curve]) => {
    const [a, b] = [0.4, 0.6].map((rho) => {
      const L = (rho * lux) / Math.PI;
      return display(curve, [L, L, L])[1] * 255;
    });
    return `${(Math.abs(b - a) / 2).toFixed(2)} (${a.toFixed(1)} / ${b.toFixed(1)})`;
  });
  rows.push(`| ρ 0.4/0.6 pattern under ${lux} lx: std-dev of 0–255 (values) | ${cells.join(' | ')} |`);
}
process.stdout.write(`${rows.join('\n')}\n\nexposure ${EXPOSURE.toExponential(4)} /(cd/m²) (300 lx room, ρ 0.5)\n`);
