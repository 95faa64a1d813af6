/**
 * Can this device run the 3D view? It needs WebGL2 and float render targets
 * (EXT_color_buffer_float) for the baker. Checked on a throwaway canvas
 * before the 3D chunk is even downloaded; null = fine, else a message.
 */
export function webglSupportProblem(): string | null {
  if (typeof document === 'undefined') return 'no document';
  const canvas = document.createElement('canvas');
  const gl = canvas.getContext('webgl2');
  if (!gl) return 'This browser or device has no WebGL2, which the 3D light view needs. The 2D planner works as before.';
  const float = gl.getExtension('EXT_color_buffer_float');
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  if (!float) return 'This device cannot render to floating-point textures (EXT_color_buffer_float), which the light baking needs. The 2D planner works as before.';
  return null;
}
