import type { Photometry } from '../../core/photometry/types';
import { DEFAULT_ADAPTATION, type AdaptationSetting } from '../../engines/view/adaptationSetting';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { QualityLevel } from '../../engines/relight/qualityLevels';
import type { ExposureSetting } from '../../engines/view/photographicExposure';
import type { BakeStatus } from '../../engines/view/createBakeService';
import type { BakeFeed } from './startBakeFeed';
import { initialQuality, storeQuality } from './qualityPreference';
import { setBakeStatusSource } from './viewerStatus';
import { webglSupportProblem } from './webglSupport';

/**
 * The planner bundle's handle on the 3D bake (docs/viewer.md, "Always ready: the bake service"):
 * tiny, with no baker code of its own. It loads the bake chunk (startBakeFeed: the service and its
 * feed from the store) in idle time once the planner shows, or at once when 3D is opened first,
 * and keeps it until disposed (the configurator destroyed), so the 3D view finds the light
 * already baked.
 */
export interface BakeHost {
  /** Load and start the service when the browser is idle; returns a cancel for a start not yet begun. */
  startWhenIdle(): () => void;
  /** The running feed, starting it now if it has not started. */
  get(): Promise<BakeFeed>;
  /** The running feed, or null (not started or still loading). */
  current(): BakeFeed | null;
  readonly quality: QualityLevel;
  /** How the 3D view starts exposing: 'auto' or a fixed EV100 (embed option `exposure`, docs/viewer.md "Exposure"). */
  readonly exposure: ExposureSetting;
  /** How the 3D view starts adapting to the light's colour (embed option `adapt`, docs/viewer.md "Adaptation"). */
  readonly adaptation: AdaptationSetting;
  /** The user's choice: applied to the running service, and kept in localStorage ('luxbox.quality') when the host allows. */
  setQuality(level: QualityLevel): void;
  dispose(): void;
}

export interface BakeHostOptions {
  /** A quality pinned by the page (URL parameter, embed option): it wins over the stored choice. */
  quality?: QualityLevel | null;
  /** The 3D view's starting exposure: 'auto' (default) or a fixed EV100 (photographicExposure.ts). */
  exposure?: ExposureSetting;
  /** The 3D view's starting chromatic adaptation: eye (default), camera white balance at a CCT, none. */
  adaptation?: AdaptationSetting;
  /** Keep the user's choice and the device calibration in localStorage (the standalone app; default false). */
  remember?: boolean;
  /** requestIdleCallback, or a stand-in (browsers without it: a short timeout). */
  idle?: (callback: () => void) => () => void;
}

const hosts = new WeakMap<object, BakeHost>();

const pageIdle = (callback: () => void): (() => void) => {
  if (typeof requestIdleCallback === 'function') {
    // A timeout so a page that is never idle (a busy shop page) still gets its light.
    const id = requestIdleCallback(callback, { timeout: 3000 });
    return () => cancelIdleCallback(id);
  }
  const id = setTimeout(callback, 300);
  return () => clearTimeout(id);
};

/** Creates the bake host of a configurator store and registers it (bakeHostOf). */
export function createBakeHost(store: ConfiguratorStore, loadPhotometry: (path: string) => Promise<Photometry>, options: BakeHostOptions = {}): BakeHost {
  /** The level asked for ('device': the calibration's, once the service runs). */
  const remember = options.remember === true;
  let quality = initialQuality(options.quality, remember);
  const level = (): QualityLevel => feed?.service.quality ?? (quality === 'device' ? 'balanced' : quality);
  let loading: Promise<BakeFeed> | null = null;
  let feed: BakeFeed | null = null;
  let disposed = false;
  const idle = options.idle ?? pageIdle;

  const get = (): Promise<BakeFeed> => {
    if (!loading) {
      loading = import('./startBakeFeed').then(({ startBakeFeed }) => {
        if (disposed) throw new Error('the configurator was closed');
        feed = startBakeFeed(store, loadPhotometry, quality, remember);
        return feed;
      });
      // A failed chunk download is reported by the 3D view when it asks; a later get() tries again.
      loading.catch(() => {
        if (!feed) loading = null;
      });
    }
    return loading;
  };

  const host: BakeHost = {
    startWhenIdle() {
      if (loading || disposed) return () => undefined;
      return idle(() => {
        // No WebGL2 or float targets: nothing to bake for (the 3D toggle says why), and no chunk to download.
        if (!disposed && !loading && !webglSupportProblem()) get().catch(() => undefined);
      });
    },
    get,
    current: () => feed,
    get quality() {
      return level();
    },
    exposure: options.exposure ?? 'auto',
    adaptation: options.adaptation ?? DEFAULT_ADAPTATION,
    setQuality(next) {
      quality = next;
      if (remember) storeQuality(next);
      feed?.service.setQuality(next);
    },
    dispose() {
      if (disposed) return;
      disposed = true;
      feed?.dispose();
      feed = null;
      if (hosts.get(store) === host) {
        hosts.delete(store);
        setBakeStatusSource(store, null);
      }
    },
  };
  hosts.set(store, host);
  setBakeStatusSource(store, (): BakeStatus => {
    if (!feed) return { running: false, paused: false, done: false, groupBakes: 0, relightsOnly: 0, indirectSolves: 0, restarts: 0, quality: level() };
    const status = feed.service.status();
    // A change still being resolved (photometric files, meshes) is not baked yet: not done, although the
    // service has finished the configuration before it (an empty room placed a moment ago, say).
    return feed.pending() ? { ...status, done: false } : status;
  });
  return host;
}

/** The bake host registered for a store (null: none, e.g. a planner rendered without its configurator). */
export function bakeHostOf(store: ConfiguratorStore): BakeHost | null {
  return hosts.get(store) ?? null;
}

/** The store's bake host, created (nothing pinned or remembered) when there is none. */
export function bakeHostFor(store: ConfiguratorStore, loadPhotometry: (path: string) => Promise<Photometry>): BakeHost {
  return hosts.get(store) ?? createBakeHost(store, loadPhotometry);
}
