import { checkInputSize, checkRange, finishPhotometry } from './checks';
import { convertTypeAB } from './convertTypeAB';
import { splitLines } from './decodeText';
import { expandTypeC, type ExpandedGrid } from './expandTypeC';
import { MAX_WATTS, SCALE_RANGE } from './limits';
import { PhotometryParseError } from './PhotometryParseError';
import { checkLeftovers, readAngles, readCandela } from './readGrid';
import { tiltFactorAt } from './tilt';
import type { Photometry, TiltTable } from './types';
import { luminousOpening, readIesHeader, readIesTilt } from './iesHeader';
import { readIesLuminaireValues, statedIesLumens, type IesLuminaireValues } from './iesLuminaireValues';
import type { NumberReader } from './numberReader';

export interface ParseIesOptions {
  /** Supplies the text of the file a `TILT=<file>` line names, or undefined. */
  resolveTilt?: (name: string) => string | undefined;
}

/**
 * Parses IES LM-63 text (1986, 1991, 1995, 2002, 2019 and the variants real
 * files use) into the expanded photometric model. Layout (LM-63-2002 §5):
 * optional version line, keyword lines up to `TILT=`, optional tilt data, then
 * a stream of numbers: 10 luminaire values, 3 ballast/watts values, vertical
 * angles, horizontal angles, candela values plane by plane.
 */
export function parseIes(text: string, fileName: string, options: ParseIesOptions = {}): Photometry {
  checkInputSize(fileName, text.length);
  const lines = splitLines(text);
  const warnings: string[] = [];

  const { version, keywords, freeText, tiltIndex } = readIesHeader(lines, fileName);
  const { reader, tilt } = readIesTilt(lines, tiltIndex, fileName, options.resolveTilt, warnings);
  const v = readIesLuminaireValues(reader, fileName, version, warnings);
  const { nV, nH, photometricType, unit, width, length, height, watts, absolute } = v;
  const { grid, scale, verticalAngles, horizontalAngles } = readIesGrid(reader, fileName, v, tilt, tiltIndex, warnings);
  const { statedLumens, statedLumensSource } = statedIesLumens(v, keywords, fileName, warnings);

  const manufacturer = keywords['MANUFAC'] ?? freeText[0] ?? '';
  const luminaire = keywords['LUMINAIRE'] ?? (keywords['MANUFAC'] === undefined ? freeText.slice(1) : freeText).filter((t) => !/^-+$/.test(t)).join(' / ');

  const ph: Photometry = {
    format: 'IES',
    version,
    manufacturer,
    luminaire,
    catalogNumber: keywords['LUMCAT'] ?? '',
    keywords,
    photometricType,
    symmetry: grid.symmetry,
    verticalAngles: grid.verticalAngles,
    horizontalAngles: grid.horizontalAngles,
    candela: grid.candela,
    statedLumens,
    statedLumensSource,
    absolute,
    inputWatts: watts > 0 && watts <= MAX_WATTS ? watts : null,
    luminousOpening: iesOpeningInLuminaireFrame(luminousOpening(width * unit, length * unit, height * unit)),
    warnings,
    tilt,
    fileGrid: {
      verticalCount: nV,
      horizontalCount: nH,
      verticalRange: [verticalAngles[0], verticalAngles[nV - 1]],
      horizontalRange: [horizontalAngles[0], horizontalAngles[nH - 1]],
    },
    candelaScale: scale,
  };
  return finishPhotometry(ph, fileName, absolute ? 'luminaire' : 'lamp');
}

/** Angles and candela values (LM-63-2002 §5.14–5.16), scaled and in ascending order, expanded to the model's grid. */
function readIesGrid(
  reader: NumberReader,
  fileName: string,
  v: IesLuminaireValues,
  tilt: TiltTable | null,
  tiltIndex: number,
  warnings: string[],
): { grid: ExpandedGrid; scale: number; verticalAngles: number[]; horizontalAngles: number[] } {
  const { nV, nH, photometricType, multiplier, ballastFactor, ballastLampFactor, modern, multiplierLine } = v;
  const typeC = photometricType === 'C';
  const vertical = readAngles(reader, fileName, nV, 'vertical angles', typeC ? 0 : -90, typeC ? 180 : 90, true);
  const horizontal = readAngles(reader, fileName, nH, 'horizontal angles', typeC ? 0 : -90, typeC ? 360 : 90, true);
  const verticalAngles = vertical.angles;
  const horizontalAngles = horizontal.angles;
  const anglesLine = reader.lastLine;
  const tiltAtZero = tilt ? tiltFactorAt(tilt, 0) : 1;
  // LM-63: every candela value is multiplied by the candela multiplier and the
  // ballast factor (and, before LM-63-2002, the ballast-lamp photometric factor);
  // TILT factors apply for the orientation the model is drawn in (tilt 0).
  const scale = multiplier * ballastFactor * (modern ? 1 : ballastLampFactor) * tiltAtZero;
  if (tilt && !(tiltAtZero > 0)) {
    throw new PhotometryParseError(fileName, tiltIndex + 1, `the TILT factor at tilt 0 is ${tiltAtZero}: every candela value would be 0`);
  }
  checkRange(fileName, multiplierLine, 'candela scale (multiplier × ballast factor × TILT factor)', scale, ...SCALE_RANGE);
  // Values are stored plane by plane in file order; a descending list is
  // reversed here together with its data (readAngles returned it ascending).
  const rowAngle = (p: number): number => horizontalAngles[horizontal.reversed ? nH - 1 - p : p];
  const colAngle = (i: number): number => verticalAngles[vertical.reversed ? nV - 1 - i : i];
  const candela = readCandela(
    reader,
    fileName,
    nH,
    nV,
    scale,
    (p) => `horizontal angle ${rowAngle(p)}`,
    (i) => `vertical angle ${colAngle(i)}`,
  );
  checkLeftovers(reader, fileName, nV, warnings);
  if (vertical.reversed) {
    for (const row of candela) row.reverse();
    warnings.push(`the ${nV} vertical angles are listed in descending order; read in ascending order with their values`);
  }
  if (horizontal.reversed) {
    candela.reverse();
    warnings.push(`the ${nH} horizontal angles are listed in descending order; read in ascending order with their planes`);
  }

  const grid: ExpandedGrid = typeC ? expandTypeC(fileName, { verticalAngles, horizontalAngles, candela }, anglesLine, warnings) : convertTypeAB(fileName, photometricType, { verticalAngles, horizontalAngles, candela }, anglesLine);
  return { grid, scale, verticalAngles, horizontalAngles };
}

/**
 * LM-63-2002 §5.10 names the opening's side along the 0°–180° photometric plane its *length* and
 * the side along 90°–270° its *width* (the example file of LM-63-1995, Ledalite's 251602SN, states
 * "[ALGN] 0 degree plane parallel to lamps" with a length of 4.04 ft for 4 ft T8 lamps; Radiance's
 * ies2rad also lays the length along x, the 0° direction). Photometry.luminousOpening uses
 * EULUMDAT's names instead (width b along C0–C180 = local x, length along C90–C270 = local z), so
 * the two sides swap here; a circle or a sphere is the same either way.
 */
function iesOpeningInLuminaireFrame(o: Photometry['luminousOpening']): Photometry['luminousOpening'] {
  return { ...o, width: o.length, length: o.width };
}
