import { PNG } from 'pngjs';

/**
 * Turbo colour map, polynomial approximation (A. Mikhailov, Google AI blog
 * 2019, "Turbo, An Improved Rainbow Colormap for Visualization").
 */
export function turbo(t: number): [number, number, number] {
  const x = Math.min(1, Math.max(0, t));
  const r = 0.13572138 + x * (4.6153926 + x * (-42.66032258 + x * (132.13108234 + x * (-152.94239396 + x * 59.28637943))));
  const g = 0.09140261 + x * (2.19418839 + x * (4.84296658 + x * (-14.18503333 + x * (4.27729857 + x * 2.82956604))));
  const b = 0.1066733 + x * (12.64194608 + x * (-60.58204836 + x * (110.36276771 + x * (-89.90310912 + x * 27.34824973))));
  const to8 = (v: number) => Math.round(255 * Math.min(1, Math.max(0, v)));
  return [to8(r), to8(g), to8(b)];
}

// 3×5 bitmap glyphs for the legend labels (no fonts are available offline).
const GLYPHS: Record<string, string> = {
  '0': '111101101101111',
  '1': '010110010010111',
  '2': '111001111100111',
  '3': '111001111001111',
  '4': '101101111001001',
  '5': '111100111001111',
  '6': '111100111101111',
  '7': '111001001001001',
  '8': '111101111101111',
  '9': '111101111001111',
  '.': '000000000000010',
  '-': '000000111000000',
  '+': '000010111010000',
  e: '000111101110011',
  k: '100101110101101',
  l: '100100100100111',
  x: '000101010101000',
  ' ': '000000000000000',
};

/** Short label of a lux value: 3 significant digits, k for thousands, e for the very large. */
export function luxLabel(value: number): string {
  if (value === 0) return '0';
  if (value >= 1e7) return value.toExponential(1).replace('e+', 'e');
  if (value >= 1e4) return `${Number((value / 1000).toPrecision(3))}k`;
  return String(Number(value.toPrecision(3)));
}

/**
 * A false-colour image of a lux map (row j = 0 at the bottom, as in the PFM)
 * with a colour bar and lux labels at 0, ¼, ½, ¾ and 1 of `scaleMax` on the
 * right. Values above scaleMax take the top colour.
 */
export function falseColorPng(lux: Float32Array, width: number, height: number, scaleMax: number): Buffer {
  const zoom = Math.max(1, Math.floor(360 / Math.max(width, height)));
  const mapW = width * zoom;
  const mapH = Math.max(height * zoom, 0);
  const legendW = 110;
  const imgH = Math.max(mapH, 140);
  const png = new PNG({ width: mapW + legendW, height: imgH });
  png.data.fill(255);
  const set = (x: number, y: number, [r, g, b]: [number, number, number]) => {
    const o = (y * png.width + x) * 4;
    png.data[o] = r;
    png.data[o + 1] = g;
    png.data[o + 2] = b;
    png.data[o + 3] = 255;
  };
  const max = scaleMax > 0 ? scaleMax : 1;
  for (let y = 0; y < mapH; y++) {
    const j = height - 1 - Math.floor(y / zoom);
    for (let x = 0; x < mapW; x++) set(x, y, turbo(lux[j * width + Math.floor(x / zoom)] / max));
  }
  const barX = mapW + 10;
  const barTop = 8;
  const barBottom = imgH - 8;
  for (let y = barTop; y <= barBottom; y++) {
    const c = turbo((barBottom - y) / (barBottom - barTop));
    for (let x = barX; x < barX + 16; x++) set(x, y, c);
  }
  const text = (s: string, x0: number, yCentre: number) => {
    const scale = 2;
    const y0 = Math.round(yCentre - (5 * scale) / 2);
    [...s].forEach((ch, n) => {
      const glyph = GLYPHS[ch] ?? GLYPHS[' '];
      for (let gy = 0; gy < 5; gy++)
        for (let gx = 0; gx < 3; gx++)
          if (glyph[gy * 3 + gx] === '1')
            for (let sy = 0; sy < scale; sy++)
              for (let sx = 0; sx < scale; sx++) {
                const x = x0 + n * 4 * scale + gx * scale + sx;
                const y = y0 + gy * scale + sy;
                if (x < png.width && y >= 0 && y < png.height) set(x, y, [0, 0, 0]);
              }
    });
  };
  for (const f of [0, 0.25, 0.5, 0.75, 1]) {
    const y = Math.round(barBottom - f * (barBottom - barTop));
    for (let x = barX + 16; x < barX + 20; x++) set(x, y, [0, 0, 0]);
    text(`${luxLabel(f * max)} lx`, barX + 22, Math.min(imgH - 6, Math.max(6, y)));
  }
  return PNG.sync.write(png);
}
