/** Float data texture (R32F profile tables, RGBA32F patch lists), read with texelFetch only. */
export function createDataTexture(gl: WebGL2RenderingContext, data: Float32Array, width: number, rows: number, channels: 1 | 4 = 1): WebGLTexture {
  const texture = gl.createTexture();
  if (!texture) throw new Error('WebGL: out of resources creating a data texture');
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
  if (channels === 4) gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, rows, 0, gl.RGBA, gl.FLOAT, data);
  else gl.texImage2D(gl.TEXTURE_2D, 0, gl.R32F, width, rows, 0, gl.RED, gl.FLOAT, data);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  return texture;
}
