/** The IES file's header: version line, keywords, lumens in text, tilt data, the luminous opening (LM-63-2002 §5). */
import { checkRange } from './checks';
import { readDecimal } from './decimal';
import { MAX_VERTICAL_ANGLES, TILT_FACTOR_MAX } from './limits';
import { NumberReader } from './numberReader';
import { PhotometryParseError } from './PhotometryParseError';
import { readAngles } from './readGrid';
import type { Photometry, TiltTable } from './types';
import { checkInputSize } from './checks';
import { splitLines } from './decodeText';
import { excerpt } from './PhotometryParseError';
import { MAX_IES_HEADER_LINES } from './limits';

/**
 * Lumens stated in header text: the whole value of [_ABSOLUTELUMENS]
 * ("1221"), or in [LAMP] the number before "lm" ("LED 1221 lm"). Scanned by
 * hand, not by an unanchored regular expression, which is quadratic on long
 * digit runs. Null when there is none.
 */
export function lumensFromText(text: string | undefined, beforeLm: boolean): number | null {
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
export function detectVersion(line: string): { version: string; hasVersionLine: boolean } {
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
export function readKeywords(lines: string[]): { keywords: Record<string, string>; freeText: string[] } {
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
export function readTilt(reader: NumberReader, fileName: string, warnings: string[]): TiltTable {
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

export function checkCount(fileName: string, line: number, n: number, what: string, min: number, max: number): void {
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

/** The version line, the keyword lines up to `TILT=`, and where that line is (LM-63-2002 §5.1–5.6). */
export function readIesHeader(lines: string[], fileName: string): { version: string; keywords: Record<string, string>; freeText: string[]; tiltIndex: number } {
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
    throw new PhotometryParseError(fileName, null, `no "TILT=" line found${lines.length > MAX_IES_HEADER_LINES ? ` in the first ${MAX_IES_HEADER_LINES} lines` : ''}: not an IES LM-63 file`);
  }
  const { keywords, freeText } = readKeywords(lines.slice(headerStart, tiltIndex));
  return { version, keywords, freeText, tiltIndex };
}

/**
 * The `TILT=` line: NONE, INCLUDE (the tilt data follow it) or the name of a separate tilt file that
 * `resolveTilt` supplies. Returns the tilt table and the reader of the numbers after the line.
 */
export function readIesTilt(lines: string[], tiltIndex: number, fileName: string, resolveTilt: ((name: string) => string | undefined) | undefined, warnings: string[]): { reader: NumberReader; tilt: TiltTable | null } {
  // --- TILT.
  const tiltValue = lines[tiltIndex].slice(lines[tiltIndex].indexOf('=') + 1).trim();
  const reader = new NumberReader(fileName, lines.slice(tiltIndex + 1), tiltIndex + 2);
  let tilt: TiltTable | null = null;
  if (/^INCLUDE$/i.test(tiltValue)) {
    tilt = readTilt(reader, fileName, warnings);
  } else if (!/^NONE$/i.test(tiltValue)) {
    if (tiltValue === '') throw new PhotometryParseError(fileName, tiltIndex + 1, 'TILT= names no file (expected NONE, INCLUDE or a file name)');
    const supplied = resolveTilt?.(tiltValue);
    if (supplied === undefined) {
      throw new PhotometryParseError(fileName, tiltIndex + 1, `TILT=${excerpt(tiltValue, 60)} refers to a separate tilt file that was not supplied`);
    }
    checkInputSize(tiltValue, supplied.length);
    tilt = readTilt(new NumberReader(tiltValue, splitLines(supplied), 1), tiltValue, warnings);
  }
  return { reader, tilt };
}
