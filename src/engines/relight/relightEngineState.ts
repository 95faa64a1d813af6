import type { BakeScene } from '../bake/bakeScene';
import type { BakeSettings } from '../bake/bakeSettings';
import type { Baker } from '../bake/createBaker';
import type { ObjectAtlas } from '../bake/objects/preparedObjects';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import type { DaylightBasisCache } from './daylightBasisCache';
import type { LightSources } from './daylightGroups';
import type { DirectBasisQueue } from './directBasisQueue';
import type { GroupState } from './groupState';
import type { IndirectSolver } from './indirectSolver';
import type { LitMaps } from './relightMaps';
import type { EngineCounters, EngineFade } from './RelightEngine';
import type { SolutionCache } from './solutionCache';

/**
 * What the relight engine's parts share (createRelightEngine.ts builds it; setEngineScene.ts,
 * engineWeights.ts, engineSolve.ts and composeRelight.ts read and change it): the scene, its
 * groups (luminaire groups, then the daylight groups) and their bases, the solves, the maps shown.
 */
export interface RelightEngineState {
  readonly settings: BakeSettings;
  readonly baker: Baker;
  readonly counters: EngineCounters;
  readonly cache: SolutionCache;
  readonly solver: IndirectSolver;
  readonly bases: DirectBasisQueue;
  /** Daylight bases of groups that left the scene, kept for their return (daylightBasisCache.ts). */
  readonly daylightCache: DaylightBasisCache;
  /** The scene as last given (setLightSources sets it again when the daylight factor's basis comes or goes). */
  given: BakeScene | null;
  /** The scene as baked (a shaped room enclosed). */
  scene: BakeScene | null;
  /** The room's and objects' key: another one drops every basis. */
  room: string;
  layouts: SurfaceLayout[];
  atlas: ObjectAtlas | null;
  states: Map<string, GroupState>;
  /** The scene's groups in order: its luminaire groups, then its daylight groups (daylightGroups.ts). */
  order: GroupState[];
  fade: EngineFade | null;
  /** Which light is shown (weights: electric, daylight or both). */
  sources: LightSources;
  out: LitMaps | null;
  /** Bumps whenever the maps shown would change. */
  version: number;
  composedVersion: number;
}
