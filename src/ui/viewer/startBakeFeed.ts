import { loadColourFilterSpectra } from '../../core/colour/colourFilterSpectra';
import { needsColourFilterSpectra } from '../../core/colour/moduleColour';
import { configurationFilterIds } from '../../core/model/modules/moduleFilter';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import { toLightingScene } from '../../core/model/files/toLightingScene';
import { photometryWarnings } from '../../core/photometry/checks';
import type { Photometry } from '../../core/photometry/types';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { LuminairePhotometryError, resolveBakeScene, SceneObjectError } from '../../engines/bake/resolveBakeScene';
import type { QualityLevel } from '../../engines/relight/qualityLevels';
import { configurationMeshLoader } from '../../engines/view/configurationMeshLoader';
import { createBakeService, type BakeService } from '../../engines/view/createBakeService';
import { fixturesFromConfiguration, type Fixtures } from '../../engines/view/fixtures';
import { withModelOpenings } from '../../engines/view/modelOpenings';
import { loadModelBodies } from '../shared/loadModelBodies';
import type { PhotometryNote } from '../shared/PhotometryWarnings';
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
 * overwrites a newer one.
 */
export function startBakeFeed(store: ConfiguratorStore, loadPhotometry: (path: string) => Promise<Photometry>, quality: QualityLevel | 'device', remember = false): BakeFeed {
  // 'device': neither the page nor the user chose a level; fit one to this device.
  const service = createBakeService({ quality: quality === 'device' ? deviceQuality(remember) : quality });
  const listeners = new Set<() => void>();
  const notify = () => {
    for (const l of [...listeners]) l();
  };
  let latest: ResolvedScene | null = null;
  let error: string | null = null;
  let sequence = 0;
  /** The sequence number of the newest configuration resolved or refused. */
  let settled = 0;
  let disposed = false;

  const feed = (config: Configuration, catalog: Catalog) => {
    const n = ++sequence;
    // A filter's colour needs the spectra (loaded on first need): wait for them, then feed this configuration unless a newer one came.
    if (needsColourFilterSpectra(configurationFilterIds(config))) {
      loadColourFilterSpectra().then(
        () => {
          if (n === sequence && !disposed) feed(config, catalog);
        },
        (e: Error) => {
          if (n !== sequence || disposed) return;
          settled = n;
          error = `Could not load the colour filters' spectra: ${e.message}`;
          notify();
        },
      );
      return;
    }
    const scene = toLightingScene(config, catalog);
    // Objects' meshes come from the configuration itself (`object:<id>`, with their finishes); L3D bodies from the asset folder.
    Promise.all([resolveBakeScene(scene, loadPhotometry, configurationMeshLoader(config)), loadModelBodies(loadPhotometry, config, catalog)])
      .then(([resolved, bodies]) => {
        if (n !== sequence || disposed) return;
        settled = n;
        // An L3D body's light-emitting object is the near field's opening (docs/gldf.md "The L3D's opening in the near field").
        const bake = withModelOpenings(
          resolved,
          scene.luminaires.map((l) => l.id ?? ''),
          config,
          catalog,
          bodies,
        );
        const files = new Map<string, PhotometryNote>();
        scene.luminaires.forEach((l, i) => {
          if (!files.has(l.photometry)) files.set(l.photometry, { file: l.photometry, warnings: photometryWarnings(bake.luminaires[i].photometry) });
        });
        latest = {
          bake,
          config,
          catalog,
          fixtures: fixturesFromConfiguration(config, catalog, new Map(scene.luminaires.map((l, i) => [l.id ?? '', bake.luminaires[i]])), bodies),
          ids: scene.luminaires.map((l) => l.id ?? ''),
          notes: [...files.values()],
        };
        error = null;
        service.setScene(bake);
        notify();
      })
      .catch((e: Error) => {
        if (n !== sequence || disposed) return;
        settled = n;
        // The loader's own message names the file ("ies/a.ies: HTTP 404"); which luminaire asked is no news to the user.
        if (e instanceof SceneObjectError) error = `Could not prepare the furniture for the light calculation: ${e.message}`;
        else error = `Could not load the photometric data: ${e instanceof LuminairePhotometryError && e.cause instanceof Error ? e.cause.message : e.message}`;
        notify();
      });
  };

  let last = store.getState();
  feed(last.config, last.catalog);
  const unsubscribe = store.subscribe((s) => {
    if (s.config === last.config && s.catalog === last.catalog) return;
    last = s;
    feed(s.config, s.catalog);
  });

  return {
    service,
    latest: () => latest,
    error: () => error,
    pending: () => settled !== sequence,
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    dispose() {
      disposed = true;
      unsubscribe();
      listeners.clear();
      service.dispose();
    },
  };
}
