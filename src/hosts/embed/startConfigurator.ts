import { codedText, InputError } from '../../core/inputError';
import { roomShapeSupport } from '../../core/model/configuration/roomShapeSupport';
import { loadRoomShapeSupport } from '../../core/model/actions/loadRoomShapeSupport';
import { createConfiguration } from '../../core/model/configuration/configuration';
import { createHistory } from '../../core/model/configuration/history';
import { deserializeConfiguration, serializeConfiguration } from '../../core/model/files/sceneFile';
import { encodeShareLink } from '../../core/model/files/shareLink';
import { createConfiguratorStore, type ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { readLocal, writeLocal } from './localStore';
import { SHARE_HASH_PREFIX, resolveStartup, startupNeedsRoomShape, type Startup, type StartupInput } from './startup';
import { createUiStore, showStatus, type UiStore } from '../../core/store/uiStore';
import type { LuxboxOptions } from './types';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { EmbedOptionsError } from './resolveCatalog';
import { EXPERT_KEY, type CheckedOptions } from './embedOptions';
import { keepColourFilterSpectra } from './keepColourFilterSpectra';
import { createI18n, type I18n } from '../../ui/i18n/createI18n';

/** What a mounted configurator's parts share: its options, stores, language, autosave key and change listeners. */
export interface Mounted {
  options: LuxboxOptions;
  catalog: Catalog;
  i18n: I18n;
  store: ConfiguratorStore;
  ui: UiStore;
  storageKey: string | null;
  startupInput: StartupInput;
  /**
   * A saved or shared room of any shape (or a file before version 8) waits for the room-shape chunk
   * (roomShapeSupport.ts): until then an empty plan shows and nothing is autosaved, so the user's shaped room is never lost.
   */
  shapePending: boolean;
  listeners: Set<(json: string) => void>;
  colourData: ReturnType<typeof keepColourFilterSpectra>;
  destroyed: boolean;
  /** Ends the subscriptions this part started (the store's, the Expert switch's, the colour data's). */
  stop(): void;
}

function currentHash(): string {
  return typeof location === 'undefined' ? '' : location.hash;
}

/** A startup's side effects: the share link leaves the address bar, the startup's room is autosaved where it asks. */
function settle(m: Pick<Mounted, 'storageKey' | 'catalog'>, s: Startup): void {
  if (s.clearHash && typeof history !== 'undefined') history.replaceState(null, '', location.pathname + location.search);
  if (m.storageKey && s.saveNow) writeLocal(m.storageKey, serializeConfiguration(s.config, m.catalog));
}

function createStore(catalog: Catalog, initial: Startup['config']): ConfiguratorStore {
  try {
    return createConfiguratorStore({ catalog, initial });
  } catch (e) {
    if (e instanceof InputError) throw new EmbedOptionsError(`options.room: ${e.message}`);
    throw e;
  }
}

/** Every configuration change autosaved (unless a shaped room is still loading) and told to the listeners as scene-file JSON. */
function followChanges(m: Pick<Mounted, 'options' | 'catalog' | 'store' | 'storageKey' | 'shapePending' | 'listeners'>): () => void {
  if (m.options.onChange) m.listeners.add(m.options.onChange);
  return m.store.subscribe((s, prev) => {
    if (s.config === prev.config) return;
    const json = serializeConfiguration(s.config, m.catalog);
    // Autosave only on changes: opening a broken link (no change) never overwrites the saved work,
    // nor does anything done while a saved or shared room of any shape is still loading.
    if (m.storageKey && !m.shapePending) writeLocal(m.storageKey, json);
    for (const l of [...m.listeners]) {
      try {
        l(json);
      } catch (err) {
        console.error('luxbox: a change listener threw', err);
      }
    }
  });
}

/** The configurator's language, stores and startup room (link, autosave, option or demo), followed for autosave and the host's listeners. */
export function startConfigurator(options: LuxboxOptions, { catalog, brand, expert, locale }: CheckedOptions): Mounted {
  const i18n = createI18n({ locale, currency: catalog.currency, onLanguageChange: options.onLanguageChange });
  const storageKey = options.storageKey || null;
  const saved = storageKey ? readLocal(storageKey) : null;
  const startupInput = { catalog, hash: options.shareLinks ? currentHash() : '', saved, room: options.room, demo: options.demo };
  const shapePending = !roomShapeSupport() && startupNeedsRoomShape(startupInput.hash, saved);
  const start: Startup = shapePending ? { config: createConfiguration(), phase: 'planner', banner: null, saveNow: false, clearHash: false } : resolveStartup(startupInput);
  const store = createStore(catalog, start.config);
  const ui = createUiStore({ phase: start.phase, banner: start.banner, brand, ...expert });
  // The user's Expert switch: remembered where the host asked for it, and told to the host.
  const unsubscribeExpert = ui.subscribe((s, prev) => {
    if (s.expert === prev.expert) return;
    if (options.rememberExpert) writeLocal(EXPERT_KEY, s.expert ? '1' : '0');
    options.onExpertChange?.(s.expert);
  });
  const parts = { options, catalog, i18n, store, ui, storageKey, startupInput, shapePending, listeners: new Set<(json: string) => void>(), destroyed: false };
  settle(parts, start);
  const unsubscribeStore = followChanges(parts);
  // The filters' spectra load when the configuration first uses a filter (not with the first screen).
  const colourData = keepColourFilterSpectra(store);
  return Object.assign(parts, {
    colourData,
    stop() {
      unsubscribeStore();
      unsubscribeExpert();
      colourData.stop();
      parts.listeners.clear();
    },
  });
}

/** What the configurator would have opened with, once the room-shape chunk is in: a fresh history, as at mount. */
export function loadPendingShape(m: Mounted): void {
  loadRoomShapeSupport().then(
    () => {
      if (m.destroyed) return;
      const s = resolveStartup(m.startupInput);
      m.store.setState({ history: createHistory(s.config), config: s.config, canUndo: false, canRedo: false, selection: null });
      m.shapePending = false;
      m.ui.setState({ phase: s.phase, banner: s.banner });
      settle(m, s);
    },
    // Not fetched (offline): said in the status line; the autosave stays untouched (shapePending).
    (e: unknown) => showStatus(m.ui, `rooms of any shape could not be loaded (${String(e)})`, { code: 'roomShapeUnavailable', params: { problem: String(e) } }),
  );
}

/** The autosaved room loaded again (the banner's Restore); a saved room of any shape has its chunk already: startup loaded it (startupNeedsRoomShape looks at the autosave too). */
export function restoreSaved(m: Mounted): void {
  const text = m.storageKey ? readLocal(m.storageKey) : null;
  if (!text) return;
  try {
    m.store.getState().load(deserializeConfiguration(text, m.catalog, 'saved configuration'));
    m.ui.setState({ banner: null, phase: 'planner' });
  } catch (e) {
    const problem = e instanceof InputError ? e.message : 'unexpected error';
    const detail = e instanceof InputError && e.code ? { detail: codedText(e.message, e) } : {};
    m.ui.setState({ banner: { text: `Your saved configuration could not be read (${problem}).`, code: 'savedUnreadable', params: { problem }, ...detail, canRestore: false } });
  }
}

/** The page's address without its hash: where a share link points. */
const pageBase = () => (typeof location === 'undefined' ? '' : location.origin + location.pathname + location.search);

/** The API's share link; imported models are not in links (they can be megabytes): the status line says so instead of dropping them silently. */
export function shareLink(m: Mounted): string {
  const base = pageBase();
  const link = encodeShareLink(m.store.getState().config, m.catalog);
  if (link.notice) showStatus(m.ui, `Share link: ${link.notice}`, { code: 'shareLinkNotice', params: { notice: link.notice } });
  return `${base}${SHARE_HASH_PREFIX}${link.text}`;
}

/** The planner's Share link button: the same link, and the models left out, shown next to it (not only in the status line). */
export function shareLinkForUi(m: Mounted): { link: string; leftOut: string[] } {
  const link = encodeShareLink(m.store.getState().config, m.catalog);
  return { link: `${pageBase()}${SHARE_HASH_PREFIX}${link.text}`, leftOut: [...new Set(link.leftOut.map((o) => o.name))] };
}
