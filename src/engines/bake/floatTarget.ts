import { countReadBack } from './readBackCounter';

/** A float render target: texture + framebuffer, RGBA32F (no overflow: half floats stop at 65 504 lx). */
export interface FloatTarget {
  texture: WebGLTexture;
  framebuffer: WebGLFramebuffer;
  width: number;
  height: number;
}

export function requireFloatTargets(gl: WebGL2RenderingContext): { linear: boolean } {
  if (!gl.getExtension('EXT_color_buffer_float')) {
    throw new Error('WebGL2 without EXT_color_buffer_float: float light maps cannot be rendered on this device');
  }
  return { linear: !!gl.getExtension('OES_texture_float_linear') };
}

export function createFloatTarget(gl: WebGL2RenderingContext, width: number, height: number, linear: boolean): FloatTarget {
  const texture = gl.createTexture();
  const framebuffer = gl.createFramebuffer();
  if (!texture || !framebuffer) throw new Error('WebGL: out of resources creating a light map');
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, null);
  const filter = linear ? gl.LINEAR : gl.NEAREST;
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
  const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
  if (status !== gl.FRAMEBUFFER_COMPLETE) throw new Error(`WebGL: RGBA32F framebuffer incomplete (0x${status.toString(16)})`);
  clearTarget(gl, { texture, framebuffer, width, height });
  return { texture, framebuffer, width, height };
}

export function clearTarget(gl: WebGL2RenderingContext, target: FloatTarget): void {
  gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
  // headless-gl 9 aborts on a plain array here: pass a typed array.
  gl.clearBufferfv(gl.COLOR, 0, new Float32Array(4));
}

export function deleteTarget(gl: WebGL2RenderingContext, target: FloatTarget): void {
  gl.deleteFramebuffer(target.framebuffer);
  gl.deleteTexture(target.texture);
}

/** Upload RGB float data (3 per texel, rows from v = 0) into a target. */
export function uploadRgb(gl: WebGL2RenderingContext, target: FloatTarget, rgb: Float32Array): void {
  const rgba = new Float32Array(target.width * target.height * 4);
  for (let i = 0; i < target.width * target.height; i++) {
    rgba[i * 4] = rgb[i * 3];
    rgba[i * 4 + 1] = rgb[i * 3 + 1];
    rgba[i * 4 + 2] = rgb[i * 3 + 2];
    rgba[i * 4 + 3] = 1;
  }
  gl.bindTexture(gl.TEXTURE_2D, target.texture);
  gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, target.width, target.height, gl.RGBA, gl.FLOAT, rgba);
}

/** Read a target back as RGBA floats (4 per texel), row j = 0 first: one readPixels, a full pipeline wait. */
export function readRgba(gl: WebGL2RenderingContext, target: FloatTarget): Float32Array {
  return readRgbaRect(gl, target, 0, 0, target.width, target.height);
}

/**
 * Read a rectangle of a target back as RGBA floats, row y first: the one readPixels of the baker,
 * counted on the context (readBackCounter.ts).
 */
export function readRgbaRect(gl: WebGL2RenderingContext, target: FloatTarget, x: number, y: number, width: number, height: number): Float32Array {
  const rgba = new Float32Array(width * height * 4);
  gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
  gl.readPixels(x, y, width, height, gl.RGBA, gl.FLOAT, rgba);
  countReadBack(gl, rgba.byteLength);
  return rgba;
}

/** Read a target back as RGB floats (3 per texel), row j = 0 first. */
export function readRgb(gl: WebGL2RenderingContext, target: FloatTarget): Float32Array {
  const rgba = readRgba(gl, target);
  const rgb = new Float32Array(target.width * target.height * 3);
  for (let i = 0; i < target.width * target.height; i++) {
    rgb[i * 3] = rgba[i * 4];
    rgb[i * 3 + 1] = rgba[i * 4 + 1];
    rgb[i * 3 + 2] = rgba[i * 4 + 2];
  }
  return rgb;
}
