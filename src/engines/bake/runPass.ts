import type { FragmentPass, UniformSpec, UniformType } from '../../../shaders/fragmentPass.glsl';
import { getProgram, uniformLocation } from './glResources';
import type { FloatTarget } from './floatTarget';

/** A compiled pass: its program and the uniforms its fragment shader declares (fragmentPass.glsl.ts). */
export interface PassProgram<U extends UniformSpec = UniformSpec> {
  program: WebGLProgram;
  uniforms: U;
}

/** What a uniform of a GLSL type is set from. */
type UniformValue<T extends UniformType> = T extends 'sampler2D'
  ? WebGLTexture
  : T extends 'int' | 'float'
    ? number
    : T extends 'vec2' | 'ivec2'
      ? readonly [number, number]
      : T extends 'vec3'
        ? readonly [number, number, number] | Float32Array
        : Float32Array | readonly number[];

/** A value for every uniform of a pass, by name. */
export type UniformValues<U extends UniformSpec> = { [K in keyof U]: UniformValue<U[K]> };

/** Link a pass (cached by source: glResources.getProgram) and pair the program with its uniforms. */
export function passProgram<U extends UniformSpec>(gl: WebGL2RenderingContext, pass: FragmentPass<U>): PassProgram<U> {
  return { program: getProgram(gl, pass.source).program, uniforms: pass.uniforms };
}

/** A sub-rectangle of the target to draw into (x, y, width, height; default: all of it). */
export type Viewport = readonly [number, number, number, number];

/**
 * The one way a bake pass is drawn: the full-screen triangle into `target`
 * (or a viewport of it) with every uniform of the pass set from `values`.
 * Samplers take texture units 0, 1, … in declaration order. A uniform the
 * compiler optimised away has no location and is skipped; array uniforms are
 * set through their first element's name (headless-gl 9 rc returns null for
 * the bare name).
 */
export function runPass<U extends UniformSpec>(gl: WebGL2RenderingContext, pass: PassProgram<U>, target: FloatTarget, values: UniformValues<U>, viewport: Viewport = [0, 0, target.width, target.height]): void {
  const { program, uniforms } = pass;
  gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
  gl.viewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  gl.useProgram(program);
  let unit = 0;
  for (const name in uniforms) {
    const type: UniformType = uniforms[name];
    const value = values[name];
    if (type === 'sampler2D') {
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, value as WebGLTexture);
      const loc = uniformLocation(gl, program, name);
      if (loc) gl.uniform1i(loc, unit);
      unit++;
      continue;
    }
    const isArray = type.endsWith(']');
    const loc = uniformLocation(gl, program, isArray ? `${name}[0]` : name);
    if (!loc) continue;
    const v = value as number | readonly number[] | Float32Array;
    switch (type) {
      case 'int':
        gl.uniform1i(loc, v as number);
        break;
      case 'float':
        gl.uniform1f(loc, v as number);
        break;
      case 'ivec2': {
        const [x, y] = v as readonly number[];
        gl.uniform2i(loc, x, y);
        break;
      }
      case 'vec2': {
        const [x, y] = v as readonly number[];
        gl.uniform2f(loc, x, y);
        break;
      }
      default:
        // vec3, float[n], vec3[n]: the arrays go through as they are.
        if (type.startsWith('float')) gl.uniform1fv(loc, v as Float32Array | number[]);
        else gl.uniform3fv(loc, v as Float32Array | number[]);
    }
  }
  gl.drawArrays(gl.TRIANGLES, 0, 3);
}
