/**
 * A colour to show on screen for a light colour (filter picker swatches, the plan's tint): the
 * linear sRGB scaled so its largest component is 1 (hue and saturation kept, brightness
 * normalised, so a dark blue gel still shows as blue and a neutral density as white), then
 * encoded with the sRGB transfer function (IEC 61966-2-1: 12.92·c below 0.0031308, else
 * 1.055·c^(1/2.4) − 0.055) to 8 bits.
 */
export function displaySwatch(linear: readonly [number, number, number]): [number, number, number] {
  const peak = Math.max(linear[0], linear[1], linear[2]);
  if (!(peak > 0)) return [0, 0, 0];
  return linear.map((c) => {
    const v = Math.max(0, c) / peak;
    const encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055;
    return Math.round(255 * encoded);
  }) as [number, number, number];
}

/** displaySwatch as a CSS colour, 'rgb(255, 180, 107)'. */
export function swatchCss(linear: readonly [number, number, number]): string {
  const [r, g, b] = displaySwatch(linear);
  return `rgb(${r}, ${g}, ${b})`;
}
