/**
 * A bake pass's fragment shader together with its uniforms, declared once:
 * the GLSL `uniform` lines are generated from the same table that the
 * caller's runPass (src/engines/bake/runPass.ts) uses to set them, so a name
 * or a type cannot drift between the shader and the code that drives it.
 */
import { fragmentHeader } from './fullscreen.glsl';

/** The GLSL types the bake passes take as uniforms; `T[n]` is an array (set by its first element's name). */
export type UniformType = 'sampler2D' | 'int' | 'float' | 'vec2' | 'ivec2' | 'vec3' | `float[${number}]` | `vec3[${number}]`;

/** Uniform name → GLSL type, in declaration order (samplers take texture units in this order). */
export type UniformSpec = Readonly<Record<string, UniformType>>;

export interface FragmentPass<U extends UniformSpec = UniformSpec> {
  /** Complete fragment shader: header, the uniforms of `uniforms`, body. */
  source: string;
  uniforms: U;
}

/** `uniform <type> <name>;` per entry (`uniform float uArea[6];` for arrays). */
export function uniformDeclarations(uniforms: UniformSpec): string {
  return Object.entries(uniforms)
    .map(([name, type]) => {
      const array = /^(\w+)\[(\d+)\]$/.exec(type);
      return array ? `uniform ${array[1]} ${name}[${array[2]}];\n` : `uniform ${type} ${name};\n`;
    })
    .join('');
}

/** A pass from its uniforms and the rest of its fragment shader (constants, functions, `main`). */
export function fragmentPass<U extends UniformSpec>(uniforms: U, body: string): FragmentPass<U> {
  return { source: `${fragmentHeader}${uniformDeclarations(uniforms)}${body}`, uniforms };
}
