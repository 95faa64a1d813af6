import { loadColourFilterSpectra } from '../../core/colour/colourFilterSpectra';
import { needsColourFilterSpectra } from '../../core/colour/moduleColour';
import { configurationFilterIds } from '../../core/model/modules/moduleFilter';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { LightingScene } from '../../core/model/lightingScene/lightingScene';
import { toLightingScene } from '../../core/model/files/toLightingScene';
import { photometryWarnings } from '../../core/photometry/checks';
import type { Photometry } from '../../core/photometry/types';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { LuminairePhotometryError, resolveBakeScene, SceneObjectError } from '../../engines/bake/resolveBakeScene';
import { configurationMeshLoader } from '../../engines/view/configurationMeshLoader';
import type { BakeService } from '../../engines/view/createBakeService';
import { fixturesFromConfiguration } from '../../engines/view/fixtures';
import { withModelOpenings } from '../../engines/view/modelOpenings';
import { loadModelBodies } from '../shared/loadModelBodies';
import type { PhotometryNote } from '../shared/PhotometryWarnings';
import type { ResolvedScene } from './startBakeFeed';

/** What the feed's steps share: the service, the listeners, the last result and the order of the configurations. */
export interface FeedState {
  service: BakeService;
  loadPhotometry: (path: string) => Promise<Photometry>;
  listeners: Set<() => void>;
  latest: ResolvedScene | null;
  error: string | null;
  sequence: number;
  /** The sequence number of the newest configuration resolved or refused. */
  settled: number;
  disposed: boolean;
}

export function notifyFeed(s: FeedState): void {
  for (const l of [...s.listeners]) l();
}

/** Whether configuration `n` is still the newest and the feed still runs: only then may its result land. */
const current = (s: FeedState, n: number) => n === s.sequence && !s.disposed;

/** Configuration `n` could not be fed: its error is shown (unless a newer one came). */
function refuse(s: FeedState, n: number, error: string): void {
  if (!current(s, n)) return;
  s.settled = n;
  s.error = error;
  notifyFeed(s);
}

/** A new configuration: resolved and handed to the service, once the colour filters' spectra are in where it needs them. */
export function feedConfiguration(s: FeedState, config: Configuration, catalog: Catalog): void {
  const n = ++s.sequence;
  // A filter's colour needs the spectra (loaded on first need): wait for them, then feed this configuration unless a newer one came.
  if (needsColourFilterSpectra(configurationFilterIds(config))) {
    loadColourFilterSpectra().then(
      () => {
        if (current(s, n)) feedConfiguration(s, config, catalog);
      },
      (e: Error) => refuse(s, n, `Could not load the colour filters' spectra: ${e.message}`),
    );
    return;
  }
  const scene = toLightingScene(config, catalog);
  // Objects' meshes come from the configuration itself (`object:<id>`, with their finishes); L3D bodies from the asset folder.
  Promise.all([resolveBakeScene(scene, s.loadPhotometry, configurationMeshLoader(config)), loadModelBodies(s.loadPhotometry, config, catalog)])
    .then(([resolved, bodies]) => {
      if (!current(s, n)) return;
      s.settled = n;
      // An L3D body's light-emitting object is the near field's opening (docs/gldf.md "The L3D's opening in the near field").
      const bake = withModelOpenings(
        resolved,
        scene.luminaires.map((l) => l.id ?? ''),
        config,
        catalog,
        bodies,
      );
      s.latest = resolvedScene(scene, bake, config, catalog, bodies);
      s.error = null;
      s.service.setScene(bake);
      notifyFeed(s);
    })
    .catch((e: Error) => {
      // The loader's own message names the file ("ies/a.ies: HTTP 404"); which luminaire asked is no news to the user.
      if (e instanceof SceneObjectError) refuse(s, n, `Could not prepare the furniture for the light calculation: ${e.message}`);
      else refuse(s, n, `Could not load the photometric data: ${e instanceof LuminairePhotometryError && e.cause instanceof Error ? e.cause.message : e.message}`);
    });
}

/** What the view draws and shows next to a baked scene: its fixtures, the module ids and each photometric file's warnings once. */
function resolvedScene(scene: LightingScene, bake: BakeScene, config: Configuration, catalog: Catalog, bodies: Awaited<ReturnType<typeof loadModelBodies>>): ResolvedScene {
  const files = new Map<string, PhotometryNote>();
  scene.luminaires.forEach((l, i) => {
    if (!files.has(l.photometry)) files.set(l.photometry, { file: l.photometry, warnings: photometryWarnings(bake.luminaires[i].photometry) });
  });
  return {
    bake,
    config,
    catalog,
    fixtures: fixturesFromConfiguration(config, catalog, new Map(scene.luminaires.map((l, i) => [l.id ?? '', bake.luminaires[i]])), bodies),
    ids: scene.luminaires.map((l) => l.id ?? ''),
    notes: [...files.values()],
  };
}
