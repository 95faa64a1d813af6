import { InputError } from '../../core/inputError';

/** Quality settings of one bake (docs/baker.md, "Defaults"). */
export interface BakeSettings {
  /** Target texel edge, metres. */
  texelSize: number;
  /** Cap on texels per map edge (memory: 6 surfaces × ~11 RGBA32F maps). */
  maxTextureSize: number;
  /** Indirect samples per texel per bounce. */
  samples: number;
  /** Bounces computed explicitly; the rest of the series is estimated (see `tail`). */
  bounces: number;
  /** Samples gathered per draw call: keeps each GPU call short (browser watchdogs) and lets `step` refine per frame. */
  samplesPerDraw: number;
  /** Gaussian blur radius of the indirect maps, in texels (0 = none). */
  blurRadius: number;
  /** Add the geometric-series estimate of the bounces after `bounces`. */
  tail: boolean;
  /** Seed of the sample streams (same seed → same maps). */
  seed: number;
  /** Largest spacing of the point sources that replace a luminous opening, metres. */
  sourceSpacing: number;
  /** At most this many point sources along each side of an opening. */
  maxSourcesPerAxis: number;
  /**
   * Near field of a luminaire (docs/baker.md, "Luminous openings"): 'split' turns a
   * luminous opening larger than sourceSpacing into a grid of point sources, 'point'
   * keeps one point source per luminaire (Radiance ies2rad's point model). Unset:
   * the scene's own `nearField` (BakeScene), else 'split'.
   */
  nearField?: 'split' | 'point';
  /** At most this many bright tiles of the direct maps gathered exactly in bounce 1 (0 = pure Monte Carlo; docs/baker.md, "Bright patches"). */
  brightPatches: number;
  /**
   * Where the bright patches are chosen (docs/baker.md, "Bright patches selected on the GPU"): 'gpu'
   * (unset) ranks and compacts the tile sums on the GPU, no read-back; 'cpu' reads the tile sums back
   * and selects in JavaScript (selectBrightPatches.ts), kept for comparison.
   */
  brightSelection?: 'gpu' | 'cpu';
  /** Direct light as the mean over each texel: at most this many sub-samples per texel edge near sources (1 = texel centre only). */
  texelSupersampling: number;
  /** Wait for the GPU after each pass so timings_ms attributes time to passes (profiling; costs a pipeline stall per pass). */
  syncTimings: boolean;
  /**
   * Direct passes with the luminaires as uniforms instead of constants (docs/baker.md, "Lamps as
   * uniforms"): a program then depends only on the surface, the photometry and the source count,
   * so a moved luminaire compiles nothing. Unset or false: constants (the CLI's shaders). The
   * relight engine sets it for its direct bases.
   */
  lampUniforms?: boolean;
  /**
   * Candela lookup of the direct passes (docs/baker.md, "Profile table"): 'dense' (unset) the
   * profile resampled once onto a uniform grid, four fetches; 'measured' the file's own grid with
   * bin tables (about ten dependent fetches; kept to compare the two, e.g. `luxbox bench`).
   */
  profileLookup?: 'dense' | 'measured';
}

export const DEFAULT_BAKE_SETTINGS: BakeSettings = {
  texelSize: 0.025,
  maxTextureSize: 512,
  samples: 64,
  bounces: 4,
  samplesPerDraw: 16,
  blurRadius: 2,
  tail: true,
  seed: 1,
  sourceSpacing: 0.05,
  maxSourcesPerAxis: 8,
  brightPatches: 64,
  texelSupersampling: 8,
  syncTimings: false,
};

function check(ok: boolean, message: string): void {
  if (!ok) throw new InputError(message);
}

/** Settings resolveBakeSettings returned (frozen, so they stay checked). */
const RESOLVED = new WeakSet<object>();

/**
 * Defaults filled in and ranges checked (bad values are input errors, named by field). Resolve
 * once and pass the result on: settings this function returned come back as they are (frozen, so
 * nothing can have changed them since the check), so the CLI's early check (before any scene file
 * is read), the scene baker and the baker's `start` do the work once per bake, not three times.
 */
export function resolveBakeSettings(partial: Partial<BakeSettings> = {}): BakeSettings {
  if (RESOLVED.has(partial)) return partial as BakeSettings;
  const s: BakeSettings = { ...DEFAULT_BAKE_SETTINGS, ...Object.fromEntries(Object.entries(partial).filter(([, v]) => v !== undefined)) };
  check(Number.isFinite(s.texelSize) && s.texelSize >= 0.001 && s.texelSize <= 10, `texel size ${s.texelSize} m is outside 0.001..10 m`);
  check(Number.isInteger(s.maxTextureSize) && s.maxTextureSize >= 1 && s.maxTextureSize <= 4096, `maxTextureSize ${s.maxTextureSize} is not an integer in 1..4096`);
  check(Number.isInteger(s.samples) && s.samples >= 1 && s.samples <= 65536, `samples ${s.samples} is not an integer in 1..65536`);
  check(Number.isInteger(s.bounces) && s.bounces >= 0 && s.bounces <= 1000, `bounces ${s.bounces} is not an integer in 0..1000`);
  check(Number.isInteger(s.samplesPerDraw) && s.samplesPerDraw >= 1 && s.samplesPerDraw <= 4096, `samplesPerDraw ${s.samplesPerDraw} is not an integer in 1..4096`);
  check(Number.isInteger(s.blurRadius) && s.blurRadius >= 0 && s.blurRadius <= 64, `blurRadius ${s.blurRadius} is not an integer in 0..64`);
  check(Number.isInteger(s.seed) && s.seed >= 0, `seed ${s.seed} is not a non-negative integer`);
  check(Number.isFinite(s.sourceSpacing) && s.sourceSpacing >= 0, `sourceSpacing ${s.sourceSpacing} must be ≥ 0`);
  check(s.nearField === undefined || s.nearField === 'split' || s.nearField === 'point', `nearField "${String(s.nearField)}" is not split or point`);
  check(s.profileLookup === undefined || s.profileLookup === 'dense' || s.profileLookup === 'measured', `profileLookup ${String(s.profileLookup)} is not 'dense' or 'measured'`);
  check(s.lampUniforms === undefined || typeof s.lampUniforms === 'boolean', `lampUniforms ${String(s.lampUniforms)} is not true or false`);
  check(s.brightSelection === undefined || s.brightSelection === 'gpu' || s.brightSelection === 'cpu', `brightSelection ${String(s.brightSelection)} is not 'gpu' or 'cpu'`);
  check(Number.isInteger(s.brightPatches) && s.brightPatches >= 0 && s.brightPatches <= 1024, `brightPatches ${s.brightPatches} is not an integer in 0..1024`);
  check(Number.isInteger(s.texelSupersampling) && s.texelSupersampling >= 1 && s.texelSupersampling <= 32, `texelSupersampling ${s.texelSupersampling} is not an integer in 1..32`);
  check(Number.isInteger(s.maxSourcesPerAxis) && s.maxSourcesPerAxis >= 1 && s.maxSourcesPerAxis <= 64, `maxSourcesPerAxis ${s.maxSourcesPerAxis} is not an integer in 1..64`);
  Object.freeze(s);
  RESOLVED.add(s);
  return s;
}
