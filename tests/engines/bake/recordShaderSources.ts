/**
 * Every shader source `gl` compiles from now on, in order (captured at gl.shaderSource, so no
 * compile escapes): for tests that pin shaders or count compiles.
 */
export function recordShaderSources(gl: WebGL2RenderingContext): string[] {
  const compiled: string[] = [];
  const shaderSource = gl.shaderSource.bind(gl);
  gl.shaderSource = (shader: WebGLShader, source: string) => {
    compiled.push(source);
    shaderSource(shader, source);
  };
  return compiled;
}
