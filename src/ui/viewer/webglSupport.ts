/** Why the 3D view cannot run here: a stable code (translated by the UI, docs/i18n.md) and the English sentence for logs and the status API. */
export interface WebglSupportIssue {
  code: 'noDocument' | 'noWebgl2' | 'noFloatTargets';
  text: string;
}

/**
 * Can this device run the 3D view? It needs WebGL2 and float render targets
 * (EXT_color_buffer_float) for the baker. Checked on a throwaway canvas
 * before the 3D chunk is even downloaded; null = fine, else the issue.
 */
export function webglSupportIssue(): WebglSupportIssue | null {
  if (typeof document === 'undefined') return { code: 'noDocument', text: 'no document' };
  const canvas = document.createElement('canvas');
  const gl = canvas.getContext('webgl2');
  if (!gl) return { code: 'noWebgl2', text: 'This browser or device has no WebGL2, which the 3D light view needs. The 2D planner works as before.' };
  const float = gl.getExtension('EXT_color_buffer_float');
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  if (!float) return { code: 'noFloatTargets', text: 'This device cannot render to floating-point textures (EXT_color_buffer_float), which the light baking needs. The 2D planner works as before.' };
  return null;
}

/** The English sentence of webglSupportIssue(), or null = fine. */
export function webglSupportProblem(): string | null {
  return webglSupportIssue()?.text ?? null;
}
