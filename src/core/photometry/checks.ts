import { integrateFlux } from './flux';
import { MAX_CANDELA, MAX_LUMENS, MAX_PHOTOMETRY_BYTES, MIN_LUMENS } from './limits';
import { PhotometryParseError } from './PhotometryParseError';
import type { Photometry } from './types';

/** Refuses input over MAX_PHOTOMETRY_BYTES (bytes, or UTF-16 units for text) before any parsing. */
export function checkInputSize(fileName: string, size: number): void {
  if (size > MAX_PHOTOMETRY_BYTES) {
    const mb = (n: number): string => `${Math.round((n / (1024 * 1024)) * 10) / 10} MB`;
    throw new PhotometryParseError(fileName, null, `the file is ${mb(size)}, over the ${mb(MAX_PHOTOMETRY_BYTES)} limit for photometric files`);
  }
}

/**
 * A value read from the header must lie in [min, max] (finite by construction:
 * the number reader never returns NaN or Infinity). `what` names it.
 */
export function checkRange(fileName: string, line: number | null, what: string, value: number, min: number, max: number): void {
  if (!(value >= min && value <= max)) {
    throw new PhotometryParseError(fileName, line, `${what} ${value} is out of range (${min} to ${max})`);
  }
}

/** How the stated lumens relate to the luminaire's output: lamp lumens (relative photometry) or the luminaire's own. */
export type StatedLumensKind = 'lamp' | 'luminaire';

/** Round to 4 significant digits for a message. */
const sig = (x: number): string => String(Number(x.toPrecision(4)));

/**
 * The last gate of both parsers: the model is finite and physical (every
 * candela value in [0, MAX_CANDELA], the integrated flux finite and at most
 * MAX_LUMENS, stated lumens null or in [MIN_LUMENS, MAX_LUMENS]), else the
 * file is refused; and the stated lumens are compared with the integrated
 * flux, which is what the renderer uses (a warning when they disagree).
 */
export function finishPhotometry(ph: Photometry, fileName: string, statedKind: StatedLumensKind): Photometry {
  for (const row of ph.candela) {
    for (const cd of row) {
      // The readers check every value after scaling; this guards the expansion and type A/B resampling.
      if (!(cd >= 0 && cd <= MAX_CANDELA)) throw new PhotometryParseError(fileName, null, `candela value ${cd} is out of range (0 to ${MAX_CANDELA} cd)`);
    }
  }
  const flux = integrateFlux(ph);
  if (!(flux >= 0 && flux <= MAX_LUMENS)) {
    throw new PhotometryParseError(fileName, null, `integrated flux ${sig(flux)} lm is out of range (0 to ${MAX_LUMENS} lm)`);
  }
  if (flux === 0) ph.warnings.push('every candela value is 0: the luminaire emits no light');
  const stated = ph.statedLumens;
  if (stated !== null && !(stated >= MIN_LUMENS && stated <= MAX_LUMENS)) {
    throw new PhotometryParseError(fileName, null, `stated lumens ${sig(stated)} lm are out of range (${MIN_LUMENS} to ${MAX_LUMENS} lm)`);
  }
  const warning = lumensWarning(flux, stated, statedKind);
  if (warning) ph.warnings.push(warning);
  return ph;
}

/**
 * Stated vs integrated lumens (issue 18: a 60× disagreement went unsaid).
 * For the luminaire's own lumens (absolute photometry, EULUMDAT lamp flux ×
 * LORL) the two must agree: a difference over 5 % is reported. For lamp
 * lumens (IES relative photometry) integrated/stated is the light output
 * ratio, normally 0.3–1: above 1.05 (more light than the lamps give) or
 * below 0.1 is reported. Either way the candela data — the integrated flux —
 * is what is used.
 */
export function lumensWarning(flux: number, stated: number | null, kind: StatedLumensKind): string | null {
  if (stated === null || !(stated > 0) || !(flux > 0)) return null;
  const ratio = flux / stated;
  if (kind === 'luminaire') {
    if (Math.abs(ratio - 1) <= 0.05) return null;
    return `stated lumens ${sig(stated)} lm and integrated flux ${sig(flux)} lm differ by ${sig((ratio - 1) * 100)} % (ratio ${sig(ratio)}); the integrated flux of the candela data is used`;
  }
  if (ratio > 1.05) {
    return `integrated flux ${sig(flux)} lm exceeds the stated lamp lumens ${sig(stated)} lm (light output ratio ${sig(ratio)} > 1); the candela data is used`;
  }
  if (ratio < 0.1) {
    return `integrated flux ${sig(flux)} lm is only ${sig(ratio * 100)} % of the stated lamp lumens ${sig(stated)} lm; the candela data is used`;
  }
  return null;
}

/**
 * The non-fatal problems found while reading a photometric file, one line
 * each (≤ 200 characters), for bake reports, the UI and `luxbox ies info`:
 * a 360° plane that differs from the 0° plane, stated lumens that disagree
 * with the integrated flux, angles listed in descending order, trailing junk,
 * ignored header fields, … (docs/photometry.md, "Warnings").
 */
export function photometryWarnings(ph: Pick<Photometry, 'warnings'>): string[] {
  return [...new Set(ph.warnings)];
}
