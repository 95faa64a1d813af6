import { InputError } from '../../core/inputError';
import { COLOUR_FILTER_LIBRARY, type FilterKind } from '../../core/colour/colourFilterLibrary';
import { loadColourFilterSpectra } from '../../core/colour/colourFilterSpectra';
import { moduleColour } from '../../core/colour/moduleColour';
import { CCT_MAX_K, CCT_MIN_K } from '../../core/photometry/cct';

/** A command-line usage problem (unknown option, bad --cct). */
export class FiltersCommandError extends InputError {
  override name = 'FiltersCommandError';
}

const USAGE = 'usage: luxbox filters [--json] [--cct K]   (K: source colour temperature, 1000–20000, default 3000)';

/** Source colour temperature when --cct is not given: the default catalog's warm white. */
export const DEFAULT_SOURCE_CCT = 3000;

export interface FilterRow {
  id: string;
  maker: string;
  number: string;
  name: string;
  kind: FilterKind;
  /** CIE 1931 chromaticity of the filtered light. */
  x: number;
  y: number;
  /** Luminous transmittance τ_v, 0..1, for this source. */
  transmission: number;
  /** Near white only (|Duv| ≤ 0.02): CCT (K) and Duv; otherwise null. */
  cct: number | null;
  duv: number | null;
}

export interface FiltersListing {
  sourceCct: number;
  filters: FilterRow[];
}

/** The library seen through a Planckian source at `sourceCct` (docs/colour-filters.md); the spectra must be loaded. */
export function listFilters(sourceCct: number): FiltersListing {
  const round = (v: number, digits: number) => Number(v.toFixed(digits));
  const filters = COLOUR_FILTER_LIBRARY.filters.map((f): FilterRow => {
    const c = moduleColour(sourceCct, f.id);
    return {
      id: f.id,
      maker: f.maker,
      number: f.number,
      name: f.name,
      kind: f.kind,
      x: round(c.x, 5),
      y: round(c.y, 5),
      transmission: round(c.transmission, 5),
      cct: c.white ? Math.round(c.white.cct) : null,
      duv: c.white ? round(c.white.duv, 5) : null,
    };
  });
  return { sourceCct, filters };
}

/** `luxbox filters [--json] [--cct K]`: lists the colour-filter library with x, y and transmission. */
export async function run(args: string[]): Promise<number> {
  await loadColourFilterSpectra();
  let json = false;
  let cct = DEFAULT_SOURCE_CCT;
  for (let i = 0; i < args.length; i++) {
    const a = args[i];
    if (a === '--json') json = true;
    else if (a === '--cct') {
      const v = args[++i];
      cct = Number(v);
      if (v === undefined || !Number.isFinite(cct) || cct < CCT_MIN_K || cct > CCT_MAX_K) throw new FiltersCommandError(`--cct needs a colour temperature from ${CCT_MIN_K} to ${CCT_MAX_K} K (got ${v ?? 'nothing'}); ${USAGE}`);
    } else throw new FiltersCommandError(`unknown argument ${a}; ${USAGE}`);
  }
  const listing = listFilters(cct);
  process.stdout.write(json ? JSON.stringify(listing, null, 2) + '\n' : toText(listing));
  return 0;
}

function toText(listing: FiltersListing): string {
  const head = ['id', 'filter', 'kind', 'x', 'y', 'transmission', 'CCT', 'Duv'];
  const rows = listing.filters.map((f) => [
    f.id,
    `${f.maker.split(' ')[0]} ${f.number} ${f.name}`,
    f.kind,
    f.x.toFixed(4),
    f.y.toFixed(4),
    `${(f.transmission * 100).toFixed(1)} %`,
    f.cct === null ? '' : `${f.cct} K`,
    f.duv === null ? '' : f.duv.toFixed(4),
  ]);
  const widths = head.map((h, k) => Math.max(h.length, ...rows.map((r) => r[k].length)));
  const line = (r: string[]) =>
    r
      .map((c, k) => (k >= 3 ? c.padStart(widths[k]) : c.padEnd(widths[k])))
      .join('  ')
      .trimEnd();
  return [`${listing.filters.length} colour filters through a ${listing.sourceCct} K Planckian source (CIE 1931 2°; transmission = luminous transmittance τ_v)`, line(head), ...rows.map(line)].join('\n') + '\n';
}
