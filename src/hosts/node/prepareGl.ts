import { activateGlBackend, GL_BACKEND_ENV, parseGlChoice, selectGlBackend, type GlBackend } from './glBackend';
import { ensureDisplay } from './ensureDisplay';

/**
 * Before a command makes its first WebGL context: choose the back end
 * (`--gl` flag, else $LUXBOX_GL, else auto), point ANGLE at it, and for GLX
 * make sure there is an X display. `exit` is non-null when this process
 * re-ran itself under xvfb-run and the caller should return that exit code.
 */
export function prepareGl(flag: string | undefined): { exit: number | null; backend: GlBackend } {
  const choice = flag !== undefined ? parseGlChoice(flag, '--gl') : parseGlChoice(process.env[GL_BACKEND_ENV], `$${GL_BACKEND_ENV}`);
  const { backend } = selectGlBackend(choice);
  activateGlBackend(backend);
  return { exit: backend === 'glx' ? ensureDisplay() : null, backend };
}
