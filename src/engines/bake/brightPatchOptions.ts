/** Tile size of the bright-patch search, metres (about the reference's patch size; at least one texel). */
export const BRIGHT_TILE_SIZE = 0.1;

/** How the bright-patch pass picks its tiles (selectBrightPatches.ts, docs/baker.md "Stiff scenes: bright patches"). */
export interface BrightPatchOptions {
  /** At most this many patches (0: none, pure Monte Carlo bounce 1). */
  maxPatches: number;
  /** Tile edge, metres. */
  tileSize: number;
  /** Stop once the residual's peakedness is at most this. */
  targetPeakedness: number;
  /** Only tiles whose mean exitance is at least this × the room's mean. */
  minContrast: number;
  /** Select on the GPU (selectBrightPatchesOnGpu.ts, no read-back) rather than on the CPU (selectBrightPatches.ts). */
  onGpu: boolean;
}

/**
 * Contrast of a candidate where the candidates are the atlas's charts (a room of any shape, whose
 * box surfaces are black sinks: docs/baker.md "Rooms of any shape"). Taking a tile out of the
 * Monte Carlo gather lowers its variance only where the tile is much brighter than what the
 * receivers see on average: a sample either hits the tile (exitance c, probability p) or the rest
 * (X_r), so Var(all) = Var(rest) + c²p(1 − p) − 2·c·p·E[X_r], and removing the tile raises the
 * variance while c(1 − p) < 2·E[X_r]. Under downlights the walls and the ceiling see mostly the lit
 * floor, so E[X_r] is far above the room's area mean and the floor's pools at 3× that mean made
 * the L of the accuracy tests worse (1.14 → 1.27 % RMS at 64 samples, seeds 1–3 alike), while the
 * attic's spot on its slope (~200× the mean) is the case the patches exist for. Measured
 * (shapedRoomVsReference.test.ts scenes, 0.1 m, 64 samples): contrast 3: L 1.27 %, attic 1.51 %;
 * 10: L 1.14 % (no patch), attic 1.35 %; 30: L 1.14 %, attic 1.60 % (22 patches).
 */
export const CHART_MIN_CONTRAST = 10;

/**
 * Where the patches are chosen: as the settings say, and unset on the GPU except on a software
 * renderer (softwareRenderer.ts). There the GPU selection's passes, and the residual copy and bright
 * gather it must run on every surface because the CPU does not know which hold patches, cost more
 * than the read-back they save, which on a software rasteriser is a memcpy with no pipeline to
 * wait for: measured 0.98–1.19× the CPU path's whole bakes on llvmpipe (docs/benchmarks.md
 * "Bright patches selected on the GPU").
 */
export function selectOnGpu(brightSelection: 'gpu' | 'cpu' | undefined, softwareGl: boolean): boolean {
  return brightSelection === undefined ? !softwareGl : brightSelection === 'gpu';
}

/**
 * The pass's options for given bake settings; `charts`: the candidates are the atlas's charts (a
 * room of any shape); `softwareGl`: the context draws on the CPU (selectOnGpu).
 */
export function brightPatchOptions(settings: { brightPatches: number; brightSelection?: 'gpu' | 'cpu' }, charts = false, softwareGl = false): BrightPatchOptions {
  return {
    maxPatches: settings.brightPatches,
    tileSize: BRIGHT_TILE_SIZE,
    targetPeakedness: 1,
    minContrast: charts ? CHART_MIN_CONTRAST : 3,
    onGpu: selectOnGpu(settings.brightSelection, softwareGl),
  };
}
