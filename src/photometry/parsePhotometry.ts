import { decodeText } from './decodeText';
import { parseIes, type ParseIesOptions } from './parseIes';
import { parseLdt } from './parseLdt';
import type { Photometry } from './types';

export type ParsePhotometryOptions = ParseIesOptions;

/**
 * Parses an IES LM-63 or EULUMDAT file into the expanded photometric model.
 * The format comes from the extension (.ies / .ldt, any case); without one, a
 * file whose first lines contain "TILT=" or an "IES" version line is IES, else
 * EULUMDAT. Bytes are decoded as UTF-8, falling back to Latin-1.
 * Throws PhotometryParseError (an InputError) for anything unreadable.
 */
export function parsePhotometry(
  data: string | Uint8Array,
  fileName: string,
  options: ParsePhotometryOptions = {},
): Photometry {
  const text = decodeText(data);
  const ext = /\.([a-z0-9]+)$/i.exec(fileName)?.[1]?.toLowerCase();
  if (ext === 'ies') return parseIes(text, fileName, options);
  if (ext === 'ldt') return parseLdt(text, fileName);
  return looksLikeIes(text) ? parseIes(text, fileName, options) : parseLdt(text, fileName);
}

function looksLikeIes(text: string): boolean {
  const head = text.slice(0, 20_000);
  return /^\s*IES/i.test(head) || /^\s*TILT\s*=/im.test(head);
}
