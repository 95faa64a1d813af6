/**
 * Shorter compile-error output (glResources.ts compileErrorExcerpt, after three.js's WebGLProgram.js
 * handleSource: the error line, five lines before and six after it, the error line marked `>`) on a real headless-gl
 * compile failure, and programsReady (KHR_parallel_shader_compile's COMPLETION_STATUS_KHR where present).
 */
import { describe, expect, it } from 'vitest';
import { compileErrorExcerpt, getProgram, programsReady, startPrograms } from '../../../src/engines/bake/glResources';
import { fragmentHeader } from '../../../shaders/fullscreen.glsl';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();

/** A 40-line fragment shader whose line 25 uses an undeclared name. */
function brokenSource(): string {
  const lines = fragmentHeader.trimEnd().split('\n');
  lines.push('out vec4 colour;');
  while (lines.length < 22) lines.push(`// filler line ${lines.length + 1}`);
  lines.push('void main() {', '  float a = 1.0;', '  colour = vec4(undeclaredName);', '}');
  while (lines.length < 40) lines.push(`// trailing line ${lines.length + 1}`);
  return lines.join('\n');
}

describe('compile errors', () => {
  it('name the stage, keep the driver log and show lines 20–31 with line 25 marked (three.js: 5 before, 6 after)', () => {
    const source = brokenSource();
    let message = '';
    try {
      getProgram(gl, source);
    } catch (error) {
      message = (error as Error).message;
    }
    expect(message).toMatch(/^GLSL compile error \(fragment\): ERROR: 0:25: 'undeclaredName' : undeclared identifier/);
    const shown = message.split('\n').filter((l) => /^[> ] \d+: /.test(l));
    expect(shown.map((l) => Number(/\d+/.exec(l)![0]))).toEqual([20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31]);
    expect(shown.filter((l) => l.startsWith('>'))).toEqual(['> 25:   colour = vec4(undeclaredName);']);
    // The failed program is not cached: asking again compiles again and fails again.
    expect(() => getProgram(gl, source)).toThrow(/undeclared identifier/);
  });

  it('clip the window at the ends of the source, and show the first lines for a log without a line', () => {
    const source = Array.from({ length: 9 }, (_, i) => `line ${i + 1}`).join('\n');
    expect(compileErrorExcerpt(source, 'ERROR: 0:2: boom').split('\n')).toEqual(['  1: line 1', '> 2: line 2', '  3: line 3', '  4: line 4', '  5: line 5', '  6: line 6', '  7: line 7', '  8: line 8']);
    expect(compileErrorExcerpt(source, 'ERROR: 0:9: boom').split('\n')[0]).toBe('  4: line 4');
    expect(compileErrorExcerpt(source, 'link failed').split('\n')).toHaveLength(9);
  });
});

describe('programsReady', () => {
  it('is false for a source never started and true once its program exists (no KHR_parallel_shader_compile in headless-gl: nothing to poll)', () => {
    const source = `${fragmentHeader}out vec4 colour;\nvoid main() { colour = vec4(0.25); }\n`;
    expect(gl.getExtension('KHR_parallel_shader_compile')).toBeNull();
    expect(programsReady(gl, [source])).toBe(false);
    startPrograms(gl, [source]);
    expect(programsReady(gl, [source])).toBe(true);
    getProgram(gl, source);
    expect(programsReady(gl, [source])).toBe(true);
  });
});
