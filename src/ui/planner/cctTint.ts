/**
 * A display colour for a colour temperature, used only to tint module symbols and footprints
 * in the 2D plan so warm and cool modules can be told apart at a glance. The stops are sRGB
 * renderings of blackbody colours from Mitchell Charity's table ("What color is a blackbody?",
 * vendian.org, 2° observer, D65 white), rounded; linear interpolation between them in kelvin.
 * The light itself (CCT -> linear RGB for the baker) lives in src/core/photometry.
 */
const STOPS: [number, [number, number, number]][] = [
  [2000, [255, 137, 18]],
  [2700, [255, 169, 87]],
  [3000, [255, 180, 107]],
  [3500, [255, 196, 137]],
  [4000, [255, 209, 163]],
  [5000, [255, 228, 206]],
  [6500, [255, 249, 253]],
];

export function cctTint(kelvin: number): string {
  const k = Number.isFinite(kelvin) ? kelvin : 3000;
  let rgb = STOPS[0][1];
  if (k >= STOPS[STOPS.length - 1][0]) rgb = STOPS[STOPS.length - 1][1];
  else {
    for (let i = 0; i + 1 < STOPS.length; i++) {
      const [k0, c0] = STOPS[i];
      const [k1, c1] = STOPS[i + 1];
      if (k >= k0 && k <= k1) {
        const t = (k - k0) / (k1 - k0);
        rgb = [0, 1, 2].map((j) => Math.round(c0[j] + t * (c1[j] - c0[j]))) as [number, number, number];
        break;
      }
    }
  }
  return `rgb(${rgb[0]}, ${rgb[1]}, ${rgb[2]})`;
}
