/**
 * Caps on grid sizes. Real files stay far below them (the largest shared file,
 * 181 × 73, is 13 213 values; fine goniophotometer scans reach 0.1° steps,
 * 1801 vertical angles). A header that claims more is corrupt, and believing it
 * would allocate gigabytes, so the parser stops with an error that names the cap.
 */
export const MAX_VERTICAL_ANGLES = 3601;
export const MAX_HORIZONTAL_ANGLES = 3601;
export const MAX_CANDELA_VALUES = 2_000_000;
/** EULUMDAT allows 1–20 lamp sets. */
export const MAX_LAMP_SETS = 20;
/** Header lines before TILT= in an IES file (LM-63 keywords are a few dozen). */
export const MAX_IES_HEADER_LINES = 10_000;

/**
 * Largest photometric file read (issue 18). The largest real file is ~60 kB;
 * a full 0.1° goniophotometer scan at the value cap is ~15 MB of text only in
 * theory. Bigger input is refused before any parsing.
 */
export const MAX_PHOTOMETRY_BYTES = 10 * 1024 * 1024;

/**
 * Physical ranges every accepted value lies in, checked AFTER every scaling
 * step (docs/photometry.md, "Ranges"): a value outside is refused, never
 * clamped, and NaN/Infinity can never come out of a product of checked factors.
 */
export const MAX_CANDELA = 1e9; // brightest searchlights ~1e9 cd; stadium floods ~1e6
export const MIN_LUMENS = 1e-3;
export const MAX_LUMENS = 1e7; // largest real luminaire ~2e5 lm
export const MULTIPLIER_RANGE: readonly [number, number] = [1e-6, 1e6];
export const BALLAST_FACTOR_RANGE: readonly [number, number] = [1e-3, 10];
export const TILT_FACTOR_MAX = 100;
export const LDT_CONVERSION_FACTOR_RANGE: readonly [number, number] = [1e-6, 1e6];
/** Candela scale (multiplier × ballast factors × TILT, or LDT flux/1000 × factor). */
export const SCALE_RANGE: readonly [number, number] = [1e-12, 1e12];
export const MAX_LAMPS = 10_000;
/** Luminous opening and luminaire dimensions, metres (magnitude). */
export const MAX_DIMENSION_M = 1000;
export const MAX_WATTS = 1e6;
