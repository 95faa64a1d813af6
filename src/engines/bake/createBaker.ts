import { SURFACE_NAMES, type Rgb, type SurfaceName, type Vec3 } from '../../core/model/lightingScene';
import type { Photometry } from '../../core/photometry/types';
import { blurFragment, combineFragment } from '../../../shaders/passes.glsl';
import { combineTailFragment } from '../../../shaders/fluxReduce.glsl';
import type { BakedMaps } from './bakedMaps';
import { toRgb, type BakeScene } from './bakeScene';
import { resolveBakeSettings, type BakeSettings } from './bakeSettings';
import { generateDirectShader, type DirectLamp } from './generateDirectShader';
import { generateGatherShader } from './generateGatherShader';
import { brightPatchOptions, brightPatchReport, runBrightPatchPass } from './brightPatches';
import { createFluxStatistics, type FluxRecord } from './fluxStatistics';
import { createTargetPool, type TargetPool } from './targetPool';
import {
  bindTexture,
  clearTarget,
  createDataTexture,
  drawInto,
  getProgram,
  readRgb,
  requireFloatTargets,
  uploadRgb,
  startPrograms,
  uniformLocation,
  type FloatTarget,
} from './glResources';
import { lampReachesSurface } from './lampReach';
import { scenePointSources } from './scenePointSources';
import { buildProfileTable, DATA_TEXTURE_WIDTH } from './profileTable';
import { surfaceLayouts, type SurfaceLayout } from './surfaceLayout';
import type { BakeJob, BakeProgress, BakeReport, Baker } from './bakeJob';

export type { BakeJob, BakeProgress, BakeReport, Baker } from './bakeJob';

function mixSeed(...values: number[]): number {
  let h = 0x811c9dc5;
  for (const v of values) {
    h = Math.imul(h ^ (v >>> 0), 0x01000193) >>> 0;
    h ^= h >>> 15;
    h = Math.imul(h, 0x2c1b3c6d) >>> 0;
  }
  return h >>> 0;
}

/** Create a baker on any WebGL2 context (browser canvas or headless-gl). */
export function createBaker(gl: WebGL2RenderingContext): Baker {
  const { linear } = requireFloatTargets(gl);
  // Render targets outlive a job: the next bake of the same room reuses them (targetPool.ts).
  const pool = createTargetPool(gl, linear);
  const start = (scene: BakeScene, partial: Partial<BakeSettings> | undefined, direct: Record<SurfaceName, Float32Array> | null) =>
    startJob(gl, linear, pool, scene, resolveBakeSettings(partial), direct);
  return {
    dispose: () => pool.dispose(),
    start: (scene, settings) => start(scene, settings, null),
    startFromDirect: (room, direct, settings) => start({ room, luminaires: [] }, settings, direct),
    bake(scene, settings) {
      const job = start(scene, settings, null);
      try {
        job.run();
        return { maps: job.readMaps(), report: job.report() };
      } finally {
        job.dispose();
      }
    },
  };
}

interface SurfaceState {
  layout: SurfaceLayout;
  direct: FloatTarget;
  sum: [FloatTarget, FloatTarget];
  sumCurrent: number;
  acc: [FloatTarget, FloatTarget, FloatTarget];
  /** Index in acc of the previous bounce (gather input), or -1 for the direct map. */
  input: number;
  read: number;
  write: number;
  raw: FloatTarget;
  blurTemp: FloatTarget;
  indirect: FloatTarget;
  total: FloatTarget;
  gather: WebGLProgram | null;
}

function startJob(
  gl: WebGL2RenderingContext,
  linear: boolean,
  pool: TargetPool,
  scene: BakeScene,
  settings: BakeSettings,
  directOverride: Record<SurfaceName, Float32Array> | null,
): BakeJob {
  const t0 = performance.now();
  const timings = { compile: 0, direct: 0, indirect: 0, blur: 0, blend: 0, readback: 0, total: 0 };
  const shaders: BakeReport['shaders'] = [];
  const { room } = scene;
  const roomSize: Vec3 = [room.width, room.height, room.depth];
  const reflectance = SURFACE_NAMES.map((n) => toRgb(room.reflectance[n]));
  const layouts = surfaceLayouts(room, settings.texelSize, settings.maxTextureSize);
  // Without syncTimings no pass waits for the GPU (a finish per pass is a full
  // pipeline stall); the timings then measure submission, and the first
  // read-back pays for the queued work.
  // Nested sections (a bounce's blend inside a step's indirect) count once:
  // a section's own time excludes its children's.
  const open: number[] = [];
  const timed = <T>(key: keyof typeof timings, f: () => T): T => {
    // Profiling: work the enclosing section queued is its own, not this one's.
    if (settings.syncTimings && open.length > 0) gl.finish();
    const s = performance.now();
    open.push(0);
    try {
      const r = f();
      if (settings.syncTimings) gl.finish();
      return r;
    } finally {
      const elapsed = performance.now() - s;
      timings[key] += elapsed - open.pop()!;
      if (open.length) open[open.length - 1] += elapsed;
    }
  };
  const readbacks = { count: 0, bytes: 0 };
  const countRead = (bytes: number) => {
    readbacks.count++;
    readbacks.bytes += bytes;
  };
  const program = (source: string, pass: string, surface: SurfaceName | null): WebGLProgram => {
    const s = performance.now();
    const info = getProgram(gl, source);
    timings.compile += performance.now() - s;
    shaders.push({ pass, surface, bytes: source.length, cached: !info.compiled });
    return info.program;
  };

  // Profiles: each distinct Photometry object once in the table.
  const distinct: Photometry[] = [];
  const profileIndex = new Map<Photometry, number>();
  for (const l of scene.luminaires) {
    if (!profileIndex.has(l.photometry)) {
      profileIndex.set(l.photometry, distinct.length);
      distinct.push(l.photometry);
    }
  }
  const table = buildProfileTable(distinct);
  const dataTexture = distinct.length > 0 ? createDataTexture(gl, table.data, DATA_TEXTURE_WIDTH, table.rows) : null;

  // Point sources (near-field model, TILT, dimming, colour): shared with the CPU directAtPoint.
  let pointSourceCount = 0;
  const lamps = scenePointSources(scene, settings).flatMap((l) => {
    const profile = table.layouts[profileIndex.get(l.photometry)!];
    if (profile.peakCandela <= 0) return [];
    pointSourceCount += l.sources.length;
    return [{ profile, rotation: l.rotation, sources: l.sources, sides: l.sides, weight: l.weight } satisfies DirectLamp];
  });

  pool.nextJob();
  // Only what is read before it is written must start at zero: the first
  // running sum and the first accumulator (a skipped direct map is cleared below).
  const target = (layout: SurfaceLayout, zero = false) => pool.acquire(layout.width, layout.height, zero);
  const directSkipped: SurfaceName[] = [];
  const states: SurfaceState[] = layouts.map((layout) => ({
    layout,
    direct: target(layout),
    sum: [target(layout, true), target(layout)],
    sumCurrent: 0,
    acc: [target(layout, true), target(layout), target(layout)],
    input: -1,
    read: 0,
    write: 1,
    raw: target(layout),
    blurTemp: target(layout),
    indirect: target(layout),
    total: target(layout),
    gather: null,
  }));

  // The programs this bake will use, known before any is needed: their
  // compiles are started together (glResources.startPrograms).
  const directSources = states.map((st) => {
    if (directOverride) return null;
    const reaching = lamps.filter((l) => lampReachesSurface(l.sources, l.rotation, l.profile.gammaMin, l.profile.gammaMax, st.layout));
    return reaching.length > 0 ? generateDirectShader(st.layout, reaching, settings.texelSupersampling) : null;
  });
  const maxRho = Math.max(...reflectance.flat());
  // Whether any light was emitted is known on the CPU: no read-back needed.
  const anyDirect = directOverride
    ? Object.values(directOverride).some((rgb) => rgb.some((v) => v > 0))
    : directSources.some((source) => source !== null);
  const indirectEnabled = settings.bounces > 0 && maxRho > 0 && anyDirect;
  const gatherSources = indirectEnabled ? states.map((st) => generateGatherShader(st.layout, roomSize, reflectance)) : [];
  startPrograms(gl, [
    ...directSources.filter((source): source is string => source !== null),
    combineFragment,
    ...(indirectEnabled ? [combineTailFragment, ...gatherSources] : []),
    ...(indirectEnabled && settings.blurRadius > 0 ? [blurFragment] : []),
  ]);

  // Direct pass.
  timed('direct', () => {
    states.forEach((st, s) => {
      if (directOverride) {
        uploadRgb(gl, st.direct, directOverride[st.layout.name]);
        return;
      }
      const source = directSources[s];
      if (source === null) {
        directSkipped.push(st.layout.name);
        clearTarget(gl, st.direct);
        return;
      }
      const prog = program(source, 'direct', st.layout.name);
      drawInto(gl, st.direct, prog, () => bindTexture(gl, prog, 'uProfiles', 0, dataTexture!));
    });
  });

  // Flux statistics per bounce (for the tail and the report) stay on the GPU:
  // record 0 is the direct light, record k bounce k.
  const statistics = createFluxStatistics(gl, pool, layouts, reflectance, settings.bounces + 1, countRead);
  timed('blend', () => statistics.record(0, states.map((st) => st.direct), 1));
  const combineTail = indirectEnabled ? program(combineTailFragment, 'combine', null) : null;
  const combine = program(combineFragment, 'combine', null);
  const blur = indirectEnabled && settings.blurRadius > 0 ? program(blurFragment, 'blur', null) : null;
  if (indirectEnabled) {
    states.forEach((st, s) => (st.gather = program(gatherSources[s], 'gather', st.layout.name)));
  }
  // Bounce 1 from the brightest tiles of the direct maps, exactly (brightPatches.ts).
  const brightPass = indirectEnabled
    ? timed('direct', () =>
        runBrightPatchPass(gl, linear, layouts, reflectance, states.map((st) => st.direct), brightPatchOptions(settings), (source, pass) => program(source, pass, null), countRead, pool),
      )
    : null;

  let bounce = 0;
  let samplesDone = 0;
  let finalized = false;
  const progress = (): BakeProgress => ({
    bounce,
    bounces: indirectEnabled ? settings.bounces : 0,
    samplesDone,
    samplesPerBounce: settings.samples,
    done: !indirectEnabled || bounce >= settings.bounces,
  });

  const runCombine = (out: FloatTarget, a: FloatTarget, b: FloatTarget, scaleA: Rgb, scaleB: Rgb) => {
    drawInto(gl, out, combine, () => {
      bindTexture(gl, combine, 'uA', 0, a.texture);
      bindTexture(gl, combine, 'uB', 1, b.texture);
      gl.uniform3fv(uniformLocation(gl, combine, 'uScaleA'), scaleA);
      gl.uniform3fv(uniformLocation(gl, combine, 'uScaleB'), scaleB);
    });
  };

  const gatherDraw = (st: SurfaceState, first: number, count: number) => {
    const prog = st.gather!;
    drawInto(gl, st.acc[st.write], prog, () => {
      states.forEach((src, s) => {
        const tex = src.input < 0 ? (brightPass?.residual[s] ?? src.direct) : src.acc[src.input];
        bindTexture(gl, prog, `uSource${s}`, s, tex.texture);
      });
      bindTexture(gl, prog, 'uAccumulated', 6, st.acc[st.read].texture);
      const bright = st.input < 0 ? brightPass?.bright[st.layout.index] : null;
      bindTexture(gl, prog, 'uBright', 7, (bright ?? st.acc[st.read]).texture);
      gl.uniform1f(uniformLocation(gl, prog, 'uBrightWeight'), bright ? 1 : 0);
      gl.uniform1i(uniformLocation(gl, prog, 'uFirstSample'), first);
      gl.uniform1i(uniformLocation(gl, prog, 'uSampleCount'), count);
      // The previous bounce is stored as the sum of its S samples: read it as lux.
      gl.uniform1f(uniformLocation(gl, prog, 'uInputScale'), st.input < 0 ? 1 : 1 / settings.samples);
      gl.uniform1i(uniformLocation(gl, prog, 'uSeed'), mixSeed(settings.seed, st.layout.index, bounce) | 0);
    });
    [st.read, st.write] = [st.write, st.read];
  };

  // A finished bounce k: acc holds S·E_k. Add E_k to the running sum, measure its
  // flux and flux-weighted reflectance (for the tail), make it the next input.
  const finishBounce = () => {
    const inv = 1 / settings.samples;
    timed('blend', () => {
      for (const st of states) {
        const next = 1 - st.sumCurrent;
        runCombine(st.sum[next], st.sum[st.sumCurrent], st.acc[st.read], [1, 1, 1], [inv, inv, inv]);
        st.sumCurrent = next;
      }
    });
    timed('blend', () => statistics.record(bounce + 1, states.map((st) => st.acc[st.read]), inv));
    bounce++;
    for (const st of states) {
      const finished = st.read;
      const free = [0, 1, 2].filter((i) => i !== finished);
      st.input = finished;
      st.read = free[0];
      st.write = free[1];
      clearTarget(gl, st.acc[st.read]);
    }
    samplesDone = 0;
  };

  const step = (maxSamples = settings.samplesPerDraw): BakeProgress => {
    if (!indirectEnabled) return progress();
    let remaining = maxSamples;
    timed('indirect', () => {
      while (remaining > 0 && bounce < settings.bounces) {
        const n = Math.min(remaining, settings.samplesPerDraw, settings.samples - samplesDone);
        for (const st of states) gatherDraw(st, samplesDone, n);
        samplesDone += n;
        remaining -= n;
        finalized = false;
        if (samplesDone >= settings.samples) finishBounce();
      }
    });
    return progress();
  };

  /**
   * Tail of the bounce series (ρ → 1). In a closed box every reflected lumen
   * lands on some surface, so the flux of bounce k+1 is exactly the reflected
   * flux of bounce k: Φ_{k+1} = Σ ρ·E_k·A. The ratio r = Φ_{k+1}/Φ_k is the
   * flux-weighted reflectance of bounce k, and as k grows the bounce shape
   * converges (power iteration) so r becomes constant: the remaining series is
   * geometric, Σ_{j>B} E_j ≈ E_B · r/(1−r). This is the "ambient term" of
   * progressive radiosity (Cohen, Chen, Wallace, Greenberg, SIGGRAPH 1988),
   * applied per channel with E_B's own distribution as the shape.
   */
  const runTail = (out: FloatTarget, sum: FloatTarget, part: FloatTarget, offset: number, tailScale: number) => {
    const prog = combineTail!;
    drawInto(gl, out, prog, () => {
      bindTexture(gl, prog, 'uA', 0, sum.texture);
      bindTexture(gl, prog, 'uB', 1, part.texture);
      bindTexture(gl, prog, 'uStats', 2, statistics.stats.texture);
      gl.uniform1i(uniformLocation(gl, prog, 'uStatsIndex'), bounce);
      gl.uniform3fv(uniformLocation(gl, prog, 'uScaleA'), [1, 1, 1]);
      gl.uniform3fv(uniformLocation(gl, prog, 'uOffsetB'), [offset, offset, offset]);
      const t = settings.tail ? tailScale : 0;
      gl.uniform3fv(uniformLocation(gl, prog, 'uTailB'), [t, t, t]);
    });
  };

  const finalize = () => {
    if (indirectEnabled) {
      // The tail factor f = r/(1−r) of the last finished bounce is applied on
      // the GPU from the stats row (fluxStatistics.ts).
      timed('blend', () => {
        for (const st of states) {
          const sum = st.sum[st.sumCurrent];
          if (samplesDone > 0) {
            // Bounce under way: its partial mean stands in for itself and the rest of the series.
            runTail(st.raw, sum, st.acc[st.read], 1 / samplesDone, 1 / samplesDone);
          } else if (bounce > 0) {
            runTail(st.raw, sum, st.acc[st.input], 0, 1 / settings.samples);
          } else {
            runCombine(st.raw, sum, sum, [1, 1, 1], [0, 0, 0]);
          }
        }
      });
      if (blur) {
        const radius = settings.blurRadius;
        const sigma = radius / 2;
        timed('blur', () => {
          for (const st of states) {
            const passes: [FloatTarget, FloatTarget, number, number][] = [
              [st.raw, st.blurTemp, 1, 0],
              [st.blurTemp, st.indirect, 0, 1],
            ];
            for (const [src, dst, dx, dy] of passes) {
              drawInto(gl, dst, blur, () => {
                bindTexture(gl, blur, 'uSource', 0, src.texture);
                gl.uniform2i(uniformLocation(gl, blur, 'uDirection'), dx, dy);
                gl.uniform1i(uniformLocation(gl, blur, 'uRadius'), radius);
                gl.uniform1f(uniformLocation(gl, blur, 'uInvTwoSigma2'), 1 / (2 * sigma * sigma));
              });
            }
          }
        });
      } else {
        timed('blend', () => {
          for (const st of states) runCombine(st.indirect, st.raw, st.raw, [1, 1, 1], [0, 0, 0]);
        });
      }
    } else {
      for (const st of states) clearTarget(gl, st.indirect);
    }
    timed('blend', () => {
      for (const st of states) runCombine(st.total, st.direct, st.indirect, [1, 1, 1], [1, 1, 1]);
    });
    finalized = true;
  };

  let disposed = false;
  let records: FluxRecord[] | null = null;
  const job: BakeJob = {
    layouts,
    get progress() {
      return progress();
    },
    step,
    run() {
      while (!progress().done) step(settings.samples);
      finalize();
    },
    finalize,
    textures() {
      return Object.fromEntries(
        states.map((st) => [st.layout.name, { direct: st.direct.texture, indirect: st.indirect.texture, total: st.total.texture }]),
      ) as ReturnType<BakeJob['textures']>;
    },
    readMaps() {
      if (!finalized) finalize();
      const read = (t: FloatTarget) => {
        countRead(t.width * t.height * 16);
        return readRgb(gl, t);
      };
      return timed('readback', () =>
        Object.fromEntries(
          states.map((st) => [st.layout.name, { layout: st.layout, direct: read(st.direct), indirect: read(st.indirect), total: read(st.total) }]),
        ) as BakedMaps,
      );
    },
    report() {
      // One read-back of the stats row, only now (never between bounces).
      if (!records || records.length !== bounce + 1) records = timed('readback', () => statistics.read(bounce + 1));
      const lastRatio = records[bounce].ratio;
      const tailFactor: Rgb = indirectEnabled && settings.tail ? (lastRatio.map((r) => r / (1 - r)) as Rgb) : [0, 0, 0];
      timings.total = performance.now() - t0;
      return {
        settings,
        texels: Object.fromEntries(layouts.map((l) => [l.name, [l.width, l.height]])) as BakeReport['texels'],
        totalTexels: layouts.reduce((n, l) => n + l.width * l.height, 0),
        luminaires: scene.luminaires.length,
        pointSources: pointSourceCount,
        directSkipped,
        indirectEnabled,
        brightPatches: brightPass ? brightPatchReport(brightPass.selection) : { count: 0, peakedness: 1, residualPeakedness: 1 },
        samplesPerTexelPerBounce: indirectEnabled ? settings.samples : 0,
        bouncesComputed: bounce,
        bounceFlux: records.map((r) => r.fluxY),
        tailRatio: lastRatio,
        tailFactor,
        linearFiltering: linear,
        shaders,
        timings_ms: { ...timings },
        readbacks: { ...readbacks },
      };
    },
    dispose() {
      if (disposed) return;
      disposed = true;
      for (const st of states) {
        for (const t of [st.direct, ...st.sum, ...st.acc, st.raw, st.blurTemp, st.indirect, st.total]) pool.release(t);
      }
      statistics.dispose();
      if (dataTexture) gl.deleteTexture(dataTexture);
      brightPass?.dispose();
    },
  };
  return job;
}
