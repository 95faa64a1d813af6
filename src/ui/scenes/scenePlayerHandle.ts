import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { RecallResult, ScenePlayer, ScenePlayerOptions, ScenePlayerState } from './createScenePlayer';

/**
 * What the first screen uses of a store's light-scene player (createScenePlayer.ts): the plan
 * reads the fade it shows, the embedding API the scene recalled last and `recall`. The player
 * itself (fades, GO / BACK, the 3D view's crossfade) is a chunk of its own, outside the first
 * screen (docs/benchmarks.md, "First screen"): it comes with the scene panel, on the first recall,
 * or in idle time after the embedding API asked for a handle. Until then nothing has been recalled
 * and nothing fades, which is the state this handle reports.
 */
export interface ScenePlayerHandle {
  getState(): ScenePlayerState;
  subscribe(listener: () => void): () => void;
  /** ScenePlayer.recall: at once when the player is there, else once its chunk has loaded. */
  recall(sceneId: string, options?: { fade?: number }): Promise<RecallResult>;
  dispose(): void;
}

/** One store's player, its options (the first given) and the handle's listeners, which move onto the player when it is made. */
interface Slot {
  options?: ScenePlayerOptions;
  player: ScenePlayer | null;
  readonly listeners: Map<() => void, (() => void) | null>;
  handle?: ScenePlayerHandle;
  disposed?: boolean;
}

const IDLE: ScenePlayerState = { current: null, fading: null };
const slots = new WeakMap<ConfiguratorStore, Slot>();

function slotOf(store: ConfiguratorStore): Slot {
  let slot = slots.get(store);
  if (!slot) slots.set(store, (slot = { player: null, listeners: new Map() }));
  return slot;
}

/**
 * The store's player, made on first use with the options the first caller gave (the embedding
 * host passes the 3D view's feed; the scene panel passes none). Used by createScenePlayer's
 * scenePlayerFor, so the panel, the keys, the API and the plan share one player.
 */
export function playerOf(store: ConfiguratorStore, options: ScenePlayerOptions | undefined, create: (options?: ScenePlayerOptions) => ScenePlayer): ScenePlayer {
  const slot = slotOf(store);
  if (!slot.player) {
    const player = create(options ?? slot.options);
    slot.player = player;
    for (const listener of slot.listeners.keys()) slot.listeners.set(listener, player.subscribe(listener));
  }
  return slot.player;
}

function loadPlayer(store: ConfiguratorStore): Promise<ScenePlayer> {
  return import('./createScenePlayer').then((m) => m.scenePlayerFor(store));
}

/** The store's scene-player handle; `options` (the first given) are those the player is made with. */
export function scenePlayerHandle(store: ConfiguratorStore, options?: ScenePlayerOptions): ScenePlayerHandle {
  const slot = slotOf(store);
  if (options && !slot.options) slot.options = options;
  if (slot.handle) return slot.handle;
  const handle: ScenePlayerHandle = {
    getState: () => slot.player?.getState() ?? IDLE,
    subscribe(listener) {
      slot.listeners.set(listener, slot.player ? slot.player.subscribe(listener) : null);
      return () => {
        slot.listeners.get(listener)?.();
        slot.listeners.delete(listener);
      };
    },
    recall: (sceneId, opts) => (slot.player ? slot.player.recall(sceneId, opts) : loadPlayer(store).then((p) => p.recall(sceneId, opts))),
    dispose() {
      slot.disposed = true;
      slot.player?.dispose();
      slot.listeners.clear();
    },
  };
  slot.handle = handle;
  return handle;
}

/** Makes the store's player in idle time (the embedding host: so a recall right after start runs at once, as before the split). */
export function preparePlayerWhenIdle(store: ConfiguratorStore): void {
  if (typeof window === 'undefined') return;
  const idle = window.requestIdleCallback ?? ((run: () => void) => window.setTimeout(run, 200));
  idle(() => {
    if (!slots.get(store)?.disposed) void loadPlayer(store).catch(() => undefined);
  });
}
