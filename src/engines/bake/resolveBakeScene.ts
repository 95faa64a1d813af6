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

/** Each distinct photometry path with the first luminaire that uses it, in first-use order. */
function firstUses(scene: LightingScene): Map<string, number> {
  const firstUse = new Map<string, number>();
  scene.luminaires.forEach((l, i) => {
    if (!firstUse.has(l.photometry)) firstUse.set(l.photometry, i);
  });
  return firstUse;
}

function buildBakeScene(scene: LightingScene, byPath: ReadonlyMap<string, Photometry>): BakeScene {
  const luminaires = scene.luminaires.map(
    (l): BakeLuminaire => ({ photometry: byPath.get(l.photometry)!, position: l.position, yaw: l.yaw, pitch: l.pitch, roll: l.roll, dimming: l.dimming ?? 1, color: l.color ?? [1, 1, 1] }),
  );
  return { room: scene.room, luminaires, ...(scene.nearField ? { nearField: scene.nearField } : {}) };
}

/**
 * A lighting scene as the baker takes it: each distinct photometry path loaded
 * once (in the order luminaires first use it), dimming and colour defaults
 * filled in (1 and white), the scene's near-field model kept. The loader is
 * the host's (createPhotometryLoader; the browser's fetches). Always a promise,
 * also for a scene without luminaires. A failure is a LuminairePhotometryError.
 */
export async function resolveBakeScene(scene: LightingScene, loadPhotometry: (path: string) => Photometry | Promise<Photometry>): Promise<BakeScene> {
  const firstUse = firstUses(scene);
  const paths = [...firstUse.keys()];
  const photometries = await Promise.all(
    paths.map(async (path) => {
      try {
        return await loadPhotometry(path);
      } catch (error) {
        throw new LuminairePhotometryError(firstUse.get(path)!, path, error);
      }
    }),
  );
  return buildBakeScene(scene, new Map(paths.map((path, k) => [path, photometries[k]])));
}

/** resolveBakeScene for a synchronous loader (Node reads files synchronously): the scene itself, or a thrown LuminairePhotometryError. */
export function resolveBakeSceneSync(scene: LightingScene, loadPhotometry: (path: string) => Photometry): BakeScene {
  const byPath = new Map<string, Photometry>();
  for (const [path, luminaire] of firstUses(scene)) {
    try {
      byPath.set(path, loadPhotometry(path));
    } catch (error) {
      throw new LuminairePhotometryError(luminaire, path, error);
    }
  }
  return buildBakeScene(scene, byPath);
}
