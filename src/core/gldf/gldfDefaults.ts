/** What the GLDF import assumes and how it names things; the export (exportGldfProduct.ts) reads the same rules to round-trip. */

/** Defaults for what neither the GLDF nor the mapping gives (docs/gldf.md, "Defaults"). */
export const GLDF_DEFAULTS = {
  /** Rail length a module occupies when the GLDF has no ProductSize: the demo catalog's spot. */
  length: 0.15,
  /** Price when neither the mapping nor a ListPrice in the catalog's currency gives one. */
  price: 0,
  roll: 0,
  /** CCT of a light source that states none. */
  cct: 3000,
  /** Aiming ranges of an adjustable head (GLDF Adjustability Tilt/Turn/Cardanic): the demo spot's. */
  tilt: { min: 0, max: 90 },
  rotation: { min: 0, max: 355 },
} as const;

/** A catalog id from a GLDF id or number: lower case, runs of other characters as '-'. */
export function catalogSlug(value: string): string {
  const s = value
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-+|-+$/g, '')
    .slice(0, 64)
    .replace(/-+$/, '');
  return s || 'product';
}

/** The longest common prefix of the beam's article numbers, trimmed at a separator ('LX-TS-N15-30', 'LX-TS-N15-40' → 'LX-TS-N15'). */
export function commonArticle(numbers: string[]): string {
  if (numbers.length < 2) return '';
  // Cut first: a hostile file's product numbers may be megabytes long.
  let prefix = numbers[0].slice(0, 100);
  for (const n of numbers) while (!n.startsWith(prefix)) prefix = prefix.slice(0, -1);
  return prefix.replace(/[-_./ ]+$/, '');
}
