import { convertTypeAB } from './convertTypeAB';
import { splitLines } from './decodeText';
import { expandTypeC, type ExpandedGrid } from './expandTypeC';
import { MAX_CANDELA_VALUES, MAX_HORIZONTAL_ANGLES, MAX_IES_HEADER_LINES, MAX_VERTICAL_ANGLES } from './limits';
import { NumberReader } from './numberReader';
import { PhotometryParseError } from './PhotometryParseError';
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
  const tiltValue = lines[tiltIndex].replace(/^\s*TILT\s*=/i, '').trim();
  const reader = new NumberReader(fileName, lines.slice(tiltIndex + 1), tiltIndex + 2);
  let tilt: TiltTable | null = null;
  if (/^INCLUDE$/i.test(tiltValue)) {
    tilt = readTilt(reader, fileName);
  } else if (!/^NONE$/i.test(tiltValue)) {
    if (tiltValue === '') throw new PhotometryParseError(fileName, tiltIndex + 1, 'TILT= names no file (expected NONE, INCLUDE or a file name)');
    const supplied = options.resolveTilt?.(tiltValue);
    if (supplied === undefined) {
      throw new PhotometryParseError(
        fileName,
        tiltIndex + 1,
        `TILT=${tiltValue} refers to a separate tilt file that was not supplied`,
      );
    }
    tilt = readTilt(new NumberReader(tiltValue, splitLines(supplied), 1), tiltValue);
  }

  // --- The 10 + 3 luminaire values.
  const lamps = reader.next('the number of lamps');
  const lumensPerLamp = reader.next('lumens per lamp');
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
  const ballastFactor = reader.next('the ballast factor');
  const ballastLine = reader.lastLine;
  const ballastLampFactor = reader.next('the ballast-lamp photometric factor');
  const watts = reader.next('the input watts');

  if (!(multiplier > 0)) throw new PhotometryParseError(fileName, multiplierLine, `candela multiplier must be positive, found ${multiplier}`);
  if (!(ballastFactor > 0)) throw new PhotometryParseError(fileName, ballastLine, `ballast factor must be positive, found ${ballastFactor}`);
  checkCount(fileName, nVLine, nV, 'vertical angles', 2, MAX_VERTICAL_ANGLES);
  checkCount(fileName, nHLine, nH, 'horizontal angles', 1, MAX_HORIZONTAL_ANGLES);
  if (nV * nH > MAX_CANDELA_VALUES) {
    throw new PhotometryParseError(fileName, nHLine, `${nV} × ${nH} candela values exceed the limit of ${MAX_CANDELA_VALUES}`);
  }
  const photometricType = ({ 1: 'C', 2: 'B', 3: 'A' } as const)[typeCode as 1 | 2 | 3];
  if (!photometricType) throw new PhotometryParseError(fileName, typeLine, `photometric type must be 1 (C), 2 (B) or 3 (A), found ${typeCode}`);
  if (units !== 1 && units !== 2) throw new PhotometryParseError(fileName, unitsLine, `units type must be 1 (feet) or 2 (metres), found ${units}`);
  if (!(lamps >= 1)) warnings.push(`number of lamps is ${lamps}; treated as 1`);
  const absolute = lumensPerLamp < 0;
  if (lumensPerLamp === 0 || (absolute && lumensPerLamp !== -1)) {
    warnings.push(`lumens per lamp is ${lumensPerLamp}; treated as absolute photometry`);
  }
  const modern = Number(version.slice(-4)) >= 2002;
  if (modern && ballastLampFactor !== 1) {
    warnings.push(`the "future use" field is ${ballastLampFactor} (LM-63-2002 and later: ignored)`);
  }
  if (!modern && !(ballastLampFactor > 0)) {
    throw new PhotometryParseError(fileName, ballastLine, `ballast-lamp photometric factor must be positive, found ${ballastLampFactor}`);
  }

  // --- Angles and candela.
  const typeC = photometricType === 'C';
  const verticalAngles = readAngles(reader, fileName, nV, 'vertical angles', typeC ? 0 : -90, typeC ? 180 : 90);
  const horizontalAngles = readAngles(reader, fileName, nH, 'horizontal angles', typeC ? 0 : -90, typeC ? 360 : 90);
  const anglesLine = reader.lastLine;
  const tiltAtZero = tilt ? tiltFactorAt(tilt, 0) : 1;
  // LM-63: every candela value is multiplied by the candela multiplier and the
  // ballast factor (and, before LM-63-2002, the ballast-lamp photometric factor);
  // TILT factors apply for the orientation the model is drawn in (tilt 0).
  const scale = multiplier * ballastFactor * (modern ? 1 : ballastLampFactor) * tiltAtZero;
  const candela = readCandela(
    reader,
    fileName,
    nH,
    nV,
    scale,
    (p) => `horizontal angle ${horizontalAngles[p]}`,
    (i) => `vertical angle ${verticalAngles[i]}`,
  );
  checkLeftovers(reader, fileName, nV, warnings);

  const grid: ExpandedGrid = typeC
    ? expandTypeC(fileName, { verticalAngles, horizontalAngles, candela }, anglesLine)
    : convertTypeAB(fileName, photometricType, { verticalAngles, horizontalAngles, candela }, anglesLine);

  // --- Stated lumens.
  let statedLumens: number | null = null;
  let statedLumensSource: string | null = null;
  if (!absolute && lumensPerLamp > 0) {
    statedLumens = Math.max(1, lamps) * lumensPerLamp * ballastFactor;
    statedLumensSource = 'lamps × lumens per lamp × ballast factor (lamp lumens; relative photometry)';
  } else {
    const keyword = keywords['_ABSOLUTELUMENS'];
    const fromKeyword = keyword !== undefined && /^\s*\d+(\.\d+)?\s*$/.test(keyword) ? Number(keyword) : NaN;
    const lampMatch = /(\d+(?:\.\d+)?)\s*lm\b/i.exec(keywords['LAMP'] ?? '');
    if (fromKeyword > 0) {
      statedLumens = fromKeyword;
      statedLumensSource = '[_ABSOLUTELUMENS]';
    } else if (lampMatch && Number(lampMatch[1]) > 0) {
      statedLumens = Number(lampMatch[1]);
      statedLumensSource = '[LAMP] text';
    }
  }

  const unit = units === 1 ? FEET_TO_METRES : 1;
  const manufacturer = keywords['MANUFAC'] ?? freeText[0] ?? '';
  const luminaire =
    keywords['LUMINAIRE'] ?? (keywords['MANUFAC'] === undefined ? freeText.slice(1) : freeText).filter((t) => !/^-+$/.test(t)).join(' / ');

  return {
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
    inputWatts: watts > 0 ? watts : null,
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
}

/**
 * The first line names the version: "IESNA:LM-63-1995", "IES:LM-63-2019",
 * "IESNA:LM-63-2002", and the older "IESNA91" (LM-63-1991; "IESNA95" also
 * occurs). LM-63-1986 files have no version line: their first line is text.
 */
function detectVersion(line: string): { version: string; hasVersionLine: boolean } {
  const t = line.trim();
  const full = /^IES(?:NA)?\s*:?\s*LM-?63-(\d{4})\b/i.exec(t);
  if (full) return { version: `LM-63-${full[1]}`, hasVersionLine: true };
  const short = /^IESNA\s*:?\s*(\d{2})\s*$/i.exec(t);
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
  const keywords: Record<string, string> = {};
  const freeText: string[] = [];
  let last: string | null = null;
  for (const raw of lines) {
    const line = raw.trim();
    if (line === '') continue;
    const match = /^\[([^\]]*)\]\s*(.*)$/.exec(line);
    if (!match) {
      freeText.push(line);
      continue;
    }
    const key = match[1].trim().toUpperCase();
    const value = match[2].trim();
    const target: string = key === 'MORE' && last !== null ? last : key;
    keywords[target] = keywords[target] !== undefined && keywords[target] !== '' ? `${keywords[target]} ${value}`.trim() : value;
    last = target;
  }
  return { keywords, freeText };
}

/** TILT data (LM-63-2002 §5.7–5.11): geometry, count, angles, factors. */
function readTilt(reader: NumberReader, fileName: string): TiltTable {
  const geometry = reader.next('the lamp-to-luminaire geometry');
  if (geometry !== 1 && geometry !== 2 && geometry !== 3) {
    throw new PhotometryParseError(fileName, reader.lastLine, `lamp-to-luminaire geometry must be 1, 2 or 3, found ${geometry}`);
  }
  const count = reader.next('the number of tilt angles');
  checkCount(fileName, reader.lastLine, count, 'tilt angles', 1, MAX_VERTICAL_ANGLES);
  const angles = readAngles(reader, fileName, count, 'tilt angles', -180, 180);
  const factors: number[] = [];
  for (let i = 0; i < count; i++) {
    const f = reader.next('a tilt multiplying factor', { expected: count, found: i, plural: 'tilt multiplying factors' });
    if (f < 0) throw new PhotometryParseError(fileName, reader.lastLine, `negative tilt multiplying factor ${f}`);
    factors.push(f);
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
