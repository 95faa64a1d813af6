import type { combinePass } from '../../../shaders/combinePass.glsl';
import type { BakeSettings } from './bakeSettings';
import type { BakeTimer } from './createBakeTimer';
import type { FluxStatistics } from './fluxStatistics';
import type { gatherUniforms } from './generateGatherShader';
import { clearTarget } from './floatTarget';
import { mixSeed } from './mixSeed';
import type { BrightPatchPass } from './runBrightPatchPass';
import { runPass, type PassProgram } from './runPass';
import type { BounceTargets } from './surfaceTargets';

/** The G-buffer and BVH textures the object-aware gather passes read (objectGatherUniforms less the per-bounce ones). */
export interface ObjectGatherSamplers {
  uObjectRho: WebGLTexture;
  uBvhNodes: WebGLTexture;
  uBvhTriangles: WebGLTexture;
  uPoints: WebGLTexture;
  uNormals: WebGLTexture;
}

/** The explicit bounces of a bake, advanced a few samples at a time. */
export interface BounceIteration {
  /** Bounces finished. */
  readonly bounce: number;
  /** Samples gathered so far in the bounce under way. */
  readonly samplesDone: number;
  /** Gather up to `maxSamples` more samples per texel (across bounce boundaries) until every bounce is done; false when there was nothing left to gather. */
  step(maxSamples: number): boolean;
}

/**
 * Bounce k gathers from bounce k−1 only (bounce 1 from the direct maps, or
 * their residual with the bright patches' light added exactly), `samples`
 * per texel, in draws of at most `samplesPerDraw` into each surface's sample
 * ping-pong pair. A finished bounce (S·E_k) is added to the running sum as
 * E_k, its flux statistics are recorded for the tail (fluxStatistics.ts),
 * and it becomes the next bounce's input.
 */
export function createBounceIteration(
  gl: WebGL2RenderingContext,
  surfaces: BounceTargets[],
  passes: BouncePasses,
  statistics: FluxStatistics,
  brightPass: BrightPatchPass | null,
  settings: BakeSettings,
  timer: BakeTimer,
  objectSamplers: ObjectGatherSamplers | null = null,
): BounceIteration {
  const state: BounceState = { gl, surfaces, passes, statistics, brightPass, settings, timer, objectSamplers, bounce: 0, samplesDone: 0 };
  return {
    get bounce() {
      return state.bounce;
    },
    get samplesDone() {
      return state.samplesDone;
    },
    step(maxSamples) {
      let remaining = maxSamples;
      timer.timed('indirect', () => {
        while (remaining > 0 && state.bounce < settings.bounces) {
          const n = Math.min(remaining, settings.samplesPerDraw, settings.samples - state.samplesDone);
          surfaces.forEach((st, index) => gatherDraw(state, st, index, state.samplesDone, n));
          state.samplesDone += n;
          remaining -= n;
          if (state.samplesDone >= settings.samples) finishBounce(state);
        }
      });
      return remaining < maxSamples;
    },
  };
}

interface BouncePasses {
  gather: PassProgram<typeof gatherUniforms>[];
  combine: PassProgram<typeof combinePass.uniforms>;
}

/** What the iteration's steps share: its inputs, and where it stands (bounces finished, samples of the current one). */
interface BounceState {
  gl: WebGL2RenderingContext;
  surfaces: BounceTargets[];
  passes: BouncePasses;
  statistics: FluxStatistics;
  brightPass: BrightPatchPass | null;
  settings: BakeSettings;
  timer: BakeTimer;
  objectSamplers: ObjectGatherSamplers | null;
  bounce: number;
  samplesDone: number;
}

/**
 * What receiver s emits into this bounce: the direct map (or its residual) for bounce 1, else the
 * previous bounce. Receivers 0–5 are the room surfaces, 6 the objects' atlas when the scene has objects.
 */
function source(state: BounceState, s: number): WebGLTexture {
  const { bounce, brightPass, surfaces } = state;
  return (bounce === 0 ? (brightPass?.residual[s] ?? surfaces[s].direct) : surfaces[s].previous).texture;
}

/** `count` more samples (from sample `first` on) of receiver `index`'s current bounce into its sample ping-pong pair. */
function gatherDraw(state: BounceState, st: BounceTargets, index: number, first: number, count: number): void {
  const { bounce, brightPass, settings, objectSamplers } = state;
  const bright = bounce === 0 ? brightPass?.bright[index] : null;
  const values = {
    uSource0: source(state, 0),
    uSource1: source(state, 1),
    uSource2: source(state, 2),
    uSource3: source(state, 3),
    uSource4: source(state, 4),
    uSource5: source(state, 5),
    uAccumulated: st.samples.read.texture,
    uBright: (bright ?? st.samples.read).texture,
    uBrightWeight: bright ? 1 : 0,
    uFirstSample: first,
    uSampleCount: count,
    // The previous bounce is stored as the sum of its S samples: read it as lux.
    uInputScale: bounce === 0 ? 1 : 1 / settings.samples,
    uSeed: mixSeed(settings.seed, index, bounce) | 0,
    // The object-aware passes (generateGatherShader.ts objectGatherUniforms) also read the atlas and the BVH.
    ...(objectSamplers ? { ...objectSamplers, uSource6: source(state, 6) } : {}),
  };
  runPass(state.gl, state.passes.gather[index], st.samples.write, values);
  st.samples.swap();
}

/** A bounce is complete: added to the running sum as E_k, its flux recorded, and made the next bounce's input. */
function finishBounce(state: BounceState): void {
  const { gl, surfaces, settings, timer, passes, statistics } = state;
  const inv = 1 / settings.samples;
  timer.timed('blend', () => {
    for (const st of surfaces) {
      runPass(gl, passes.combine, st.sum.write, { uA: st.sum.read.texture, uB: st.samples.read.texture, uScaleA: [1, 1, 1], uScaleB: [inv, inv, inv] });
      st.sum.swap();
    }
  });
  timer.timed('blend', () =>
    statistics.record(
      state.bounce + 1,
      surfaces.map((st) => st.samples.read),
      inv,
    ),
  );
  state.bounce++;
  for (const st of surfaces) {
    // The finished bounce becomes the input; the old input, cleared, collects the next bounce.
    st.previous = st.samples.exchange(st.previous);
    clearTarget(gl, st.samples.read);
  }
  state.samplesDone = 0;
}
