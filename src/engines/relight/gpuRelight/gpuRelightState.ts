import { relightCombinePass, type RelightCombineUniforms } from '../../../../shaders/relightCombine.glsl';
import { createFloatTarget, requireFloatTargets, type FloatTarget } from '../../bake/floatTarget';
import { passProgram, type PassProgram } from '../../bake/runPass';
import type { BasisPrecision, GpuDirectTotal, ReadbackCounter } from '../createGpuRelight';

/** A basis or indirect map uploaded once as a texture (sampled with texelFetch: no filtering needed). */
export interface Uploaded {
  texture: WebGLTexture;
  bytes: number;
}

/** A receiver's display targets and the scratch target its chunked combine alternates with. */
export type ReceiverTargets = GpuDirectTotal & { scratch: FloatTarget };

/** What the GPU relight's parts share: the context, its program, the uploaded maps, the display targets and the counters. */
export interface GpuRelightState {
  gl: WebGL2RenderingContext;
  precision: BasisPrecision;
  /** The display targets are sampled by the view: linear only where float textures filter (else nearest, as the view's DataTextures). */
  linear: boolean;
  program: PassProgram<RelightCombineUniforms>;
  uploads: Map<Float32Array, Uploaded>;
  outputs: Map<string, ReceiverTargets>;
  readbacks: ReadbackCounter;
  uploaded: ReadbackCounter;
  draws: number;
  /** A 1×1 zero texture: the sampler of an unused basis slot. */
  zero: FloatTarget;
  /** Zero textures of each size: the accumulator of a direct map. Cleared on creation (createFloatTarget). */
  zeros: Map<string, FloatTarget>;
  /** The maps the last grid relight used: kept by the receivers' prune. */
  gridInUse: Set<Float32Array>;
}

export function initialGpuRelightState(gl: WebGL2RenderingContext, precision: BasisPrecision): GpuRelightState {
  const { linear } = requireFloatTargets(gl);
  return {
    gl,
    precision,
    linear,
    program: passProgram(gl, relightCombinePass),
    uploads: new Map(),
    outputs: new Map(),
    readbacks: { count: 0, bytes: 0 },
    uploaded: { count: 0, bytes: 0 },
    draws: 0,
    zero: createFloatTarget(gl, 1, 1, false),
    zeros: new Map(),
    gridInUse: new Set(),
  };
}
