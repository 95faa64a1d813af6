import { InputError } from '../../core/inputError';
import type { LightingScene } from '../../core/model/lightingScene';
import type { Photometry } from '../../core/photometry/types';
import type { BakeLuminaire, BakeScene } from './bakeScene';

/**
 * A luminaire whose photometric file could not be loaded: names the first
 * luminaire that uses the file and the file; `cause` is the loader's error
 * (PhotometryReadError or PhotometryParseError), which hosts may show as is.
 */
export class LuminairePhotometryError extends InputError {
  override name = 'LuminairePhotometryError';
  readonly luminaire: number;
  readonly path: string;
  override readonly cause: unknown;

  constructor(luminaire: number, path: string, cause: unknown) {
    const problem = cause instanceof Error ? cause.message : String(cause);
    // The loaders' errors already name the file; say it once.
    super(problem.includes(path) ? `luminaires[${luminaire}].photometry: ${problem}` : `luminaires[${luminaire}].photometry: ${path}: ${problem}`);
    this.luminaire = luminaire;
    this.path = path;
    this.cause = cause;
  }
}

/**
 * A lighting scene as the baker takes it: each distinct photometry path loaded
 * once (in the order luminaires first use it), dimming and colour defaults
 * filled in (1 and white), the scene's near-field model kept. The loader is
 * the host's (createPhotometryLoader): with an asynchronous one the result is
 * a promise, with a synchronous one (Node) it is the scene itself. A failure
 * is a LuminairePhotometryError.
 */
export function resolveBakeScene(scene: LightingScene, loadPhotometry: (path: string) => Promise<Photometry>): Promise<BakeScene>;
export function resolveBakeScene(scene: LightingScene, loadPhotometry: (path: string) => Photometry): BakeScene;
export function resolveBakeScene(scene: LightingScene, loadPhotometry: (path: string) => Photometry | Promise<Photometry>): BakeScene | Promise<BakeScene> {
  const firstUse = new Map<string, number>();
  scene.luminaires.forEach((l, i) => {
    if (!firstUse.has(l.photometry)) firstUse.set(l.photometry, i);
  });
  const paths = [...firstUse.keys()];
  const loaded = paths.map((path) => {
    const fail = (error: unknown): never => {
      throw new LuminairePhotometryError(firstUse.get(path)!, path, error);
    };
    try {
      const result = loadPhotometry(path);
      return result instanceof Promise ? result.catch(fail) : result;
    } catch (error) {
      return fail(error);
    }
  });
  const build = (photometries: Photometry[]): BakeScene => {
    const byPath = new Map(paths.map((path, k) => [path, photometries[k]]));
    const luminaires = scene.luminaires.map(
      (l): BakeLuminaire => ({ photometry: byPath.get(l.photometry)!, position: l.position, yaw: l.yaw, pitch: l.pitch, roll: l.roll, dimming: l.dimming ?? 1, color: l.color ?? [1, 1, 1] }),
    );
    return { room: scene.room, luminaires, ...(scene.nearField ? { nearField: scene.nearField } : {}) };
  };
  if (loaded.some((p) => p instanceof Promise)) return Promise.all(loaded).then(build);
  return build(loaded as Photometry[]);
}
