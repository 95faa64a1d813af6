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

/** The pass's options for given bake settings. */
export function brightPatchOptions(settings: { brightPatches: number; brightSelection?: 'gpu' | 'cpu' }): BrightPatchOptions {
  return { maxPatches: settings.brightPatches, tileSize: BRIGHT_TILE_SIZE, targetPeakedness: 1, minContrast: 3, onGpu: settings.brightSelection !== 'cpu' };
}
