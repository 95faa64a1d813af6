import { afterAll } from 'vitest';
import { createHeadlessGL } from '../../../src/hosts/node/createHeadlessGL';

/** One headless-gl WebGL2 context per test file (vitest forks: one process per file), destroyed after it. */
export function withHeadlessGL(): WebGL2RenderingContext {
  const gl = createHeadlessGL();
  afterAll(() => gl.destroy());
  return gl;
}
