/** Bytes as text: UTF-8 (ASCII files are the common case), a byte-order mark dropped, invalid sequences replaced (the line checks then name them). */
export function decodeText(bytes: Uint8Array): string {
  return new TextDecoder('utf-8', { fatal: false, ignoreBOM: false }).decode(bytes);
}
