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
