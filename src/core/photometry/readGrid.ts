import { MAX_CANDELA } from './limits';
import type { NumberReader } from './numberReader';
import { excerpt, PhotometryParseError } from './PhotometryParseError';

/** Angles read from a file, ascending; `reversed` when the file listed them descending. */
export interface AngleList {
  angles: number[];
  reversed: boolean;
}

/**
 * Reads `count` strictly monotonic angles within [min, max]. A value that does
 * not ascend usually means the count in the header is wrong (the next list has
 * started), so the message says both. With `allowDescending`, a list that is
 * strictly descending from its first two values to its end (an exporter that
 * writes 180 … 0) is returned reversed with `reversed: true`: the caller
 * reverses the data with it and warns. Anything else out of order is refused.
 */
export function readAngles(reader: NumberReader, fileName: string, count: number, plural: string, min: number, max: number, allowDescending = false): AngleList {
  const singular = plural.replace(/s$/, '');
  const angles: number[] = [];
  let descending = false;
  for (let i = 0; i < count; i++) {
    const value = reader.next(`a number (${singular} ${i + 1} of ${count})`, {
      expected: count,
      found: i,
      plural,
    });
    if (value < min - 1e-6 || value > max + 1e-6) {
      throw new PhotometryParseError(fileName, reader.lastLine, `${singular} ${value} is outside ${min}..${max}`);
    }
    if (i === 1 && allowDescending && value < angles[0]) descending = true;
    if (i > 0 && !descending && value <= angles[i - 1]) {
      throw new PhotometryParseError(
        fileName,
        reader.lastLine,
        `expected ${count} ${plural}, found ${i} before ${value}, which does not ascend after ${angles[i - 1]} (the count in the header does not match the data, or the angles are out of order)`,
      );
    }
    if (i > 0 && descending && value >= angles[i - 1]) {
      throw new PhotometryParseError(
        fileName,
        reader.lastLine,
        `expected ${count} ${plural}, found ${i} before ${value}, which breaks the descending order after ${angles[i - 1]} (the count in the header does not match the data, or the angles are out of order)`,
      );
    }
    angles.push(value);
  }
  if (descending) angles.reverse();
  return { angles, reversed: descending };
}

/**
 * Reads planes × perPlane candela values (plane by plane, as LM-63 and
 * EULUMDAT store them), each finite and ≥ 0, scaled by `scale`. The range is
 * checked on the scaled value (issue 18: a valid value × a huge multiplier is
 * Infinity), so every stored value is in [0, MAX_CANDELA].
 */
export function readCandela(reader: NumberReader, fileName: string, planes: number, perPlane: number, scale: number, planeName: (plane: number) => string, angleName: (index: number) => string): number[][] {
  const total = planes * perPlane;
  const grid: number[][] = [];
  for (let p = 0; p < planes; p++) {
    const row: number[] = [];
    for (let i = 0; i < perPlane; i++) {
      const value = reader.next(`a candela value`, { expected: total, found: p * perPlane + i, plural: 'candela values' });
      if (value < 0) {
        throw new PhotometryParseError(fileName, reader.lastLine, `negative candela value ${value} at ${planeName(p)}, ${angleName(i)}`);
      }
      const cd = value * scale;
      if (!(cd <= MAX_CANDELA)) {
        throw new PhotometryParseError(fileName, reader.lastLine, `candela value ${value} × scale ${scale} at ${planeName(p)}, ${angleName(i)} exceeds ${MAX_CANDELA} cd`);
      }
      row.push(cd);
    }
    grid.push(row);
  }
  return grid;
}

/**
 * What is left after the data. A few tokens are junk real files carry ("END",
 * a signature); a whole plane's worth or more of numbers means the header's
 * counts are too small for the data, which would silently drop measurements.
 */
export function checkLeftovers(reader: NumberReader, fileName: string, perPlane: number, warnings: string[]): void {
  const { count, numeric, first } = reader.leftovers();
  if (count === 0) return;
  if (numeric >= Math.max(perPlane, 2) && numeric === count) {
    throw new PhotometryParseError(fileName, first[0].line, `${numeric} numbers follow the candela table: the angle counts in the header do not match the data`);
  }
  const shown = first.map((t) => excerpt(t.text, 16)).join(' ');
  warnings.push(`ignored ${count} trailing item(s) after the data from line ${first[0].line} ("${shown}")`);
}
