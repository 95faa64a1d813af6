/** The 10 + 3 luminaire values of an IES file (LM-63-2002 §5.12–5.13), checked, with what follows from them. */
import { checkRange } from './checks';
import { lumensFromText, checkCount } from './iesHeader';
import type { NumberReader } from './numberReader';
import { PhotometryParseError } from './PhotometryParseError';
import { BALLAST_FACTOR_RANGE, MAX_CANDELA_VALUES, MAX_DIMENSION_M, MAX_HORIZONTAL_ANGLES, MAX_LAMPS, MAX_LUMENS, MAX_VERTICAL_ANGLES, MAX_WATTS, MIN_LUMENS, MULTIPLIER_RANGE } from './limits';

const FEET_TO_METRES = 0.3048;

export interface IesLuminaireValues {
  readonly lamps: number;
  readonly lumensPerLamp: number;
  readonly multiplier: number;
  /** Vertical and horizontal angle counts. */
  readonly nV: number;
  readonly nH: number;
  readonly photometricType: 'A' | 'B' | 'C';
  /** Metres per unit of the file's dimensions. */
  readonly unit: number;
  readonly width: number;
  readonly length: number;
  readonly height: number;
  readonly ballastFactor: number;
  readonly ballastLampFactor: number;
  readonly watts: number;
  /** Absolute photometry (lumens per lamp −1). */
  readonly absolute: boolean;
  /** LM-63-2002 or later (the ballast-lamp factor is "future use"). */
  readonly modern: boolean;
  /** Lines of the candela multiplier and of lumens per lamp, for later messages. */
  readonly multiplierLine: number | null;
  readonly lumensLine: number | null;
}

export function readIesLuminaireValues(reader: NumberReader, fileName: string, version: string, warnings: string[]): IesLuminaireValues {
  const lamps = reader.next('the number of lamps');
  const lampsLine = reader.lastLine;
  const lumensPerLamp = reader.next('lumens per lamp');
  const lumensLine = reader.lastLine;
  const multiplier = reader.next('the candela multiplier');
  const multiplierLine = reader.lastLine;
  const nV = reader.next('the number of vertical angles');
  const nVLine = reader.lastLine;
  const nH = reader.next('the number of horizontal angles');
  const nHLine = reader.lastLine;
  const typeCode = reader.next('the photometric type');
  const typeLine = reader.lastLine;
  const units = reader.next('the units type');
  const unitsLine = reader.lastLine;
  const width = reader.next('the luminous opening width');
  const length = reader.next('the luminous opening length');
  const height = reader.next('the luminous opening height');
  const openingLine = reader.lastLine;
  const ballastFactor = reader.next('the ballast factor');
  const ballastLine = reader.lastLine;
  const ballastLampFactor = reader.next('the ballast-lamp photometric factor');
  const watts = reader.next('the input watts');

  if (!(multiplier > 0)) throw new PhotometryParseError(fileName, multiplierLine, `candela multiplier must be positive, found ${multiplier}`);
  if (!(ballastFactor > 0)) throw new PhotometryParseError(fileName, ballastLine, `ballast factor must be positive, found ${ballastFactor}`);
  checkRange(fileName, multiplierLine, 'candela multiplier', multiplier, ...MULTIPLIER_RANGE);
  checkRange(fileName, ballastLine, 'ballast factor', ballastFactor, ...BALLAST_FACTOR_RANGE);
  checkRange(fileName, lampsLine, 'number of lamps', lamps, -MAX_LAMPS, MAX_LAMPS);
  checkCount(fileName, nVLine, nV, 'vertical angles', 2, MAX_VERTICAL_ANGLES);
  checkCount(fileName, nHLine, nH, 'horizontal angles', 1, MAX_HORIZONTAL_ANGLES);
  if (nV * nH > MAX_CANDELA_VALUES) {
    throw new PhotometryParseError(fileName, nHLine, `${nV} × ${nH} candela values exceed the limit of ${MAX_CANDELA_VALUES}`);
  }
  const photometricType = ({ 1: 'C', 2: 'B', 3: 'A' } as const)[typeCode as 1 | 2 | 3];
  if (!photometricType) throw new PhotometryParseError(fileName, typeLine, `photometric type must be 1 (C), 2 (B) or 3 (A), found ${typeCode}`);
  if (units !== 1 && units !== 2) throw new PhotometryParseError(fileName, unitsLine, `units type must be 1 (feet) or 2 (metres), found ${units}`);
  const unit = units === 1 ? FEET_TO_METRES : 1;
  for (const [what, value] of [
    ['luminous opening width', width],
    ['luminous opening length', length],
    ['luminous opening height', height],
  ] as const) {
    checkRange(fileName, openingLine, `${what} (m)`, value * unit, -MAX_DIMENSION_M, MAX_DIMENSION_M);
  }
  if (!(lamps >= 1)) warnings.push(`number of lamps is ${lamps}; treated as 1`);
  const absolute = lumensPerLamp < 0;
  if (lumensPerLamp === 0 || (absolute && lumensPerLamp !== -1)) {
    warnings.push(`lumens per lamp is ${lumensPerLamp}; treated as absolute photometry`);
  }
  if (lumensPerLamp > 0) checkRange(fileName, lumensLine, 'lumens per lamp', lumensPerLamp, MIN_LUMENS, MAX_LUMENS);
  const modern = Number(version.slice(-4)) >= 2002;
  if (modern && ballastLampFactor !== 1) {
    warnings.push(`the "future use" field is ${ballastLampFactor} (LM-63-2002 and later: ignored)`);
  }
  if (!modern && !(ballastLampFactor > 0)) {
    throw new PhotometryParseError(fileName, ballastLine, `ballast-lamp photometric factor must be positive, found ${ballastLampFactor}`);
  }
  if (!modern) checkRange(fileName, ballastLine, 'ballast-lamp photometric factor', ballastLampFactor, ...BALLAST_FACTOR_RANGE);
  if (!(watts <= MAX_WATTS)) warnings.push(`input watts ${watts} exceed ${MAX_WATTS} W; ignored`);
  return { lamps, lumensPerLamp, multiplier, nV, nH, photometricType, unit, width, length, height, ballastFactor, ballastLampFactor, watts, absolute, modern, multiplierLine, lumensLine };
}

/** The lumens the file states: lamps × lumens per lamp × ballast factor (relative photometry), else [_ABSOLUTELUMENS] or the [LAMP] text. */
export function statedIesLumens(
  v: Pick<IesLuminaireValues, 'absolute' | 'lumensPerLamp' | 'lamps' | 'ballastFactor' | 'lumensLine'>,
  keywords: Record<string, string>,
  fileName: string,
  warnings: string[],
): { statedLumens: number | null; statedLumensSource: string | null } {
  const { absolute, lumensPerLamp, lamps, ballastFactor, lumensLine } = v;
  let statedLumens: number | null = null;
  let statedLumensSource: string | null = null;
  if (!absolute && lumensPerLamp > 0) {
    statedLumens = Math.max(1, lamps) * lumensPerLamp * ballastFactor;
    statedLumensSource = 'lamps × lumens per lamp × ballast factor (lamp lumens; relative photometry)';
    checkRange(fileName, lumensLine, 'stated lumens (lamps × lumens per lamp × ballast factor)', statedLumens, MIN_LUMENS, MAX_LUMENS);
  } else {
    const fromKeyword = lumensFromText(keywords['_ABSOLUTELUMENS'], false);
    const fromLamp = lumensFromText(keywords['LAMP'], true);
    for (const [source, value] of [
      ['[_ABSOLUTELUMENS]', fromKeyword],
      ['[LAMP] text', fromLamp],
    ] as const) {
      if (value === null) continue;
      if (!(value >= MIN_LUMENS && value <= MAX_LUMENS)) {
        warnings.push(`${source} states ${value} lm, out of range (${MIN_LUMENS} to ${MAX_LUMENS} lm); ignored`);
        continue;
      }
      statedLumens = value;
      statedLumensSource = source;
      break;
    }
  }
  return { statedLumens, statedLumensSource };
}
