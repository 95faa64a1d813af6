import type { SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { FragmentPass, UniformSpec } from '../../../shaders/fragmentPass.glsl';
import type { BakeReport } from './bakeJob';
import { getProgram } from './glResources';
import type { PassProgram } from './runPass';

/** Compiles (or takes from the cache) a pass; `name` and `surface` label it in the report. */
export type CompilePass = <U extends UniformSpec>(pass: FragmentPass<U>, name: string, surface?: SurfaceName | null) => PassProgram<U>;

/**
 * A job's compiler: programs come from the per-context cache
 * (glResources.getProgram), the time spent waiting for compiles is added to
 * `timings.compile`, and every program used is listed in `shaders` (the
 * report's `bake.shaders`, with whether it came from the cache).
 */
export function createPassCompiler(gl: WebGL2RenderingContext, timings: { compile: number }): { compile: CompilePass; shaders: BakeReport['shaders'] } {
  const shaders: BakeReport['shaders'] = [];
  const compile: CompilePass = (pass, name, surface = null) => {
    const s = performance.now();
    const info = getProgram(gl, pass.source);
    timings.compile += performance.now() - s;
    shaders.push({ pass: name, surface, bytes: pass.source.length, cached: !info.compiled });
    return { program: info.program, uniforms: pass.uniforms };
  };
  return { compile, shaders };
}
