/**
 * The one photometric model that both parsers (IES LM-63, EULUMDAT) produce.
 *
 * Frame (docs/scene-format.md "Units and frames"): IES type C. Vertical angle γ from the
 * nadir (0 = straight down along local −y, 180 = straight up); horizontal angle C
 * from local +x, counterclockwise seen from above (C=90 toward local −z). Type A
 * and B files are converted into this frame on load.
 *
 * The candela grid is stored *expanded*: symmetry already unfolded, multiplier,
 * ballast factor and TILT already applied, so `candela[h][v]` is the real
 * intensity in cd at (horizontalAngles[h], verticalAngles[v]).
 */
export interface Photometry {
  /** 'IES' or 'LDT' (EULUMDAT). */
  format: 'IES' | 'LDT';
  /** e.g. 'LM-63-1986', 'LM-63-1991', 'LM-63-1995', 'LM-63-2002', 'LM-63-2019', 'EULUMDAT'. */
  version: string;
  manufacturer: string;
  luminaire: string;
  catalogNumber: string;
  /** All header keywords (IES) or named header fields (LDT), [MORE] lines joined. */
  keywords: Record<string, string>;
  /** Photometric type of the source file before conversion. */
  photometricType: 'A' | 'B' | 'C';
  /** Symmetry of the source data. */
  symmetry: 'rotational' | 'quadrant' | 'bilateral-c0' | 'bilateral-c90' | 'none';
  /**
   * Vertical angles γ in degrees, strictly ascending, within [0, 180]. The grid
   * always spans 0..180: where the file measured less (e.g. 0..90), the parser
   * appends zero-intensity rows just beyond the measured range so interpolation
   * falls to zero there instead of smearing.
   */
  verticalAngles: number[];
  /**
   * Horizontal angles C in degrees, strictly ascending. Either exactly [0]
   * (rotationally symmetric: one plane holds for every C) or spanning 0..360
   * inclusive (the 360 plane equals the 0 plane) so lookups never wrap.
   */
  horizontalAngles: number[];
  /** candela[h][v], cd, finite and ≥ 0. */
  candela: number[][];
  /** Lumens the file states for the whole luminaire (lamps × lumens/lamp × multipliers where meaningful); null for absolute photometry with no stated value. */
  statedLumens: number | null;
  /** true when the file uses absolute photometry (IES lumens/lamp = −1). */
  absolute: boolean;
  /** Input watts as stated, or null. */
  inputWatts: number | null;
  /**
   * Luminous opening in metres (converted from feet where needed), magnitudes,
   * in the luminaire frame, under EULUMDAT's names: width along the C0–C180 axis
   * (local x), length along the C90–C270 axis (local z), height along y. LM-63-2002
   * §5.10 names the two sides the other way round (its length runs along 0°–180°),
   * so the IES parser swaps them (parseIes.ts, iesOpeningInLuminaireFrame); the
   * baker's point sources, the reference and the drawn models all read width as x.
   * `shape` follows LM-63-2002 Table 1 sign conventions (negative width =
   * circular/…) decoded into a name.
   */
  luminousOpening: { width: number; length: number; height: number; shape: 'point' | 'rectangular' | 'circular' | 'elliptical' | 'cylindrical' | 'spherical' | 'other' };
  /** Non-fatal problems found while reading (cap applied, lumens mismatch, …). */
  warnings: string[];
  /** Where statedLumens came from, in words (header lamp lumens, a keyword, LDT lamp flux × LOR). */
  statedLumensSource?: string | null;
  /**
   * IES TILT table (TILT=INCLUDE or a supplied TILT=<file>), or null. The grid
   * already carries the factor for tilt 0; see tiltFactorAt for others.
   */
  tilt?: TiltTable | null;
  /** Angle counts and ranges exactly as the file stores them, before expansion. */
  fileGrid?: {
    verticalCount: number;
    horizontalCount: number;
    verticalRange: [number, number];
    horizontalRange: [number, number];
  };
  /** Factor applied to the file's raw values to get cd (multiplier × ballast factor …, or LDT lamp flux / 1000). */
  candelaScale?: number;
}

/** LM-63 TILT data: lamp-to-luminaire geometry (1–3), tilt angles (deg) and multiplying factors. */
export interface TiltTable {
  lampToLuminaireGeometry: 1 | 2 | 3;
  angles: number[];
  factors: number[];
}
