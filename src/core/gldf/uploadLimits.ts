/**
 * Caps on an uploaded container (a GLDF product, later an L3D geometry): a zip is an upload, and
 * a zip bomb is a few kilobytes that claim gigabytes (docs/gldf.md, "Limits"). Every cap is
 * checked from the central directory before anything is inflated, and again while inflating
 * (an entry that inflates to more than its directory entry claims is refused at that point).
 */
export const UPLOAD_LIMITS = {
  /** Largest container file. The largest published GLDF examples are a few MB (images, L3D). */
  maxContainerBytes: 64 * 1024 * 1024,
  /** Most entries (files and folders) in one container; a product with every document and image has a few dozen. */
  maxEntries: 1000,
  /** Largest single entry, uncompressed: above the 10 MB photometry cap, room for a large image or L3D. */
  maxEntryBytes: 32 * 1024 * 1024,
  /** Largest sum of all entries, uncompressed. */
  maxTotalBytes: 128 * 1024 * 1024,
  /**
   * Largest compression ratio (uncompressed / compressed) of an entry over `ratioFloorBytes`:
   * text (XML, IES, EULUMDAT) deflates 3–20:1, a grid full of zeros up to ~100:1; a bomb's
   * entries run at deflate's maximum, ~1000:1.
   */
  maxRatio: 200,
  /** Entries smaller than this are not ratio-checked (a short run of spaces compresses 100:1 and harms no one). */
  ratioFloorBytes: 1024 * 1024,
  /** Longest entry name. */
  maxNameLength: 255,
  /** Largest product.xml (GLDF definitions with hundreds of variants stay under a few MB). */
  maxXmlBytes: 8 * 1024 * 1024,
  /** Deepest XML element nesting (the GLDF schema needs fewer than 15 levels). */
  maxXmlDepth: 40,
  /** Most elements of one name under one parent (variants, files, photometries…). */
  maxSiblings: 5000,
} as const;
