import { splitLines } from './decodeText';
import { expandTypeC } from './expandTypeC';
import { MAX_CANDELA_VALUES, MAX_HORIZONTAL_ANGLES, MAX_LAMP_SETS, MAX_VERTICAL_ANGLES } from './limits';
import { NumberReader } from './numberReader';
import { luminousOpening } from './parseIes';
import { PhotometryParseError } from './PhotometryParseError';
import { checkLeftovers, readAngles, readCandela } from './readGrid';
import type { Photometry } from './types';

const NUMBER = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;

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
 */
export function parseLdt(text: string, fileName: string): Photometry {
  // A decimal comma ("0,5") is used by some German exporters: with one value
  // per line it is unambiguous.
  const lines = splitLines(text).map((l) => (/^\s*[+-]?\d*,\d+\s*$/.test(l) ? l.replace(',', '.') : l));
  const warnings: string[] = [];
  let index = 0;

  const stringField = (what: string): string => {
    if (index >= lines.length) throw new PhotometryParseError(fileName, lines.length, `unexpected end of file: expected ${what}`);
    return lines[index++].trim().replace(/^"(.*)"$/, '$1');
  };
  const numberField = (what: string): number => {
    const line = index + 1;
    const raw = stringField(what);
    if (!NUMBER.test(raw)) {
      const shown = raw.length > 24 ? raw.slice(0, 24) + '…' : raw;
      throw new PhotometryParseError(fileName, line, `expected ${what} (a number), found "${shown}"`);
    }
    const value = Number(raw);
    if (!Number.isFinite(value)) throw new PhotometryParseError(fileName, line, `${what} "${raw}" is out of range`);
    return value;
  };
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
  numberField('the C-plane distance Dc');
  const ngLine = index + 1;
  const ng = intField('the number of γ angles Ng', 2, MAX_VERTICAL_ANGLES);
  numberField('the γ distance Dg');
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
  const dims = ['length', 'width', 'height'].map((d) => numberField(`the luminaire ${d} (mm)`));
  const lumLength = numberField('the luminous area length/diameter (mm)');
  const lumWidth = numberField('the luminous area width (mm)');
  const heights = ['C0', 'C90', 'C180', 'C270'].map((c) => numberField(`the luminous area height at ${c} (mm)`));
  const dff = numberField('the downward flux fraction DFF (%)');
  const lorlLine = index + 1;
  const lorl = numberField('the light output ratio LORL (%)');
  const cfliLine = index + 1;
  const cfli = numberField('the intensity conversion factor');
  const tiltAngle = numberField('the tilt angle during measurement');
  const n = intField('the number of lamp sets', 1, MAX_LAMP_SETS);

  let totalFlux = 0;
  let watts = 0;
  const lampTypes: string[] = [];
  const fluxLines: number[] = [];
  for (let s = 0; s < n; s++) {
    numberField(`the number of lamps (set ${s + 1})`);
    lampTypes.push(stringField(`the lamp type (set ${s + 1})`));
    fluxLines.push(index + 1);
    totalFlux += Math.abs(numberField(`the lamp flux (set ${s + 1})`));
    stringField(`the colour temperature (set ${s + 1})`);
    stringField(`the colour rendering index (set ${s + 1})`);
    watts += numberField(`the wattage (set ${s + 1})`);
  }
  if (!(totalFlux > 0)) throw new PhotometryParseError(fileName, fluxLines[0], 'total lamp flux must be positive, found 0');
  if (!(cfli > 0)) throw new PhotometryParseError(fileName, cfliLine, `intensity conversion factor must be positive, found ${cfli}`);
  if (!(lorl > 0 && lorl <= 100.5)) warnings.push(`light output ratio LORL is ${lorl} % (expected 0..100)`);
  if (lorl < 0) throw new PhotometryParseError(fileName, lorlLine, `light output ratio LORL must not be negative, found ${lorl}`);

  // From here on: numbers, tolerated several per line.
  const reader = new NumberReader(fileName, lines.slice(index), index + 1);
  for (let k = 0; k < 10; k++) reader.next(`direct ratio ${k + 1} of 10`);
  const cAngles = readAngles(reader, fileName, mc, 'C-plane angles', 0, 360);
  const gammas = readAngles(reader, fileName, ng, 'γ angles', 0, 180);
  const anglesLine = reader.lastLine;

  // Which stored planes, at which C angles (see the comment at the top).
  let stored: number[];
  if (isym === 0) stored = cAngles.map((_, i) => i);
  else if (isym === 1) stored = [0];
  else if (isym === 2) stored = range(0, mc / 2);
  else if (isym === 3) stored = [...range((3 * mc) / 4, mc - 1), ...range(0, mc / 4)];
  else stored = range(0, mc / 4);
  const scale = (totalFlux / 1000) * cfli;
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
  const grid = expandTypeC(fileName, { verticalAngles: gammas, horizontalAngles, candela }, anglesLine);

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
    DFF: String(dff),
    LORL: String(lorl),
    TILT: String(tiltAngle),
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
  return {
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
    statedLumens: (totalFlux * lorl) / 100,
    statedLumensSource: 'lamp flux × LORL',
    absolute: false,
    inputWatts: watts > 0 ? watts : null,
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
}

function range(from: number, to: number): number[] {
  const out: number[] = [];
  for (let i = from; i <= to; i++) out.push(i);
  return out;
}
