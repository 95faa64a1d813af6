/** GPU → CPU read-backs made on one WebGL context, and the bytes they moved. */
export interface ReadBackCount {
  count: number;
  bytes: number;
}

const counts = new WeakMap<WebGL2RenderingContext, ReadBackCount>();

/**
 * The baker's read-backs on `gl`, counted where they happen: every readPixels of the baker goes
 * through floatTarget.readRgbaRect, which calls countReadBack (the baker makes no
 * getBufferSubData). A live object: copy it to keep a value.
 */
export function readBacks(gl: WebGL2RenderingContext): ReadBackCount {
  let c = counts.get(gl);
  if (!c) {
    c = { count: 0, bytes: 0 };
    counts.set(gl, c);
  }
  return c;
}

/** Count one read-back of `bytes` on `gl`. */
export function countReadBack(gl: WebGL2RenderingContext, bytes: number): void {
  const c = readBacks(gl);
  c.count++;
  c.bytes += bytes;
}
