import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { Photometry } from '../../core/photometry/types';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { QualityLevel } from '../../engines/relight/qualityLevels';
import { createBakeService, type BakeService } from '../../engines/view/createBakeService';
import type { Fixtures } from '../../engines/view/fixtures';
import type { PhotometryNote } from '../shared/PhotometryWarnings';
import { feedConfiguration, type FeedState } from './bakeFeedSteps';
import { deviceQuality } from './deviceQuality';

/** A configuration resolved for the baker, with what the view draws and shows next to it. */
export interface ResolvedScene {
  bake: BakeScene;
  config: Configuration;
  catalog: Catalog;
  fixtures: Fixtures;
  /** Module id per luminaire (the live overlay addresses modules by id). */
  ids: readonly string[];
  /** Each photometric file in use once, with its warnings (docs/photometry.md, "Warnings"). */
  notes: PhotometryNote[];
}

/** The bake service fed with the store's configuration (the lazily loaded part of the bake host). */
export interface BakeFeed {
  readonly service: BakeService;
  /** The last configuration resolved and handed to the service (null before the first). */
  latest(): ResolvedScene | null;
  /** Why the last configuration could not be resolved (a photometric file, an object's mesh), or null. */
  error(): string | null;
  /** Called after every resolved configuration or failure. */
  subscribe(listener: () => void): () => void;
  /** True while the newest configuration is still being resolved (the service bakes an older one, or none). */
  pending(): boolean;
  dispose(): void;
}

/**
 * Starts the bake service and keeps feeding it the store's configuration: every change is turned
 * into a lighting scene (toLightingScene), resolved with the page's photometry loader and the
 * configuration's own meshes (configurationMeshLoader) and handed over, so the light is baked in
 * the background while the plan is on screen. With no level chosen (`'device'`) the level comes
 * from the device's calibration (deviceQuality). A slower resolve of an older configuration never
 * overwrites a newer one. Its steps (bakeFeedSteps.ts) share one FeedState.
 */
export function startBakeFeed(store: ConfiguratorStore, loadPhotometry: (path: string) => Promise<Photometry>, quality: QualityLevel | 'device', remember = false): BakeFeed {
  // 'device': neither the page nor the user chose a level; fit one to this device.
  const service = createBakeService({ quality: quality === 'device' ? deviceQuality(remember) : quality });
  const s: FeedState = { service, loadPhotometry, listeners: new Set(), latest: null, error: null, sequence: 0, settled: 0, disposed: false };

  let last = store.getState();
  feedConfiguration(s, last.config, last.catalog);
  const unsubscribe = store.subscribe((next) => {
    if (next.config === last.config && next.catalog === last.catalog) return;
    last = next;
    feedConfiguration(s, next.config, next.catalog);
  });

  return {
    service,
    latest: () => s.latest,
    error: () => s.error,
    pending: () => s.settled !== s.sequence,
    subscribe(listener) {
      s.listeners.add(listener);
      return () => s.listeners.delete(listener);
    },
    dispose() {
      s.disposed = true;
      unsubscribe();
      s.listeners.clear();
      service.dispose();
    },
  };
}
