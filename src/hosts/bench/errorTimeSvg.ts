/** One line of the error-versus-time plot. */
export interface PlotSeries {
  label: string;
  /** [bake seconds, relative error] pairs, in ladder order. */
  rms: [number, number][];
  max: [number, number][];
}

// Distinct colours for up to 14 series (each scene, and the stiff scenes' old method beside them).
const COLORS = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#8c564b', '#e377c2', '#7f7f7f', '#bcbd22', '#17becf', '#393b79', '#637939', '#8c6d31', '#843c39'];
const W = 900;
const H = 440;
const M = { left: 70, right: 270, top: 30, bottom: 55 };

const esc = (s: string): string => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

/** Decades covering [lo, hi] (both > 0). */
function decades(lo: number, hi: number): [number, number] {
  return [Math.floor(Math.log10(lo)), Math.ceil(Math.log10(hi) + 1e-12)];
}

function format(v: number): string {
  if (v >= 1) return String(v);
  return v.toPrecision(1).replace(/^0+/, '0');
}

/**
 * Log–log plot of relative error of total illuminance against bake time: solid
 * lines and filled dots (numbered by ladder rung) for RMS, dashed lines and
 * rings for the largest error.
 * Plain SVG, no dependencies, so docs/benchmarks.md can embed it.
 */
export function errorTimeSvg(series: PlotSeries[], title: string): string {
  const all = series.flatMap((s) => [...s.rms, ...s.max]).filter(([t, e]) => t > 0 && e > 0);
  const [tx0, tx1] = all.length ? decades(Math.min(...all.map((p) => p[0])), Math.max(...all.map((p) => p[0]))) : [-1, 1];
  const [ey0, ey1] = all.length ? decades(Math.min(...all.map((p) => p[1])), Math.max(...all.map((p) => p[1]))) : [-3, 0];
  const pw = W - M.left - M.right;
  const ph = H - M.top - M.bottom;
  const x = (t: number): number => M.left + ((Math.log10(t) - tx0) / (tx1 - tx0)) * pw;
  const y = (e: number): number => M.top + ph - ((Math.log10(e) - ey0) / (ey1 - ey0)) * ph;
  const parts: string[] = [];
  parts.push(`<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}" font-family="sans-serif" font-size="12">`);
  parts.push(`<rect width="${W}" height="${H}" fill="white"/>`);
  parts.push(`<text x="${M.left + pw / 2}" y="18" text-anchor="middle" font-size="14">${esc(title)}</text>`);
  for (let d = tx0; d <= tx1; d++) {
    const px = x(10 ** d);
    parts.push(`<line x1="${px}" y1="${M.top}" x2="${px}" y2="${M.top + ph}" stroke="#ddd"/>`);
    parts.push(`<text x="${px}" y="${M.top + ph + 16}" text-anchor="middle">${format(10 ** d)}</text>`);
  }
  for (let d = ey0; d <= ey1; d++) {
    const py = y(10 ** d);
    parts.push(`<line x1="${M.left}" y1="${py}" x2="${M.left + pw}" y2="${py}" stroke="#ddd"/>`);
    parts.push(`<text x="${M.left - 6}" y="${py + 4}" text-anchor="end">${format(100 * 10 ** d)} %</text>`);
  }
  parts.push(`<rect x="${M.left}" y="${M.top}" width="${pw}" height="${ph}" fill="none" stroke="#333"/>`);
  parts.push(`<text x="${M.left + pw / 2}" y="${H - 12}" text-anchor="middle">bake time, s (log)</text>`);
  parts.push(`<text transform="translate(16 ${M.top + ph / 2}) rotate(-90)" text-anchor="middle">relative error of total lux (log)</text>`);
  series.forEach((s, i) => {
    const c = COLORS[i % COLORS.length];
    // Lines join the settings in order of bake time; numbers name the ladder rung.
    const line = (pts: [number, number][], dash: string): void => {
      const ok = pts.filter(([t, e]) => t > 0 && e > 0).sort((a, b) => a[0] - b[0]);
      if (ok.length > 1) parts.push(`<polyline fill="none" stroke="${c}" stroke-width="1.5"${dash} points="${ok.map(([t, e]) => `${x(t).toFixed(1)},${y(e).toFixed(1)}`).join(' ')}"/>`);
    };
    line(s.rms, '');
    line(s.max, ' stroke-dasharray="5 4"');
    s.rms.forEach(([t, e], k) => {
      if (!(t > 0 && e > 0)) return;
      parts.push(`<circle cx="${x(t).toFixed(1)}" cy="${y(e).toFixed(1)}" r="3.5" fill="${c}"/>`);
      parts.push(`<text x="${(x(t) + 5).toFixed(1)}" y="${(y(e) + 13).toFixed(1)}" font-size="10" fill="${c}">${k + 1}</text>`);
    });
    for (const [t, e] of s.max) if (t > 0 && e > 0) parts.push(`<circle cx="${x(t).toFixed(1)}" cy="${y(e).toFixed(1)}" r="3.5" fill="white" stroke="${c}"/>`);
    const ly = M.top + 14 + i * 20;
    parts.push(`<line x1="${W - M.right + 12}" y1="${ly}" x2="${W - M.right + 36}" y2="${ly}" stroke="${c}" stroke-width="2"/>`);
    parts.push(`<text x="${W - M.right + 42}" y="${ly + 4}">${esc(s.label)}</text>`);
  });
  const ky = M.top + 14 + series.length * 20 + 10;
  parts.push(`<circle cx="${W - M.right + 24}" cy="${ky}" r="3.5" fill="#555"/><text x="${W - M.right + 42}" y="${ky + 4}">RMS</text>`);
  parts.push(`<circle cx="${W - M.right + 24}" cy="${ky + 20}" r="3.5" fill="white" stroke="#555"/><text x="${W - M.right + 42}" y="${ky + 24}">max (dashed)</text>`);
  parts.push('</svg>');
  return parts.join('\n') + '\n';
}
