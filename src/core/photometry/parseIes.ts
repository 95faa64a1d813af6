import { checkInputSize, checkRange, finishPhotometry } from './checks';
import { convertTypeAB } from './convertTypeAB';
import { readDecimal } from './decimal';
import { splitLines } from './decodeText';
import { expandTypeC, type ExpandedGrid } from './expandTypeC';
import {
  BALLAST_FACTOR_RANGE,
  MAX_CANDELA_VALUES,
  MAX_DIMENSION_M,
  MAX_HORIZONTAL_ANGLES,
  MAX_IES_HEADER_LINES,
  MAX_LAMPS,
  MAX_LUMENS,
  MAX_VERTICAL_ANGLES,
  MAX_WATTS,
  MIN_LUMENS,
  MULTIPLIER_RANGE,
  SCALE_RANGE,
  TILT_FACTOR_MAX,
} from './limits';
import { NumberReader } from './numberReader';
import { excerpt, PhotometryParseError } from './PhotometryParseError';
import { checkLeftovers, readAngles, readCandela } from './readGrid';
import { tiltFactorAt } from './tilt';
import type { Photometry, TiltTable } from './types';

export interface ParseIesOptions {
  /** Supplies the text of the file a `TILT=<file>` line names, or undefined. */
  resolveTilt?: (name: string) => string | undefined;
}

const FEET_TO_METRES = 0.3048;

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

  // --- Version line.
  let start = 0;
  while (start < lines.length && lines[start].trim() === '') start++;
  if (start >= lines.length) throw new PhotometryParseError(fileName, null, 'the file is empty');
  const { version, hasVersionLine } = detectVersion(lines[start]);
  const headerStart = hasVersionLine ? start + 1 : start;

  // --- Keywords up to TILT=.
  let tiltIndex = -1;
  for (let i = headerStart; i < lines.length && i < headerStart + MAX_IES_HEADER_LINES; i++) {
    if (/^\s*TILT\s*=/i.test(lines[i])) {
      tiltIndex = i;
      break;
    }
  }
  if (tiltIndex < 0) {
    throw new PhotometryParseError(
      fileName,
      null,
      `no "TILT=" line found${lines.length > MAX_IES_HEADER_LINES ? ` in the first ${MAX_IES_HEADER_LINES} lines` : ''}: not an IES LM-63 file`,
    );
  }
  const { keywords, freeText } = readKeywords(lines.slice(headerStart, tiltIndex));

  // --- TILT.
  const tiltValue = lines[tiltIndex].slice(lines[tiltIndex].indexOf('=') + 1).trim();
  const reader = new NumberReader(fileName, lines.slice(tiltIndex + 1), tiltIndex + 2);
  let tilt: TiltTable | null = null;
  if (/^INCLUDE$/i.test(tiltValue)) {
    tilt = readTilt(reader, fileName, warnings);
  } else if (!/^NONE$/i.test(tiltValue)) {
    if (tiltValue === '') throw new PhotometryParseError(fileName, tiltIndex + 1, 'TILT= names no file (expected NONE, INCLUDE or a file name)');
    const supplied = options.resolveTilt?.(tiltValue);
    if (supplied === undefined) {
      throw new PhotometryParseError(
        fileName,
        tiltIndex + 1,
        `TILT=${excerpt(tiltValue, 60)} refers to a separate tilt file that was not supplied`,
      );
    }
    checkInputSize(tiltValue, supplied.length);
    tilt = readTilt(new NumberReader(tiltValue, splitLines(supplied), 1), tiltValue, warnings);
  }

  // --- The 10 + 3 luminaire values.
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

  // --- Angles and candela.
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

  const grid: ExpandedGrid = typeC
    ? expandTypeC(fileName, { verticalAngles, horizontalAngles, candela }, anglesLine, warnings)
    : convertTypeAB(fileName, photometricType, { verticalAngles, horizontalAngles, candela }, anglesLine);

  // --- Stated lumens.
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

  const manufacturer = keywords['MANUFAC'] ?? freeText[0] ?? '';
  const luminaire =
    keywords['LUMINAIRE'] ?? (keywords['MANUFAC'] === undefined ? freeText.slice(1) : freeText).filter((t) => !/^-+$/.test(t)).join(' / ');

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
    luminousOpening: luminousOpening(width * unit, length * unit, height * unit),
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

/**
 * Lumens stated in header text: the whole value of [_ABSOLUTELUMENS]
 * ("1221"), or in [LAMP] the number before "lm" ("LED 1221 lm"). Scanned by
 * hand, not by an unanchored regular expression, which is quadratic on long
 * digit runs. Null when there is none.
 */
function lumensFromText(text: string | undefined, beforeLm: boolean): number | null {
  if (text === undefined) return null;
  if (!beforeLm) {
    const read = readDecimal(text.trim());
    if (!read.ok) return read.problem === 'not a number' ? null : Infinity;
    return read.value > 0 ? read.value : null;
  }
  // Each "lm" not followed by a letter/digit: the numeral just before it (spaces allowed).
  const lower = text.toLowerCase();
  for (let at = lower.indexOf('lm'); at >= 0; at = lower.indexOf('lm', at + 2)) {
    if (/\w/.test(lower.charAt(at + 2))) continue;
    let end = at;
    while (end > 0 && /\s/.test(lower.charAt(end - 1))) end--;
    let start = end;
    while (start > 0 && /[\d.]/.test(lower.charAt(start - 1))) start--;
    if (start === end) continue;
    const read = readDecimal(text.slice(start, end));
    if (read.ok && read.value > 0) return read.value;
    if (!read.ok && read.problem !== 'not a number') return Infinity;
  }
  return null;
}

/**
 * The first line names the version: "IESNA:LM-63-1995", "IES:LM-63-2019",
 * "IESNA:LM-63-2002", and the older "IESNA91" (LM-63-1991; "IESNA95" also
 * occurs). LM-63-1986 files have no version line: their first line is text.
 */
function detectVersion(line: string): { version: string; hasVersionLine: boolean } {
  const t = line.trim();
  // "\s*(?::\s*)?" rather than "\s*:?\s*": two adjacent \s* backtrack
  // quadratically on a long run of spaces (issue 18).
  const full = /^IES(?:NA)?\s*(?::\s*)?LM-?63-(\d{4})\b/i.exec(t);
  if (full) return { version: `LM-63-${full[1]}`, hasVersionLine: true };
  const short = /^IESNA\s*(?::\s*)?(\d{2})$/i.exec(t);
  if (short) return { version: `LM-63-19${short[1]}`, hasVersionLine: true };
  return { version: 'LM-63-1986', hasVersionLine: false };
}

/**
 * `[KEY] value` lines. [MORE] continues the previous keyword (joined by a
 * space); a repeated keyword is joined the same way (some files repeat
 * [LUMINAIRE] instead of using [MORE]). Other lines are free text (the whole
 * header of an LM-63-1986 file).
 */
function readKeywords(lines: string[]): { keywords: Record<string, string>; freeText: string[] } {
  // Parts are collected and joined once at the end: joining as we go would
  // re-copy a keyword for every [MORE] line (quadratic on a huge header).
  const parts = new Map<string, string[]>();
  const freeText: string[] = [];
  let last: string | null = null;
  for (const raw of lines) {
    const line = raw.trim();
    if (line === '') continue;
    const close = line.indexOf(']');
    if (line.charCodeAt(0) !== 0x5b || close < 0) {
      freeText.push(line);
      continue;
    }
    const key = line.slice(1, close).trim().toUpperCase();
    const value = line.slice(close + 1).trim();
    const target: string = key === 'MORE' && last !== null ? last : key;
    const list = parts.get(target);
    if (!list) parts.set(target, [value]);
    else if (value !== '') list.push(value);
    last = target;
  }
  const keywords: Record<string, string> = {};
  for (const [key, list] of parts) keywords[key] = list.filter((v) => v !== '').join(' ');
  return { keywords, freeText };
}

/** TILT data (LM-63-2002 §5.7–5.11): geometry, count, angles, factors. */
function readTilt(reader: NumberReader, fileName: string, warnings: string[]): TiltTable {
  const geometry = reader.next('the lamp-to-luminaire geometry');
  if (geometry !== 1 && geometry !== 2 && geometry !== 3) {
    throw new PhotometryParseError(fileName, reader.lastLine, `lamp-to-luminaire geometry must be 1, 2 or 3, found ${geometry}`);
  }
  const count = reader.next('the number of tilt angles');
  checkCount(fileName, reader.lastLine, count, 'tilt angles', 1, MAX_VERTICAL_ANGLES);
  const { angles, reversed } = readAngles(reader, fileName, count, 'tilt angles', -180, 180, true);
  const factors: number[] = [];
  for (let i = 0; i < count; i++) {
    const f = reader.next('a tilt multiplying factor', { expected: count, found: i, plural: 'tilt multiplying factors' });
    if (f < 0) throw new PhotometryParseError(fileName, reader.lastLine, `negative tilt multiplying factor ${f}`);
    checkRange(fileName, reader.lastLine, 'tilt multiplying factor', f, 0, TILT_FACTOR_MAX);
    factors.push(f);
  }
  if (reversed) {
    factors.reverse();
    warnings.push(`the ${count} tilt angles are listed in descending order; read in ascending order with their factors`);
  }
  return { lampToLuminaireGeometry: geometry, angles, factors };
}

function checkCount(fileName: string, line: number, n: number, what: string, min: number, max: number): void {
  if (!Number.isInteger(n) || n < min) {
    throw new PhotometryParseError(fileName, line, `number of ${what} must be an integer ≥ ${min}, found ${n}`);
  }
  if (n > max) {
    throw new PhotometryParseError(fileName, line, `${n} ${what} exceed the limit of ${max}`);
  }
}

/**
 * LM-63-2002 Table 1: the signs of width, length and height encode the shape
 * of the luminous opening. Dimensions are returned as magnitudes in metres.
 */
export function luminousOpening(width: number, length: number, height: number): Photometry['luminousOpening'] {
  const w = Math.abs(width);
  const l = Math.abs(length);
  const h = Math.abs(height);
  let shape: Photometry['luminousOpening']['shape'];
  if (width === 0 && length === 0 && height === 0) shape = 'point';
  else if (width > 0 && length > 0 && height >= 0) shape = 'rectangular';
  else if (width < 0 && length < 0 && height < 0) shape = 'spherical';
  else if (width < 0 && height === 0 && (length === 0 || length === width)) shape = 'circular';
  else if (width < 0 && length < 0 && height === 0) shape = 'elliptical';
  else if ((width < 0 && height > 0) || (height > 0 && (width < 0 || length < 0))) shape = 'cylindrical';
  else shape = 'other';
  // A circle given by its width alone has that diameter in both directions.
  return { width: w, length: shape === 'circular' && l === 0 ? w : l, height: h, shape };
}
