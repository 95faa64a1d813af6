import { checkInputSize } from './checks';
import { decodeText, splitLines } from './decodeText';
import { parseIes, type ParseIesOptions } from './parseIes';
import { parseLdt } from './parseLdt';
import type { Photometry } from './types';

export type ParsePhotometryOptions = ParseIesOptions;

/**
 * Parses an IES LM-63 or EULUMDAT file into the expanded photometric model.
 * The format comes from the extension (.ies / .ldt, any case); without one, a
 * file whose first lines contain "TILT=" or an "IES" version line is IES, else
 * EULUMDAT. Bytes are decoded as UTF-8, falling back to Latin-1.
 * Throws PhotometryParseError (an InputError) for anything unreadable,
 * including input over MAX_PHOTOMETRY_BYTES (checked before decoding).
 * Non-fatal findings are in `warnings` (see photometryWarnings).
 */
export function parsePhotometry(data: string | Uint8Array, fileName: string, options: ParsePhotometryOptions = {}): Photometry {
  checkInputSize(fileName, typeof data === 'string' ? data.length : data.byteLength);
  const text = decodeText(data);
  const ext = /\.([a-z0-9]+)$/i.exec(fileName)?.[1]?.toLowerCase();
  if (ext === 'ies') return parseIes(text, fileName, options);
  if (ext === 'ldt') return parseLdt(text, fileName);
  return looksLikeIes(text) ? parseIes(text, fileName, options) : parseLdt(text, fileName);
}

function looksLikeIes(text: string): boolean {
  const head = text.slice(0, 20_000);
  // Line by line: a multiline /^\s*TILT/m backtracks quadratically over a run
  // of blank lines (\s* crosses line breaks from every line start).
  return /^\s*IES/i.test(head) || splitLines(head).some((line) => /^\s*TILT\s*=/i.test(line));
}
