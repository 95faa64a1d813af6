import { InputError } from '../../core/inputError';
import type { LightingScene } from '../../core/model/lightingScene/lightingScene';
import type { Photometry } from '../../core/photometry/types';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import { positionBounds } from '../../core/mesh/triangleMesh';
import { firstNonFiniteVertex, placedPositions } from '../../core/mesh/placeMesh';
import { OBJECT_ROOM_TOLERANCE } from '../../core/model/lightingScene/parseLightingScene';
import type { BakeLuminaire, BakeObject, BakeScene } from './bakeScene';
import { bakeDaylightOf, darkWindowsOf } from './daylight/sceneDaylight';

/** Loads an object's mesh by the path the scene gives (Node: an OBJ/glTF file relative to the scene file; the app: `object:<id>`). */
export type LoadMesh = (path: string) => TriangleMesh | Promise<TriangleMesh>;

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
 * An object of the scene whose mesh could not be loaded, or whose placed mesh leaves the room:
 * the message starts with `objects[i]`; `cause` is the loader's error for a load failure.
 */
export class SceneObjectError extends InputError {
  override name = 'SceneObjectError';
  readonly object: number;
  override readonly cause: unknown;

  constructor(object: number, message: string, cause?: unknown) {
    super(`objects[${object}]${message}`);
    this.object = object;
    this.cause = cause;
  }
}

function meshLoadError(object: number, path: string, cause: unknown): SceneObjectError {
  const problem = cause instanceof Error ? cause.message : String(cause);
  return new SceneObjectError(object, `.mesh: ${problem.includes(path) || problem.includes(path.split(/[\\/]/).pop()!) ? problem : `${path}: ${problem}`}`, cause);
}

/** Each distinct mesh path with the first object that uses it, in first-use order. */
function firstMeshUses(scene: LightingScene): Map<string, number> {
  const firstUse = new Map<string, number>();
  (scene.objects ?? []).forEach((o, i) => {
    if (!firstUse.has(o.mesh)) firstUse.set(o.mesh, i);
  });
  return firstUse;
}

const ROOM_SIDES = [
  ['west wall (x = 0)', 'east wall (x = %)', 'wide'],
  ['floor (y = 0)', 'ceiling (y = %)', 'high'],
  ['north wall (z = 0)', 'south wall (z = %)', 'deep'],
] as const;

/**
 * The scene's objects with their meshes, each placed mesh checked against the room: one that
 * reaches more than OBJECT_ROOM_TOLERANCE beyond a surface is a SceneObjectError saying where
 * and by how much (docs/scene-format.md, "Objects").
 */
function buildObjects(scene: LightingScene, byPath: ReadonlyMap<string, TriangleMesh>): BakeObject[] {
  const dims = [scene.room.width, scene.room.height, scene.room.depth];
  // A room of any shape: its outline's bounding box, wherever its minimum corner lies (issue 29).
  const shape = scene.room.shape;
  const origin = shape ? [Math.min(...shape.corners.map((c) => c[0])), 0, Math.min(...shape.corners.map((c) => c[1]))] : [0, 0, 0];
  return (scene.objects ?? []).map((o, i): BakeObject => {
    const mesh = byPath.get(o.mesh)!;
    const placement = { position: o.position, yaw: o.yaw, scale: o.scale };
    const placed = placedPositions(mesh, placement);
    const bad = firstNonFiniteVertex(placed);
    if (bad >= 0) {
      throw new SceneObjectError(i, `: placed vertex ${bad} is not finite (position [${o.position.join(', ')}], yaw ${o.yaw}, scale ${o.scale} put it beyond any number)`);
    }
    const { min, max } = positionBounds(placed);
    for (let a = 0; a < 3; a++) {
      const below = origin[a] - min[a];
      const above = max[a] - origin[a] - dims[a];
      const [low, high, extent] = ROOM_SIDES[a];
      // Written so that NaN fails (a comparison with NaN is false): issue 32.
      if (!(below <= OBJECT_ROOM_TOLERANCE) || !(above <= OBJECT_ROOM_TOLERANCE)) {
        const side = below >= above ? low : high.replace('%', `${dims[a]} m`);
        const by = Math.max(below, above);
        throw new SceneObjectError(i, `: the placed mesh reaches ${by.toPrecision(3)} m beyond the ${side} (the room is ${dims[a]} m ${extent}); objects must be inside the room (${OBJECT_ROOM_TOLERANCE * 100} cm tolerance)`);
      }
    }
    return { id: o.id ?? `objects[${i}]`, mesh, ...placement, ...(o.reflectance !== undefined ? { reflectance: o.reflectance } : {}) };
  });
}

/** Each distinct photometry path with the first luminaire that uses it, in first-use order. */
function firstUses(scene: LightingScene): Map<string, number> {
  const firstUse = new Map<string, number>();
  scene.luminaires.forEach((l, i) => {
    if (!firstUse.has(l.photometry)) firstUse.set(l.photometry, i);
  });
  return firstUse;
}

function buildBakeScene(scene: LightingScene, byPath: ReadonlyMap<string, Photometry>, meshes: ReadonlyMap<string, TriangleMesh>): BakeScene {
  const luminaires = scene.luminaires.map((l): BakeLuminaire => ({ photometry: byPath.get(l.photometry)!, position: l.position, yaw: l.yaw, pitch: l.pitch, roll: l.roll, dimming: l.dimming ?? 1, color: l.color ?? [1, 1, 1] }));
  const objects = buildObjects(scene, meshes);
  // Windows without a sky still carry their glazing and ground (the panes at night, the daylight factor after sunset).
  const daylight = bakeDaylightOf(scene)?.daylight ?? darkWindowsOf(scene);
  return { room: scene.room, luminaires, ...(objects.length > 0 ? { objects } : {}), ...(scene.nearField ? { nearField: scene.nearField } : {}), ...(daylight ? { daylight } : {}) };
}

function requireLoader(scene: LightingScene, loadMesh: LoadMesh | undefined): LoadMesh {
  if (loadMesh) return loadMesh;
  return (path) => {
    throw new SceneObjectError(firstMeshUses(scene).get(path) ?? 0, `.mesh: ${path}: this host loads no meshes`);
  };
}

/**
 * A lighting scene as the baker takes it: each distinct photometry path loaded
 * once (in the order luminaires first use it), dimming and colour defaults
 * filled in (1 and white), the scene's near-field model kept; each distinct
 * object mesh loaded once through `loadMesh`, objects given their id (`id`, else
 * `objects[i]`) and checked inside the room. The loaders are the host's
 * (createPhotometryLoader; the browser's fetches; Node's mesh importer, the
 * app's `object:<id>` resolver). Always a promise, also for a scene without
 * luminaires. A failure is a LuminairePhotometryError or a SceneObjectError.
 */
export async function resolveBakeScene(scene: LightingScene, loadPhotometry: (path: string) => Photometry | Promise<Photometry>, loadMesh?: LoadMesh): Promise<BakeScene> {
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
  const meshUses = firstMeshUses(scene);
  const meshPaths = [...meshUses.keys()];
  const load = requireLoader(scene, loadMesh);
  const meshes = await Promise.all(
    meshPaths.map(async (path) => {
      try {
        return await load(path);
      } catch (error) {
        throw meshLoadError(meshUses.get(path)!, path, error);
      }
    }),
  );
  return buildBakeScene(scene, new Map(paths.map((path, k) => [path, photometries[k]])), new Map(meshPaths.map((path, k) => [path, meshes[k]])));
}

/** resolveBakeScene for synchronous loaders (Node reads files synchronously): the scene itself, or a thrown LuminairePhotometryError or SceneObjectError. */
export function resolveBakeSceneSync(scene: LightingScene, loadPhotometry: (path: string) => Photometry, loadMesh?: (path: string) => TriangleMesh): BakeScene {
  const byPath = new Map<string, Photometry>();
  for (const [path, luminaire] of firstUses(scene)) {
    try {
      byPath.set(path, loadPhotometry(path));
    } catch (error) {
      throw new LuminairePhotometryError(luminaire, path, error);
    }
  }
  const meshes = new Map<string, TriangleMesh>();
  const load = requireLoader(scene, loadMesh);
  for (const [path, object] of firstMeshUses(scene)) {
    let mesh: TriangleMesh | Promise<TriangleMesh>;
    try {
      mesh = load(path);
    } catch (error) {
      throw meshLoadError(object, path, error);
    }
    if (mesh instanceof Promise) throw new Error('resolveBakeSceneSync: loadMesh returned a promise; use resolveBakeScene');
    meshes.set(path, mesh);
  }
  return buildBakeScene(scene, byPath, meshes);
}
