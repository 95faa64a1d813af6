import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import type { blurPass } from '../../../shaders/blurPass.glsl';
import type { chartBlurPass } from '../../../shaders/chartBlurPass.glsl';
import type { chartDilatePass } from '../../../shaders/chartDilatePass.glsl';
import type { combinePass } from '../../../shaders/combinePass.glsl';
import type { combineTailPass } from '../../../shaders/combineTailPass.glsl';
import type { BakeSettings } from './bakeSettings';
import type { BakeTimer } from './createBakeTimer';
import type { BounceIteration } from './createBounceIteration';
import type { FluxStatistics } from './fluxStatistics';
import { clearTarget, type FloatTarget } from './floatTarget';
import { runPass, type PassProgram } from './runPass';
import type { BounceTargets } from './surfaceTargets';

export interface FinalPasses {
  combine: PassProgram<typeof combinePass.uniforms>;
  /** Null when the bake has no indirect light. */
  combineTail: PassProgram<typeof combineTailPass.uniforms> | null;
  /** Null without indirect light or with blurRadius 0. */
  blur: PassProgram<typeof blurPass.uniforms> | null;
}

/**
 * The objects' atlas in the final passes: its targets (also in `surfaces`), a chart-aware blur
 * (shaders/chartBlurPass.glsl.ts) instead of the plain one, and after the total the dilation
 * (shaders/chartDilatePass.glsl.ts) of direct, indirect and total into the maps that are shown.
 */
export interface FinalObjects {
  targets: BounceTargets;
  chartBlur: PassProgram<typeof chartBlurPass.uniforms> | null;
  dilate: PassProgram<typeof chartDilatePass.uniforms>;
  /** G-buffer normal texture (a = chart id + 1) and point texture (a = coverage). */
  charts: WebGLTexture;
  coverage: WebGLTexture;
  shown: { direct: FloatTarget; indirect: FloatTarget; total: FloatTarget };
}

const ONE: Rgb = [1, 1, 1];
const ZERO: Rgb = [0, 0, 0];

/**
 * Indirect and total maps from the current state of a bake: indirect = the
 * finished bounces' sum + the tail of the series (tailFactor.ts, applied on
 * the GPU from the flux-statistics row), blurred (separable Gaussian, σ =
 * radius/2, shaders/blurPass.glsl.ts); total = direct + indirect. A bounce
 * under way stands in, as its partial mean, for itself and the rest of the
 * series. `bounces` is null when the bake has no indirect light.
 */
export function finalizeMaps(
  gl: WebGL2RenderingContext,
  surfaces: readonly BounceTargets[],
  passes: FinalPasses,
  bounces: BounceIteration | null,
  statistics: FluxStatistics,
  settings: BakeSettings,
  timer: BakeTimer,
  objects: FinalObjects | null = null,
): void {
  const copy = (out: FloatTarget, from: FloatTarget) => runPass(gl, passes.combine, out, { uA: from.texture, uB: from.texture, uScaleA: ONE, uScaleB: ZERO });
  const { combineTail, blur } = passes;
  if (bounces && combineTail) {
    // raw = sum + part·(offset + f·tailScale), f = r/(1−r) of the last finished bounce.
    const tail = (st: BounceTargets, part: FloatTarget, offset: number, tailScale: number) => {
      const t = settings.tail ? tailScale : 0;
      runPass(gl, combineTail, st.raw, {
        uA: st.sum.read.texture,
        uB: part.texture,
        uStats: statistics.stats.texture,
        uStatsIndex: bounces.bounce,
        uScaleA: ONE,
        uOffsetB: [offset, offset, offset],
        uTailB: [t, t, t],
      });
    };
    timer.timed('blend', () => {
      for (const st of surfaces) {
        const done = bounces.samplesDone;
        if (done > 0) tail(st, st.samples.read, 1 / done, 1 / done);
        else if (bounces.bounce > 0) tail(st, st.previous, 0, 1 / settings.samples);
        else copy(st.raw, st.sum.read);
      }
    });
    if (blur) {
      const radius = settings.blurRadius;
      const sigma = radius / 2;
      const blurInto = (out: FloatTarget, from: FloatTarget, direction: readonly [number, number]) => runPass(gl, blur, out, { uSource: from.texture, uDirection: direction, uRadius: radius, uInvTwoSigma2: 1 / (2 * sigma * sigma) });
      const chartBlurInto = (out: FloatTarget, from: FloatTarget, direction: readonly [number, number]) =>
        runPass(gl, objects!.chartBlur!, out, { uSource: from.texture, uCharts: objects!.charts, uDirection: direction, uRadius: radius, uInvTwoSigma2: 1 / (2 * sigma * sigma) });
      timer.timed('blur', () => {
        for (const st of surfaces) {
          const into = objects?.chartBlur && st === objects.targets ? chartBlurInto : blurInto;
          into(st.blurTemp, st.raw, [1, 0]);
          into(st.indirect, st.blurTemp, [0, 1]);
        }
      });
    } else {
      timer.timed('blend', () => {
        for (const st of surfaces) copy(st.indirect, st.raw);
      });
    }
  } else {
    for (const st of surfaces) clearTarget(gl, st.indirect);
  }
  timer.timed('blend', () => {
    for (const st of surfaces) runPass(gl, passes.combine, st.total, { uA: st.direct.texture, uB: st.indirect.texture, uScaleA: ONE, uScaleB: ONE });
  });
  if (objects) {
    const { targets, shown, dilate, coverage } = objects;
    timer.timed('blend', () => {
      for (const kind of ['direct', 'indirect', 'total'] as const) runPass(gl, dilate, shown[kind], { uSource: targets[kind].texture, uCoverage: coverage });
    });
  }
}
