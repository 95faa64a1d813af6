import { checkInputSize, checkRange, finishPhotometry } from './checks';
import { splitLines } from './decodeText';
import { expandTypeC } from './expandTypeC';
import { MAX_WATTS, SCALE_RANGE } from './limits';
import { NumberReader } from './numberReader';
import { luminousOpening } from './iesHeader';
import { PhotometryParseError } from './PhotometryParseError';
import { checkLeftovers, readAngles, readCandela } from './readGrid';
import type { Photometry } from './types';
import { LdtLineReader } from './ldtLineReader';
import { readLdtHeader, readLdtLamps, skipDirectRatios, type LdtHeader } from './ldtSections';

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

  const r = new LdtLineReader(fileName, lines);
  const h = readLdtHeader(r, warnings);
  const { company, isym, mc, ng, luminaireName, luminaireNumber, cfliLine } = h;
  const lamps = readLdtLamps(r, h, warnings);
  const { totalFlux, watts, cfli, statedLumens } = lamps;
  skipDirectRatios(r);

  // From here on: numbers with known counts, tolerated several per line.
  const reader = new NumberReader(fileName, lines.slice(r.index), r.index + 1);
  const cAngles = readAngles(reader, fileName, mc, 'C-plane angles', 0, 360).angles;
  const gammas = readAngles(reader, fileName, ng, 'γ angles', 0, 180).angles;
  const anglesLine = reader.lastLine;

  // Which stored planes, at which C angles (see the comment at the top).
  const stored = storedPlanes(isym, mc, cAngles);
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

  const { horizontalAngles, candela } = unfoldPlanes(fileName, isym, mc, cAngles, stored, planes, anglesLine);
  const grid = expandTypeC(fileName, { verticalAngles: gammas, horizontalAngles, candela }, anglesLine, warnings);

  const ph: Photometry = {
    format: 'LDT',
    version: 'EULUMDAT',
    manufacturer: company,
    luminaire: luminaireName,
    catalogNumber: luminaireNumber,
    keywords: ldtKeywords(h, lamps),
    photometricType: 'C',
    symmetry: grid.symmetry,
    verticalAngles: grid.verticalAngles,
    horizontalAngles: grid.horizontalAngles,
    candela: grid.candela,
    statedLumens,
    statedLumensSource: statedLumens === null ? null : 'lamp flux × LORL',
    absolute: false,
    inputWatts: watts > 0 && watts <= MAX_WATTS ? watts : null,
    luminousOpening: ldtOpening(h),
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

/** The header's fields as keywords, under the LM-63 names where one exists, so both formats read alike. */
function ldtKeywords(h: LdtHeader, lamps: ReturnType<typeof readLdtLamps>): Record<string, string> {
  const { dff, lorl, tiltAngle } = h;
  return {
    COMPANY: h.company,
    ITYP: String(h.ityp),
    ISYM: String(h.isym),
    REPORT: h.reportNumber,
    LUMINAIRE: h.luminaireName,
    LUMCAT: h.luminaireNumber,
    FILENAME: h.sourceFileName,
    DATE: h.dateUser,
    LUMINAIRE_DIMENSIONS_MM: h.dims.join(' × '),
    DFF: dff === null ? '' : String(dff),
    LORL: lorl === null ? '' : String(lorl),
    TILT: tiltAngle === null ? '' : String(tiltAngle),
    LAMP: lamps.lampTypes.join('; '),
    LAMP_FLUX: String(lamps.totalFlux),
  };
}

/** The luminous area in metres. EULUMDAT: width 0 means a circle of diameter = length; LM-63 signs say the same. */
function ldtOpening({ lumLength, lumWidth, heights }: LdtHeader) {
  const mm = 0.001;
  const lumHeight = Math.max(...heights) * mm;
  return lumWidth > 0 ? luminousOpening(lumWidth * mm, lumLength * mm, lumHeight) : luminousOpening(-lumLength * mm, -lumLength * mm, lumHeight);
}

function range(from: number, to: number): number[] {
  const out: number[] = [];
  for (let i = from; i <= to; i++) out.push(i);
  return out;
}

/** Indices of the C-planes the file stores for symmetry Isym (see parseLdt's comment). */
function storedPlanes(isym: number, mc: number, cAngles: number[]): number[] {
  let stored: number[];
  if (isym === 0) stored = cAngles.map((_, i) => i);
  else if (isym === 1) stored = [0];
  else if (isym === 2) stored = range(0, mc / 2);
  else if (isym === 3) stored = [...range((3 * mc) / 4, mc - 1), ...range(0, mc / 4)];
  else stored = range(0, mc / 4);
  return stored;
}

/** The stored planes as LM-63 type C planes in ascending order, after checking Isym's C angles (Isym 3 mirrored onto 90..270). */
function unfoldPlanes(fileName: string, isym: number, mc: number, cAngles: number[], stored: number[], planes: number[][], anglesLine: number | null): { horizontalAngles: number[]; candela: number[][] } {
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
  return { horizontalAngles, candela };
}
