import { InputError } from '../../core/inputError';
import type { Photometry } from '../../core/photometry/types';
import type { BakeScene } from '../bake/bakeScene';
import type { BakeSettings } from '../bake/bakeSettings';
import { resolveBakeSettings } from '../bake/bakeSettings';
import { createBaker } from '../bake/createBaker';
import { surfaceLayouts } from '../bake/surfaceLayout';
import { QUALITY_LEVEL_NAMES, QUALITY_LEVELS, type QualityLevel } from './qualityLevels';

/**
 * How fast this device bakes (docs/viewer.md, "Quality levels"): measured once by a short
 * calibration bake, then used by `chooseQuality` to predict each level's times.
 */
export interface BakeCalibration {
  /** Indirect solve cost: ms per texel per sample per bounce (warm; gather, bright patches, blur and blend; GPU work included). */
  msPerTexelSample: number;
  /** Direct pass cost: ms per texel per point source (warm, GPU work included). */
  msPerTexelSource: number;
  /** The rest of a direct basis: combine, read-back to the CPU and allocation, ms per texel (warm). */
  msPerTexelBasis: number;
  /**
   * What a group with a photometry not seen before costs before its direct pass can run: the
   * relight engine's direct bases take the lamps as uniforms (`lampUniforms`), so a program is
   * compiled per surface and photometry, and a moved or added module of a known type compiles
   * nothing (ms).
   */
  directCompileMs: number;
  /** What the first (cold) calibration bake cost more than the warm one: every program compiled once, ms. */
  compileMs: number;
  /** The GL renderer string (the cache key of a stored calibration). */
  renderer: string;
  /** The work the timed bake did (the same on every device: CALIBRATION_SCENE, CALIBRATION_SETTINGS). */
  work: { texels: number; pointSources: number; samples: number; bounces: number };
}

/** Peak intensity of the calibration luminaire (cd, straight down). */
export const CALIBRATION_PEAK_CD = 300;

/**
 * The calibration scene: a 3 × 2.5 × 3 m room (ρ 0.5) and one module-like luminaire at its
 * centre, facing down: a cosine (Lambertian) distribution of 300 cd peak (≈ 942 lm) tabulated
 * every 5° like a measured file, from a 0.24 × 0.09 m luminous opening that the split near
 * field turns into 5 × 2 = 10 point sources (the mean of the catalog's modules), so its direct
 * program, and the compile of it, is a typical group's. At the centre (1.25 m from floor and
 * ceiling): a source hung 0.3 m under the ceiling made the ceiling's supersampling dominate and
 * predicted 3–5× the direct cost measured in real rooms. 5 cm texels (19 200, about half a
 * viewer basis, so per-draw overheads weigh as they do there), 32 samples, 1 bounce, the
 * viewer's blur and bright patches; the direct pass supersamples near the sources as every
 * viewer bake does. Fixed, so every device bakes the same work.
 */
export const CALIBRATION_SCENE: BakeScene = {
  room: { width: 3, height: 2.5, depth: 3, reflectance: { floor: 0.5, ceiling: 0.5, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } },
  luminaires: [{ photometry: calibrationPhotometry(), position: [1.5, 1.25, 1.5], yaw: 0, pitch: 0, roll: 0, dimming: 1, color: [1, 1, 1] }],
};

export const CALIBRATION_SETTINGS: Partial<BakeSettings> = {
  texelSize: 0.05,
  maxTextureSize: 128,
  samples: 32,
  bounces: 1,
  samplesPerDraw: 8,
  blurRadius: 5,
  tail: false,
  syncTimings: true,
  seed: 1,
};

/**
 * A luminaire of a new type at the centre moved by `dx` m: the relight engine's direct-basis bake
 * of a group. Types differ in distribution (cos^`power` γ) and in table size (every `step`°), as
 * two catalog files do, so each compiles its own direct programs.
 */
const groupScene = (power: number, step: number, dx: number): BakeScene => ({
  ...CALIBRATION_SCENE,
  luminaires: [{ ...CALIBRATION_SCENE.luminaires[0], photometry: calibrationPhotometry(power, step), position: [1.5 + dx, 1.25, 1.5] }],
});

/** I(γ) = CALIBRATION_PEAK_CD · cos^power γ below the horizon, 0 above, every `step`° (a divisor of 180); absolute photometry; 0.24 × 0.09 m opening. */
function calibrationPhotometry(power = 1, step = 5): Photometry {
  const angles = Array.from({ length: 180 / step + 1 }, (_, i) => i * step);
  const candela = angles.map((g) => (g < 90 ? CALIBRATION_PEAK_CD * Math.cos((g * Math.PI) / 180) ** power : 0));
  return {
    format: 'IES',
    version: 'calibration',
    manufacturer: '',
    luminaire: 'calibration downlight',
    catalogNumber: '',
    keywords: {},
    photometricType: 'C',
    symmetry: 'rotational',
    verticalAngles: angles,
    horizontalAngles: [0],
    candela: [candela],
    statedLumens: null,
    absolute: true,
    inputWatts: null,
    luminousOpening: { width: 0.24, length: 0.09, height: 0, shape: 'rectangular' },
    warnings: [],
  };
}

/** Renderer string, unmasked where WEBGL_debug_renderer_info is offered. */
export function glRenderer(gl: WebGL2RenderingContext): string {
  const debug = gl.getExtension('WEBGL_debug_renderer_info') as { UNMASKED_RENDERER_WEBGL: number } | null;
  return String(gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
}

// A timer's resolution can be 0.1 ms or coarser (browsers): floor each measured cost at 1 µs.
const atLeast = (ms: number) => Math.max(ms, 0.001);

/**
 * Bakes the calibration scene on `gl`: once cold (compiles every program: `compileMs` is its
 * extra time over the fastest warm one) and twice warm, timed per pass (`syncTimings`: each pass
 * waits for the GPU) for the indirect cost; then, as the relight engine bakes a group's direct
 * basis (direct only, lamps as uniforms), twice a luminaire of a new type (cos² every 2.5°, cos³
 * every 2°: new programs), each followed by the same type moved 10 cm (no compile): the
 * difference is `directCompileMs`, the moved one's direct pass gives `msPerTexelSource` and the
 * rest of its bake (combine, read-back) `msPerTexelBasis`. Each
 * figure is the smaller of its two trials (other work on the device only ever adds time). Costs
 * are per unit of work, so they carry over to any room. About 0.5–4 s on a 2-core software
 * renderer (mostly the first compile), tens of ms on a GPU.
 */
export function calibrateBakeSpeed(gl: WebGL2RenderingContext): BakeCalibration {
  const baker = createBaker(gl);
  try {
    const settings = resolveBakeSettings(CALIBRATION_SETTINGS);
    const basis = { ...settings, bounces: 0, lampUniforms: true };
    const cold = baker.bake(CALIBRATION_SCENE, settings).report;
    const warm = [0, 1].map(() => baker.bake(CALIBRATION_SCENE, settings).report);
    const groups = [
      [2, 2.5],
      [3, 2],
    ].map(([power, step]) => {
      const newType = baker.bake(groupScene(power, step, 0), basis).report;
      const knownType = baker.bake(groupScene(power, step, 0.1), basis).report;
      const t = knownType.timings_ms;
      return { compile: Math.max(0, newType.timings_ms.total - t.total), direct: t.direct, rest: t.total - t.direct };
    });
    const texels = warm[0].totalTexels;
    const pointSources = warm[0].pointSources;
    const least = (f: (t: (typeof warm)[number]['timings_ms']) => number) => atLeast(Math.min(...warm.map((r) => f(r.timings_ms))));
    return {
      msPerTexelSample: least((t) => t.indirect + t.blend + t.blur) / (texels * settings.samples * settings.bounces),
      msPerTexelSource: atLeast(Math.min(...groups.map((g) => g.direct))) / (texels * pointSources),
      msPerTexelBasis: atLeast(Math.min(...groups.map((g) => g.rest))) / texels,
      directCompileMs: Math.min(...groups.map((g) => g.compile)),
      compileMs: Math.max(0, cold.timings_ms.total - least((t) => t.total)),
      renderer: glRenderer(gl),
      work: { texels, pointSources, samples: settings.samples, bounces: settings.bounces },
    };
  } finally {
    baker.dispose();
  }
}

/** What `chooseQuality` predicts for: a room, its luminaire groups and their point sources. */
export interface QualityScene {
  room: { width: number; height: number; depth: number };
  /** Luminaire groups (modules) that each get a direct basis before the first lit frame. */
  groups: number;
  /** Point sources per group (the split near field makes 1–64 per luminaire; docs/baker.md). */
  pointSourcesPerGroup: number;
  /** Distinct photometries among the groups (module types and beams): each compiles its direct programs once. */
  photometries: number;
  /** Indirect solves to finish: 1 when the engine shares one indirect solve, else one per group. */
  indirectSolves: number;
}

/**
 * The scene a first toggle is planned for when the caller knows none yet: the configurator's
 * default 5 × 4 × 2.8 m room with the L-corner preset (6 modules); 10 point sources per module
 * is the mean over the default catalog's five module types under the split near field
 * (spot 9, flood 12, linear 16, washer 6, direct/indirect 8: the bake reports' pointSources),
 * as many as the calibration luminaire has; corner-l has 3 photometries (spot, flood, washer).
 * The relight engine solves the indirect light once for all groups (createRelightEngine).
 */
export const TYPICAL_QUALITY_SCENE: QualityScene = { room: { width: 5, height: 2.8, depth: 4 }, groups: 6, pointSourcesPerGroup: 10, photometries: 3, indirectSolves: 1 };

/** Targets of the automatic choice (issue #15): first lit frame within 1 s, final light within a few seconds. */
export const FIRST_LIT_TARGET_MS = 1000;
export const SOLVE_TARGET_MS = 8000;

export interface QualityPrediction {
  level: QualityLevel;
  texels: number;
  /** Predicted time to the first lit frame (every group's direct basis, each photometry's program compile included), ms. */
  firstLitMs: number;
  /** Predicted time of the indirect solve(s) after that, ms. */
  solveMs: number;
}

/** Texels of one basis at a level's settings (the six surface maps, as the baker lays them out). */
export function levelTexels(room: QualityScene['room'], level: QualityLevel): number {
  const s = resolveBakeSettings(QUALITY_LEVELS[level]);
  return surfaceLayouts(room, s.texelSize, s.maxTextureSize).reduce((n, l) => n + l.width * l.height, 0);
}

/**
 * Each level's predicted cost on a calibrated device:
 * firstLit = compileMs + photometries × directCompileMs + groups × texels × (pointSources × msPerTexelSource + msPerTexelBasis),
 * solve = indirectSolves × texels × samples × bounces × msPerTexelSample.
 * compileMs stands for the first bake on a fresh context (the bake service's own), which compiles
 * its programs there.
 */
export function predictQuality(calibration: BakeCalibration, scene: QualityScene = TYPICAL_QUALITY_SCENE): QualityPrediction[] {
  // A stored calibration from another version, or a hand-edited one, must not turn into NaN predictions (NaN fits no target).
  for (const key of ['msPerTexelSample', 'msPerTexelSource', 'msPerTexelBasis', 'directCompileMs', 'compileMs'] as const) {
    const v = calibration[key];
    if (typeof v !== 'number' || !Number.isFinite(v) || v < 0) throw new InputError(`calibration: ${key} is ${String(v)}, not a finite number ≥ 0`);
  }
  return QUALITY_LEVEL_NAMES.map((level) => {
    const s = resolveBakeSettings(QUALITY_LEVELS[level]);
    const texels = levelTexels(scene.room, level);
    return {
      level,
      texels,
      firstLitMs: calibration.compileMs + scene.photometries * calibration.directCompileMs + scene.groups * texels * (scene.pointSourcesPerGroup * calibration.msPerTexelSource + calibration.msPerTexelBasis),
      solveMs: scene.indirectSolves * texels * s.samples * Math.max(1, s.bounces) * calibration.msPerTexelSample,
    };
  });
}

/**
 * The best level (best > balanced > fast) whose predicted first lit frame is within
 * FIRST_LIT_TARGET_MS and whose solve is within SOLVE_TARGET_MS; 'fast' when none is.
 * Monotone: each level's predictions grow with the per-unit costs, so a device that is at
 * least as fast in every cost never gets a lower level.
 */
export function chooseQuality(calibration: BakeCalibration, scene: QualityScene = TYPICAL_QUALITY_SCENE): QualityLevel {
  const fits = predictQuality(calibration, scene).filter((p) => p.firstLitMs <= FIRST_LIT_TARGET_MS && p.solveMs <= SOLVE_TARGET_MS);
  let chosen: QualityLevel = 'fast';
  for (const p of fits) if (QUALITY_LEVEL_NAMES.indexOf(p.level) > QUALITY_LEVEL_NAMES.indexOf(chosen)) chosen = p.level;
  return chosen;
}
