/** A named benchmark scene: a lighting scene file in tests/fixtures/bench and how finely to check it. */
export interface BenchScene {
  name: string;
  /** Path relative to the repository root. */
  file: string;
  description: string;
  /** Patch edge of the converged CPU reference, metres. */
  referencePatch: number;
  /** Spacing of the comparison points on every surface, metres. */
  sampleSpacing: number;
  /** A coarser reference patch (metres) solved too, to show how far the reference has converged (stiff scenes). */
  referenceCheckPatch?: number;
  /** Stiff scene (issue #8): both methods are run over the stiff ladder. */
  stiff?: boolean;
}

/**
 * How the indirect light and the probe values are computed:
 * - 'monte-carlo': the method before issue #8 — texel-centre direct maps, every
 *   bounce by cosine-sampled Monte Carlo, probe reads direct light from the maps;
 * - 'bright-patches' (today's default): texel-mean direct maps, bounce 1 from the
 *   brightest tiles by exact form factors, probe evaluates direct light at the point.
 */
export type BenchMethod = 'monte-carlo' | 'bright-patches';
export const METHOD_SETTINGS: Record<BenchMethod, { brightPatches?: number; texelSupersampling?: number }> = {
  'monte-carlo': { brightPatches: 0, texelSupersampling: 1 },
  'bright-patches': {},
};

/** Quality settings of one rung of the ladder (the CLI's --texel, --samples, --bounces). */
export interface BenchQuality {
  texelSize: number;
  samples: number;
  bounces: number;
}

export const BENCH_SCENES: readonly BenchScene[] = [
  {
    name: 'cie-cube',
    file: 'tests/fixtures/bench/cie-cube.json',
    description: 'CIE 171:2006 case 5.8: 4 × 4 × 4 m, ρ = 0.8, isotropic 10 000 lm at the centre',
    referencePatch: 0.2,
    sampleSpacing: 0.25,
  },
  {
    name: 'living-room',
    file: 'tests/fixtures/bench/living-room.json',
    description: 'empty living room 5 × 4 × 2.7 m, 10 real IES/LDT modules (downlights, pendant, track spots, wall light, spot, washer), RGB east wall',
    referencePatch: 0.15,
    sampleSpacing: 0.25,
  },
  {
    name: 'corridor',
    file: 'tests/fixtures/bench/corridor.json',
    description: 'corridor 20 × 3 × 2.5 m, a row of 8 linear recessed LED luminaires (RAB BOA2)',
    referencePatch: 0.25,
    sampleSpacing: 0.4,
  },
];

/** Stiff scenes (issue #8): light concentrated in small, very bright regions near a surface. */
export const STIFF_SCENES: readonly BenchScene[] = [
  {
    name: 'spot-wall',
    file: 'tests/fixtures/bench/spot-wall.json',
    description: 'issue #8 (a): 4 × 2.6 × 3.5 m, ρ 0.3–0.85, a narrow spot (BEGA 84693) 25 cm from the north wall aimed at it, one downlight',
    referencePatch: 0.1,
    referenceCheckPatch: 0.2,
    sampleSpacing: 0.25,
    stiff: true,
  },
  {
    name: 'uplight-corridor',
    file: 'tests/fixtures/bench/uplight-corridor.json',
    description: 'issue #8 (b): corridor 20 × 3 × 2.5 m, 8 ceiling luminaires with an up-light component (Cooper Shaper, 13 cm tall) hung 5 cm under a ρ = 0.85 ceiling',
    referencePatch: 0.125,
    referenceCheckPatch: 0.25,
    sampleSpacing: 0.4,
    stiff: true,
  },
  {
    name: 'ceiling-uplight',
    file: 'tests/fixtures/bench/ceiling-uplight.json',
    description: '4 × 2.7 × 3 m, two pure up-lights (ERCO Trion) 3 and 8 cm under a ρ = 0.9 ceiling',
    referencePatch: 0.1,
    referenceCheckPatch: 0.2,
    sampleSpacing: 0.25,
    stiff: true,
  },
  {
    name: 'wall-washer',
    file: 'tests/fixtures/bench/wall-washer.json',
    description: '5 × 2.7 × 4 m, three track spots 30 cm from a ρ = 0.95 wall, pitched 40° onto it (wall washing), ceiling ρ = 0.9',
    referencePatch: 0.1,
    referenceCheckPatch: 0.2,
    sampleSpacing: 0.25,
    stiff: true,
  },
];

/** Stiff scenes: both methods at these rungs (the last is the default), and the old method with 4× the samples. */
export const STIFF_LADDER: readonly BenchQuality[] = [
  { texelSize: 0.1, samples: 64, bounces: 4 },
  { texelSize: 0.05, samples: 64, bounces: 4 },
  { texelSize: 0.025, samples: 64, bounces: 4 },
];
export const STIFF_EXTRA_OLD: readonly BenchQuality[] = [{ texelSize: 0.025, samples: 256, bounces: 4 }];

/** The baker's default quality (DEFAULT_BAKE_SETTINGS), where the smooth scenes also run the old method. */
export const DEFAULT_QUALITY: BenchQuality = { texelSize: 0.025, samples: 64, bounces: 4 };

/** From coarse and fast to fine and slow; the fourth rung is the baker's default. */
export const QUALITY_LADDER: readonly BenchQuality[] = [
  { texelSize: 0.1, samples: 16, bounces: 2 },
  { texelSize: 0.1, samples: 64, bounces: 4 },
  { texelSize: 0.05, samples: 64, bounces: 4 },
  { texelSize: 0.025, samples: 64, bounces: 4 },
  { texelSize: 0.05, samples: 256, bounces: 8 },
];

/** `--quick`: one small scene, two cheap rungs, coarse reference — a smoke run of the machinery. */
export const QUICK_SCENES: readonly BenchScene[] = [{ ...BENCH_SCENES[0], referencePatch: 0.5, sampleSpacing: 1 }];
export const QUICK_LADDER: readonly BenchQuality[] = [
  { texelSize: 0.25, samples: 8, bounces: 1 },
  { texelSize: 0.2, samples: 16, bounces: 2 },
];

/** Scaling studies on the living room: luminaire counts, and texel sizes at fixed samples and bounces. */
export const SCALING_LUMINAIRES = [1, 2, 5, 10];
export const SCALING_TEXELS = [0.1, 0.05, 0.035, 0.025];
export const SCALING_QUALITY: Omit<BenchQuality, 'texelSize'> = { samples: 32, bounces: 3 };
