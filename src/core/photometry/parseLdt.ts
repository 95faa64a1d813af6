import { checkInputSize, checkRange, finishPhotometry } from './checks';
import { MAX_NUMERAL_LENGTH, readDecimal } from './decimal';
import { splitLines } from './decodeText';
import { expandTypeC } from './expandTypeC';
import {
  LDT_CONVERSION_FACTOR_RANGE,
  MAX_CANDELA_VALUES,
  MAX_DIMENSION_M,
  MAX_HORIZONTAL_ANGLES,
  MAX_LAMP_SETS,
  MAX_LUMENS,
  MAX_VERTICAL_ANGLES,
  MAX_WATTS,
  MIN_LUMENS,
  SCALE_RANGE,
} from './limits';
import { NumberReader } from './numberReader';
import { luminousOpening } from './iesHeader';
import { excerpt, PhotometryParseError } from './PhotometryParseError';
import { checkLeftovers, readAngles, readCandela } from './readGrid';
import type { Photometry } from './types';

/** Largest |dimension| in mm (luminaire and luminous area sizes). */
const MAX_DIMENSION_MM = MAX_DIMENSION_M * 1000;

/**
 * Parses EULUMDAT (.ldt) text. The format is line-oriented: lines 1–26 are
 * fixed header fields (strings and single numbers), then for each of n lamp
 * sets six lines (count, type, flux, colour, CRI, watts), ten direct ratios,
 * Mc C-plane angles, Ng γ angles and the intensities in cd/klm for the planes
 * that the symmetry indicator Isym says are stored:
 *   Isym 0: all Mc planes; 1: one plane (rotational); 2: C0..C180 (Mc/2+1);
 *   3: C270 → C0 → C90 (Mc/2+1, stored from plane index 3Mc/4);
 *   4: C0..C90 (Mc/4+1).
 * (EULUMDAT format description, Stockmar 1990; the plane ranges Mc1..Mc2 per
 * Isym given there.) Intensities in cd = value × Σ lamp flux / 1000 × line 24's
 * conversion factor.
 *
 * The header, the lamp sets and the ten direct ratios are read line by line,
 * as the format defines them: an empty line is a field "not given" (real
 * manufacturer files leave the direct ratios, CCT, CRI, … empty), never a line
 * to skip (issue 18: skipping them took the first C-plane angles for direct
 * ratios). Angles and intensities, whose counts are known, are then read as a
 * number stream that tolerates several values per line.
 */
export function parseLdt(text: string, fileName: string): Photometry {
  checkInputSize(fileName, text.length);
  // A decimal comma ("0,5") is used by some German exporters: with one value
  // per line it is unambiguous.
  const lines = splitLines(text).map((l) => (/^\s*[+-]?\d*,\d+\s*$/.test(l) ? l.replace(',', '.') : l));
  const warnings: string[] = [];
  let index = 0;

  const stringField = (what: string): string => {
    if (index >= lines.length) throw new PhotometryParseError(fileName, lines.length, `unexpected end of file: expected ${what}`);
    const t = lines[index++].trim();
    return t.length >= 2 && t.startsWith('"') && t.endsWith('"') ? t.slice(1, -1) : t;
  };
  /** A numeric line; empty → null when `optional` (the field is not given). */
  const optionalNumber = (what: string, optional: boolean): number | null => {
    const line = index + 1;
    const raw = stringField(what);
    if (raw === '' && optional) return null;
    const read = readDecimal(raw);
    if (read.ok) return read.value;
    const problem =
      read.problem === 'not a number'
        ? `expected ${what} (a number${optional ? ' or an empty line' : ''}), found "${excerpt(raw)}"`
        : read.problem === 'too long'
          ? `${what}: a numeral of ${raw.length} characters is too long (limit ${MAX_NUMERAL_LENGTH})`
          : `${what} "${excerpt(raw)}" is out of range`;
    throw new PhotometryParseError(fileName, line, problem);
  };
  const numberField = (what: string): number => optionalNumber(what, false) as number;
  /** An optional numeric field: empty means "not given" (0 where a value is needed). */
  const optionalField = (what: string): number | null => optionalNumber(what, true);
  const intField = (what: string, min: number, max: number): number => {
    const line = index + 1;
    const value = numberField(what);
    if (!Number.isInteger(value) || value < min) {
      throw new PhotometryParseError(fileName, line, `${what} must be an integer ≥ ${min}, found ${value}`);
    }
    if (value > max) throw new PhotometryParseError(fileName, line, `${what} ${value} exceeds the limit of ${max}`);
    return value;
  };

  const company = stringField('the company identification');
  const ityp = numberField('the type indicator Ityp');
  const isymLine = index + 1;
  const isym = numberField('the symmetry indicator Isym');
  if (![0, 1, 2, 3, 4].includes(isym)) {
    throw new PhotometryParseError(fileName, isymLine, `symmetry indicator Isym must be 0..4, found ${isym}`);
  }
  if (![0, 1, 2, 3].includes(ityp)) warnings.push(`type indicator Ityp is ${ityp} (expected 0..3); ignored`);
  const mcLine = index + 1;
  const mc = intField('the number of C-planes Mc', 1, MAX_HORIZONTAL_ANGLES);
  optionalField('the C-plane distance Dc');
  const ngLine = index + 1;
  const ng = intField('the number of γ angles Ng', 2, MAX_VERTICAL_ANGLES);
  optionalField('the γ distance Dg');
  if (mc * ng > MAX_CANDELA_VALUES) {
    throw new PhotometryParseError(fileName, ngLine, `${mc} × ${ng} intensities exceed the limit of ${MAX_CANDELA_VALUES}`);
  }
  if ((isym === 2 || isym === 3) && mc % 2 !== 0) {
    throw new PhotometryParseError(fileName, mcLine, `Isym ${isym} needs an even number of C-planes, found ${mc}`);
  }
  if (isym === 4 && mc % 4 !== 0) {
    throw new PhotometryParseError(fileName, mcLine, `Isym 4 needs a multiple of 4 C-planes, found ${mc}`);
  }
  const reportNumber = stringField('the measurement report number');
  const luminaireName = stringField('the luminaire name');
  const luminaireNumber = stringField('the luminaire number');
  const sourceFileName = stringField('the file name');
  const dateUser = stringField('the date/user');
  const dimension = (what: string): number => {
    const line = index + 1;
    const value = optionalField(what) ?? 0;
    checkRange(fileName, line, what, value, -MAX_DIMENSION_MM, MAX_DIMENSION_MM);
    return value;
  };
  const dims = ['length', 'width', 'height'].map((d) => dimension(`the luminaire ${d} (mm)`));
  const lumLength = dimension('the luminous area length/diameter (mm)');
  const lumWidth = dimension('the luminous area width (mm)');
  const heights = ['C0', 'C90', 'C180', 'C270'].map((c) => dimension(`the luminous area height at ${c} (mm)`));
  const dff = optionalField('the downward flux fraction DFF (%)');
  const lorlLine = index + 1;
  const lorl = optionalField('the light output ratio LORL (%)');
  const cfliLine = index + 1;
  const cfliGiven = optionalField('the intensity conversion factor');
  const tiltAngle = optionalField('the tilt angle during measurement');
  const n = intField('the number of lamp sets', 1, MAX_LAMP_SETS);

  let totalFlux = 0;
  let watts = 0;
  const lampTypes: string[] = [];
  const fluxLines: number[] = [];
  for (let s = 0; s < n; s++) {
    optionalField(`the number of lamps (set ${s + 1})`);
    lampTypes.push(stringField(`the lamp type (set ${s + 1})`));
    fluxLines.push(index + 1);
    const flux = Math.abs(numberField(`the lamp flux (set ${s + 1})`));
    if (flux > 0) checkRange(fileName, index, `lamp flux (set ${s + 1}, lm)`, flux, MIN_LUMENS, MAX_LUMENS);
    totalFlux += flux;
    stringField(`the colour temperature (set ${s + 1})`);
    stringField(`the colour rendering index (set ${s + 1})`);
    watts += optionalField(`the wattage (set ${s + 1})`) ?? 0;
  }
  if (!(totalFlux > 0)) throw new PhotometryParseError(fileName, fluxLines[0], 'total lamp flux must be positive, found 0');
  checkRange(fileName, fluxLines[0], 'total lamp flux (lm)', totalFlux, MIN_LUMENS, MAX_LUMENS);
  if (cfliGiven === null) warnings.push(`line ${cfliLine}: the intensity conversion factor is not given; 1 is used`);
  const cfli = cfliGiven ?? 1;
  if (!(cfli > 0)) throw new PhotometryParseError(fileName, cfliLine, `intensity conversion factor must be positive, found ${cfli}`);
  checkRange(fileName, cfliLine, 'intensity conversion factor', cfli, ...LDT_CONVERSION_FACTOR_RANGE);
  if (lorl === null) warnings.push(`line ${lorlLine}: the light output ratio LORL is not given; no stated lumens`);
  else if (!(lorl > 0 && lorl <= 100.5)) warnings.push(`light output ratio LORL is ${lorl} % (expected 0..100)`);
  if (lorl !== null && lorl < 0) throw new PhotometryParseError(fileName, lorlLine, `light output ratio LORL must not be negative, found ${lorl}`);
  if (lorl !== null) checkRange(fileName, lorlLine, 'light output ratio LORL (%)', lorl, 0, 1000);
  const statedLumens = lorl !== null && lorl > 0 ? (totalFlux * lorl) / 100 : null;
  if (statedLumens !== null) {
    checkRange(fileName, lorlLine, 'stated lumens (lamp flux × LORL)', statedLumens, MIN_LUMENS, MAX_LUMENS);
  }
  if (!(watts <= MAX_WATTS)) warnings.push(`total wattage ${watts} W exceeds ${MAX_WATTS} W; ignored`);

  // Ten direct ratios (DR for room indices k = 0.6 … 5), one line each; an
  // empty line is a ratio not given. A line holding several numbers counts as
  // that many ratios (tolerated; never more than ten).
  let ratios = 0;
  while (ratios < 10) {
    const line = index + 1;
    const raw = stringField(`direct ratio ${ratios + 1} of 10`);
    if (raw === '') {
      ratios++;
      continue;
    }
    const parts = raw.split(/[\s,;]+/);
    if (ratios + parts.length > 10) {
      throw new PhotometryParseError(fileName, line, `expected ${10 - ratios} more direct ratio(s) (10 in all), found ${parts.length} values on this line`);
    }
    for (const part of parts) {
      const read = readDecimal(part);
      if (!read.ok) {
        throw new PhotometryParseError(fileName, line, `expected direct ratio ${ratios + 1} of 10 (a number or an empty line), found "${excerpt(part)}"`);
      }
      ratios++;
    }
  }

  // From here on: numbers with known counts, tolerated several per line.
  const reader = new NumberReader(fileName, lines.slice(index), index + 1);
  const cAngles = readAngles(reader, fileName, mc, 'C-plane angles', 0, 360).angles;
  const gammas = readAngles(reader, fileName, ng, 'γ angles', 0, 180).angles;
  const anglesLine = reader.lastLine;

  // Which stored planes, at which C angles (see the comment at the top).
  let stored: number[];
  if (isym === 0) stored = cAngles.map((_, i) => i);
  else if (isym === 1) stored = [0];
  else if (isym === 2) stored = range(0, mc / 2);
  else if (isym === 3) stored = [...range((3 * mc) / 4, mc - 1), ...range(0, mc / 4)];
  else stored = range(0, mc / 4);
  const scale = (totalFlux / 1000) * cfli;
  checkRange(fileName, cfliLine, 'candela scale (lamp flux / 1000 × conversion factor)', scale, ...SCALE_RANGE);
  const planes = readCandela(
    reader,
    fileName,
    stored.length,
    ng,
    scale,
    (p) => `C-plane ${cAngles[stored[p]]}`,
    (i) => `γ ${gammas[i]}`,
  );
  checkLeftovers(reader, fileName, ng, warnings);

  const expect = (i: number, angle: number): void => {
    if (Math.abs(cAngles[i] - angle) > 1e-6) {
      throw new PhotometryParseError(fileName, anglesLine, `Isym ${isym} needs C-plane ${i + 1} at ${angle}°, found ${cAngles[i]}°`);
    }
  };
  let horizontalAngles: number[];
  let candela: number[][];
  if (isym === 0 || isym === 1) {
    horizontalAngles = isym === 1 ? [0] : cAngles.slice();
    if (isym === 0) expect(0, 0);
    candela = planes;
  } else if (isym === 2) {
    expect(0, 0);
    expect(mc / 2, 180);
    horizontalAngles = stored.map((i) => cAngles[i]);
    candela = planes;
  } else if (isym === 3) {
    expect((3 * mc) / 4, 270);
    expect(mc / 4, 90);
    // Stored C270..C360/C0..C90; the mirror image C' = 180 − C puts them on
    // 90..270, the LM-63 form of the same symmetry, in ascending order.
    const mirrored = stored.map((i, p) => ({ c: 180 - (cAngles[i] >= 270 - 1e-6 ? cAngles[i] - 360 : cAngles[i]), row: planes[p] }));
    mirrored.sort((a, b) => a.c - b.c);
    horizontalAngles = mirrored.map((m) => m.c);
    candela = mirrored.map((m) => m.row);
  } else {
    expect(0, 0);
    expect(mc / 4, 90);
    horizontalAngles = stored.map((i) => cAngles[i]);
    candela = planes;
  }
  const grid = expandTypeC(fileName, { verticalAngles: gammas, horizontalAngles, candela }, anglesLine, warnings);

  const keywords: Record<string, string> = {
    COMPANY: company,
    ITYP: String(ityp),
    ISYM: String(isym),
    REPORT: reportNumber,
    LUMINAIRE: luminaireName,
    LUMCAT: luminaireNumber,
    FILENAME: sourceFileName,
    DATE: dateUser,
    LUMINAIRE_DIMENSIONS_MM: dims.join(' × '),
    DFF: dff === null ? '' : String(dff),
    LORL: lorl === null ? '' : String(lorl),
    TILT: tiltAngle === null ? '' : String(tiltAngle),
    LAMP: lampTypes.join('; '),
    LAMP_FLUX: String(totalFlux),
  };
  const mm = 0.001;
  // EULUMDAT: width 0 means a circle of diameter = length; LM-63 signs say the same.
  const lumHeight = Math.max(...heights) * mm;
  const opening =
    lumWidth > 0
      ? luminousOpening(lumWidth * mm, lumLength * mm, lumHeight)
      : luminousOpening(-lumLength * mm, -lumLength * mm, lumHeight);
  const ph: Photometry = {
    format: 'LDT',
    version: 'EULUMDAT',
    manufacturer: company,
    luminaire: luminaireName,
    catalogNumber: luminaireNumber,
    keywords,
    photometricType: 'C',
    symmetry: grid.symmetry,
    verticalAngles: grid.verticalAngles,
    horizontalAngles: grid.horizontalAngles,
    candela: grid.candela,
    statedLumens,
    statedLumensSource: statedLumens === null ? null : 'lamp flux × LORL',
    absolute: false,
    inputWatts: watts > 0 && watts <= MAX_WATTS ? watts : null,
    luminousOpening: opening,
    warnings,
    tilt: null,
    fileGrid: {
      verticalCount: ng,
      horizontalCount: mc,
      verticalRange: [gammas[0], gammas[ng - 1]],
      horizontalRange: [cAngles[0], cAngles[mc - 1]],
    },
    candelaScale: scale,
  };
  return finishPhotometry(ph, fileName, 'luminaire');
}

function range(from: number, to: number): number[] {
  const out: number[] = [];
  for (let i = from; i <= to; i++) out.push(i);
  return out;
}
