/**
 * Decodes a photometric file's bytes. Files in the wild are UTF-8, ASCII or
 * Latin-1 (Windows-1252 degree signs, NBSP in catalogue numbers), with no
 * declaration of which. Strict UTF-8 is tried first; any invalid sequence means
 * the file is not UTF-8, and Latin-1 is used (the WHATWG "latin1" label is
 * Windows-1252, a superset for printable bytes; every byte maps to a character),
 * so decoding never fails and never inserts U+FFFD.
 */
export function decodeText(data: string | Uint8Array): string {
  let text: string;
  if (typeof data === 'string') {
    text = data;
  } else {
    try {
      text = new TextDecoder('utf-8', { fatal: true }).decode(data);
    } catch {
      text = new TextDecoder('latin1').decode(data);
    }
  }
  // A byte-order mark is not part of the first header line.
  return text.charCodeAt(0) === 0xfeff ? text.slice(1) : text;
}

/** Splits into lines on CRLF, LF or lone CR (old Mac files). */
export function splitLines(text: string): string[] {
  return text.split(/\r\n|\r|\n/);
}
