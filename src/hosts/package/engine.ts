// The package's headless door, `luxbox/engine` (docs/package.md): photometry parsing, lighting
// scenes, configurations to lighting scenes, the WebGL2 baker and the relight engine, for people
// building their own viewer. No UI, no React; a WebGL2 context (a canvas's, or headless-gl's in
// Node) is the caller's.
export * from '../../core/photometry';
export type { LightingScene, LightingRoom, LightingLuminaire, LightingObject, SurfaceName, Rgb, Vec3, Reflectance, NearField } from '../../core/model/lightingScene/lightingScene';
export { SURFACE_NAMES } from '../../core/model/lightingScene/lightingScene';
export { parseLightingScene, LightingSceneError, LIGHTING_SCENE_VERSION } from '../../core/model/lightingScene/parseLightingScene';
export { parseCatalog, CatalogError, type Catalog } from '../../core/model/catalogSchema/catalogSchema';
export { configurationFromData, deserializeConfiguration, serializeConfiguration } from '../../core/model/files/sceneFile';
import { installRoomShapeSupport } from '../../core/model/configuration/roomShapeSupport';
import { roomShapeSupportChunk } from '../../core/model/actions/roomShapeChunk';
// A headless door has no first screen to keep small: rooms of any shape are read and judged from the start (roomShapeSupport.ts).
installRoomShapeSupport(roomShapeSupportChunk);
export { SceneFileError } from '../../core/model/files/sceneFileError';
export { toLightingScene, type ToLightingSceneOptions } from '../../core/model/files/toLightingScene';
export type { Configuration } from '../../core/model/configuration/configuration';
export { InputError } from '../../core/inputError';
export { createBaker, type BakeJob, type BakeProgress, type BakeReport, type Baker } from '../../engines/bake/createBaker';
export type { BakeScene, BakeLuminaire, BakeObject } from '../../engines/bake/bakeScene';
export { resolveBakeScene, resolveBakeSceneSync, LuminairePhotometryError, SceneObjectError, type LoadMesh } from '../../engines/bake/resolveBakeScene';
export { DEFAULT_BAKE_SETTINGS, resolveBakeSettings, type BakeSettings } from '../../engines/bake/bakeSettings';
export { luxOf, combineMaps, LUMINANCE_WEIGHTS, type BakedMaps, type SurfaceMaps, type ObjectMaps } from '../../engines/bake/bakedMaps';
export { createRelightEngine, VIEWER_BAKE_SETTINGS, type RelightEngineOptions } from '../../engines/relight/createRelightEngine';
export type { RelightEngine, EngineProgress, EngineCounters, EngineFade, RelightParts, SetSceneResult, DaylightCacheStatus } from '../../engines/relight/RelightEngine';
export type { LightSources } from '../../engines/relight/daylightGroups';
export type { TriangleMesh } from '../../core/mesh/triangleMesh';
