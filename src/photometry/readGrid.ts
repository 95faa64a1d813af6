import type { NumberReader } from './numberReader';
import { PhotometryParseError } from './PhotometryParseError';

/**
 * Reads `count` strictly ascending angles within [min, max]. A value that does
 * not ascend usually means the count in the header is wrong (the next list has
 * started), so the message says both.
 */
export function readAngles(
  reader: NumberReader,
  fileName: string,
  count: number,
  plural: string,
  min: number,
  max: number,
): number[] {
  const angles: number[] = [];
  for (let i = 0; i < count; i++) {
    const value = reader.next(`a number (${plural.replace(/s$/, '')} ${i + 1} of ${count})`, {
      expected: count,
      found: i,
      plural,
    });
    if (value < min - 1e-6 || value > max + 1e-6) {
      throw new PhotometryParseError(fileName, reader.lastLine, `${plural.replace(/s$/, '')} ${value} is outside ${min}..${max}`);
    }
    if (i > 0 && value <= angles[i - 1]) {
      throw new PhotometryParseError(
        fileName,
        reader.lastLine,
        `expected ${count} ${plural}, found ${i} before ${value}, which does not ascend after ${angles[i - 1]} (the count in the header does not match the data, or the angles are out of order)`,
      );
    }
    angles.push(value);
  }
  return angles;
}

/**
 * Reads planes × perPlane candela values (plane by plane, as LM-63 and
 * EULUMDAT store them), each finite and ≥ 0, scaled by `scale`.
 */
export function readCandela(
  reader: NumberReader,
  fileName: string,
  planes: number,
  perPlane: number,
  scale: number,
  planeName: (plane: number) => string,
  angleName: (index: number) => string,
): number[][] {
  const total = planes * perPlane;
  const grid: number[][] = [];
  for (let p = 0; p < planes; p++) {
    const row: number[] = [];
    for (let i = 0; i < perPlane; i++) {
      const value = reader.next(`a candela value`, { expected: total, found: p * perPlane + i, plural: 'candela values' });
      if (value < 0) {
        throw new PhotometryParseError(
          fileName,
          reader.lastLine,
          `negative candela value ${value} at ${planeName(p)}, ${angleName(i)}`,
        );
      }
      row.push(value * scale);
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
  const rest = reader.rest();
  if (rest.length === 0) return;
  const numeric = rest.filter((t) => /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/.test(t.text)).length;
  if (numeric >= Math.max(perPlane, 2) && numeric === rest.length) {
    throw new PhotometryParseError(
      fileName,
      rest[0].line,
      `${numeric} numbers follow the candela table: the angle counts in the header do not match the data`,
    );
  }
  const shown = rest
    .slice(0, 3)
    .map((t) => (t.text.length > 16 ? t.text.slice(0, 16) + '…' : t.text))
    .join(' ');
  warnings.push(`ignored ${rest.length} trailing item(s) after the data from line ${rest[0].line} ("${shown}")`);
}
