/** EULUMDAT's header fields, lamp sets and direct ratios, read line by line (see parseLdt.ts). */
import { checkRange } from './checks';
import { readDecimal } from './decimal';
import { LDT_CONVERSION_FACTOR_RANGE, MAX_CANDELA_VALUES, MAX_HORIZONTAL_ANGLES, MAX_LAMP_SETS, MAX_LUMENS, MAX_VERTICAL_ANGLES, MAX_WATTS, MIN_LUMENS } from './limits';
import type { LdtLineReader } from './ldtLineReader';
import { excerpt, PhotometryParseError } from './PhotometryParseError';

/** Lines 1–26: identification, symmetry and grid counts, names, sizes, ratios, the conversion factor, the lamp set count. */
export function readLdtHeader(r: LdtLineReader, warnings: string[]) {
  const company = r.stringField('the company identification');
  const ityp = r.numberField('the type indicator Ityp');
  const isymLine = r.index + 1;
  const isym = r.numberField('the symmetry indicator Isym');
  if (![0, 1, 2, 3, 4].includes(isym)) {
    throw new PhotometryParseError(r.fileName, isymLine, `symmetry indicator Isym must be 0..4, found ${isym}`);
  }
  if (![0, 1, 2, 3].includes(ityp)) warnings.push(`type indicator Ityp is ${ityp} (expected 0..3); ignored`);
  const mcLine = r.index + 1;
  const mc = r.intField('the number of C-planes Mc', 1, MAX_HORIZONTAL_ANGLES);
  r.optionalField('the C-plane distance Dc');
  const ngLine = r.index + 1;
  const ng = r.intField('the number of γ angles Ng', 2, MAX_VERTICAL_ANGLES);
  r.optionalField('the γ distance Dg');
  if (mc * ng > MAX_CANDELA_VALUES) {
    throw new PhotometryParseError(r.fileName, ngLine, `${mc} × ${ng} intensities exceed the limit of ${MAX_CANDELA_VALUES}`);
  }
  if ((isym === 2 || isym === 3) && mc % 2 !== 0) {
    throw new PhotometryParseError(r.fileName, mcLine, `Isym ${isym} needs an even number of C-planes, found ${mc}`);
  }
  if (isym === 4 && mc % 4 !== 0) {
    throw new PhotometryParseError(r.fileName, mcLine, `Isym 4 needs a multiple of 4 C-planes, found ${mc}`);
  }
  const reportNumber = r.stringField('the measurement report number');
  const luminaireName = r.stringField('the luminaire name');
  const luminaireNumber = r.stringField('the luminaire number');
  const sourceFileName = r.stringField('the file name');
  const dateUser = r.stringField('the date/user');
  const dims = ['length', 'width', 'height'].map((d) => r.dimension(`the luminaire ${d} (mm)`));
  const lumLength = r.dimension('the luminous area length/diameter (mm)');
  const lumWidth = r.dimension('the luminous area width (mm)');
  const heights = ['C0', 'C90', 'C180', 'C270'].map((c) => r.dimension(`the luminous area height at ${c} (mm)`));
  const dff = r.optionalField('the downward flux fraction DFF (%)');
  const lorlLine = r.index + 1;
  const lorl = r.optionalField('the light output ratio LORL (%)');
  const cfliLine = r.index + 1;
  const cfliGiven = r.optionalField('the intensity conversion factor');
  const tiltAngle = r.optionalField('the tilt angle during measurement');
  const n = r.intField('the number of lamp sets', 1, MAX_LAMP_SETS);
  return { company, ityp, isym, mc, ng, reportNumber, luminaireName, luminaireNumber, sourceFileName, dateUser, dims, lumLength, lumWidth, heights, dff, lorlLine, lorl, cfliLine, cfliGiven, tiltAngle, n };
}

export type LdtHeader = ReturnType<typeof readLdtHeader>;

/** The lamp sets (six lines each): total flux and watts, then the conversion factor and LORL checked, the stated lumens. */
export function readLdtLamps(r: LdtLineReader, h: Pick<LdtHeader, 'n' | 'cfliGiven' | 'cfliLine' | 'lorl' | 'lorlLine'>, warnings: string[]) {
  const { n, cfliGiven, cfliLine, lorl, lorlLine } = h;
  let totalFlux = 0;
  let watts = 0;
  const lampTypes: string[] = [];
  const fluxLines: number[] = [];
  for (let s = 0; s < n; s++) {
    r.optionalField(`the number of lamps (set ${s + 1})`);
    lampTypes.push(r.stringField(`the lamp type (set ${s + 1})`));
    fluxLines.push(r.index + 1);
    const flux = Math.abs(r.numberField(`the lamp flux (set ${s + 1})`));
    if (flux > 0) checkRange(r.fileName, r.index, `lamp flux (set ${s + 1}, lm)`, flux, MIN_LUMENS, MAX_LUMENS);
    totalFlux += flux;
    r.stringField(`the colour temperature (set ${s + 1})`);
    r.stringField(`the colour rendering r.index (set ${s + 1})`);
    watts += r.optionalField(`the wattage (set ${s + 1})`) ?? 0;
  }
  if (!(totalFlux > 0)) throw new PhotometryParseError(r.fileName, fluxLines[0], 'total lamp flux must be positive, found 0');
  checkRange(r.fileName, fluxLines[0], 'total lamp flux (lm)', totalFlux, MIN_LUMENS, MAX_LUMENS);
  if (cfliGiven === null) warnings.push(`line ${cfliLine}: the intensity conversion factor is not given; 1 is used`);
  const cfli = cfliGiven ?? 1;
  if (!(cfli > 0)) throw new PhotometryParseError(r.fileName, cfliLine, `intensity conversion factor must be positive, found ${cfli}`);
  checkRange(r.fileName, cfliLine, 'intensity conversion factor', cfli, ...LDT_CONVERSION_FACTOR_RANGE);
  if (lorl === null) warnings.push(`line ${lorlLine}: the light output ratio LORL is not given; no stated lumens`);
  else if (!(lorl > 0 && lorl <= 100.5)) warnings.push(`light output ratio LORL is ${lorl} % (expected 0..100)`);
  if (lorl !== null && lorl < 0) throw new PhotometryParseError(r.fileName, lorlLine, `light output ratio LORL must not be negative, found ${lorl}`);
  if (lorl !== null) checkRange(r.fileName, lorlLine, 'light output ratio LORL (%)', lorl, 0, 1000);
  const statedLumens = lorl !== null && lorl > 0 ? (totalFlux * lorl) / 100 : null;
  if (statedLumens !== null) {
    checkRange(r.fileName, lorlLine, 'stated lumens (lamp flux × LORL)', statedLumens, MIN_LUMENS, MAX_LUMENS);
  }
  if (!(watts <= MAX_WATTS)) warnings.push(`total wattage ${watts} W exceeds ${MAX_WATTS} W; ignored`);
  return { totalFlux, watts, lampTypes, cfli, statedLumens };
}

/**
 * Ten direct ratios (DR for room indices k = 0.6 … 5), one line each; an
 * empty line is a ratio not given. A line holding several numbers counts as
 * that many ratios (tolerated; never more than ten).
 */
export function skipDirectRatios(r: LdtLineReader): void {
  let ratios = 0;
  while (ratios < 10) {
    const line = r.index + 1;
    const raw = r.stringField(`direct ratio ${ratios + 1} of 10`);
    if (raw === '') {
      ratios++;
      continue;
    }
    const parts = raw.split(/[\s,;]+/);
    if (ratios + parts.length > 10) {
      throw new PhotometryParseError(r.fileName, line, `expected ${10 - ratios} more direct ratio(s) (10 in all), found ${parts.length} values on this line`);
    }
    for (const part of parts) {
      const read = readDecimal(part);
      if (!read.ok) {
        throw new PhotometryParseError(r.fileName, line, `expected direct ratio ${ratios + 1} of 10 (a number or an empty line), found "${excerpt(part)}"`);
      }
      ratios++;
    }
  }
}
