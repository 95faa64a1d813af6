/**
 * A message shown on its own starts with a capital (issue #27): the core words refusals and
 * problems as clauses ("the 240 W driver is full: …") so they read inside other sentences and on
 * the command line; the status line shows them as sentences. Locale-aware (the Turkish dotted İ).
 */
export function sentenceStart(text: string, locale: string): string {
  const first = text.codePointAt(0);
  if (first === undefined) return text;
  const head = String.fromCodePoint(first);
  return head.toLocaleUpperCase(locale) + text.slice(head.length);
}
