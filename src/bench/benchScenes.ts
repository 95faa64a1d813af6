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
}

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
