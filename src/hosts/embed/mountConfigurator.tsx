import { StrictMode } from 'react';
import { parseAdaptation } from '../../engines/view/adaptationSetting';
import { createRoot } from 'react-dom/client';
import { codedText, InputError } from '../../core/inputError';
import { isActionName } from '../../core/model/actions/actionDefinitions';
import { isRoomShapeActionName } from '../../core/model/actions/roomShapeActionNames';
import { roomShapeSupport, RoomShapeSupportMissing } from '../../core/model/configuration/roomShapeSupport';
import { loadRoomShapeSupport } from '../../core/model/actions/loadRoomShapeSupport';
import { createConfiguration } from '../../core/model/configuration/configuration';
import { createHistory } from '../../core/model/configuration/history';
import { billOfMaterials, type BillOfMaterials } from '../../core/model/power/billOfMaterials';
import { installationNeeds } from '../../core/model/power/installationNeeds';
import { configurationFromData, deserializeConfiguration, serializeConfiguration } from '../../core/model/files/sceneFile';
import { encodeShareLink } from '../../core/model/files/shareLink';
import { toLightingScene } from '../../core/model/files/toLightingScene';
import { createConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { Configurator } from '../../ui/app/Configurator';
import { readLocal, writeLocal } from './localStore';
import { SHARE_HASH_PREFIX, resolveStartup, startupNeedsRoomShape, type Startup } from './startup';
import { createUiStore, DEFAULT_BRAND, showStatus, type Brand } from '../../core/store/uiStore';
import { createFootprintSource } from '../../ui/planner/footprintSource';
import type { LuxboxInstance, LuxboxOptions } from './types';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { isQualityLevel, QUALITY_LEVEL_NAMES } from '../../engines/relight/qualityLevels';
import { EV100_MAX, EV100_MIN, isEv100 } from '../../engines/view/photographicExposure';
import { EmbedOptionsError, resolveCatalog } from './resolveCatalog';
import { keepColourFilterSpectra } from './keepColourFilterSpectra';
import { ColourFilterSpectraPending } from '../../core/colour/colourFilterSpectra';

export { EmbedOptionsError };
import { getViewerStatus } from '../../ui/viewer/viewerStatus';
import { createBakeHost } from '../../ui/viewer/bakeHost';
import { preparePlayerWhenIdle, scenePlayerHandle } from '../../ui/scenes/scenePlayerHandle';
import { FADE_LIMITS, sceneByName } from '../../core/model/cues/lightScenes';
import { createI18n } from '../../ui/i18n/createI18n';
import { I18nProvider } from '../../ui/i18n/I18nProvider';
import { isLanguage, LANGUAGES } from '../../ui/i18n/languages';
import { isLocaleTag } from '../../ui/i18n/resolveLocale';
import { noticeText } from '../../ui/i18n/noticeText';
import { bomLineName } from '../../ui/i18n/bomLineName';
import type { CodedMessage } from '../../ui/i18n/translateCoded';

/** options.locale checked: a string must be a BCP 47 tag; a list (navigator.languages) may hold tags resolveLocale skips. */
function checkLocale(locale: unknown): string | readonly string[] | undefined {
  if (locale === undefined) return typeof navigator === 'undefined' ? undefined : navigator.languages;
  if (typeof locale === 'string') {
    if (!isLocaleTag(locale)) throw new EmbedOptionsError(`options.locale: '${locale}' is not a BCP 47 language tag (e.g. 'de-CH')`);
    return locale;
  }
  if (Array.isArray(locale) && locale.every((t) => typeof t === 'string')) return locale;
  throw new EmbedOptionsError("options.locale must be a BCP 47 tag such as 'de-CH' or a list of them");
}

/** The header's brand from options.brand: absent → luxbox, null → none, else a name (1–80 characters) and an optional logo URL. */
function checkBrand(brand: unknown): Brand | null {
  if (brand === undefined) return DEFAULT_BRAND;
  if (brand === null) return null;
  const b = brand as { name?: unknown; logo?: unknown };
  if (typeof brand !== 'object' || typeof b.name !== 'string' || b.name.trim() === '' || b.name.length > 80) {
    throw new EmbedOptionsError('options.brand must be null or { name, logo? } with a name of 1 to 80 characters');
  }
  if (b.logo !== undefined && (typeof b.logo !== 'string' || b.logo === '')) throw new EmbedOptionsError('options.brand.logo must be an image URL');
  return { name: b.name, ...(b.logo !== undefined ? { logo: b.logo as string } : {}) };
}

/** Where the user's Expert switch is kept (option rememberExpert): '1' on, '0' off. */
export const EXPERT_KEY = 'luxbox.expert';

/**
 * options.expert checked: true shows the expert tools (no switch), false hides them (no switch;
 * the default), 'switch' offers the user the switch, off at first unless rememberExpert finds it on.
 */
export function checkExpert(expert: unknown, remember: boolean): { expert: boolean; expertSwitch: boolean } {
  if (expert === undefined || expert === false) return { expert: false, expertSwitch: false };
  if (expert === true) return { expert: true, expertSwitch: false };
  if (expert === 'switch') return { expert: remember && readLocal(EXPERT_KEY) === '1', expertSwitch: true };
  throw new EmbedOptionsError(`options.expert: ${JSON.stringify(expert)} is not true, false or 'switch'`);
}

/** Class on the element luxbox renders into: the scope of its stylesheet and its size container. */
const ROOT_CLASS = 'luxbox';

function currentHash(): string {
  return typeof location === 'undefined' ? '' : location.hash;
}

/**
 * mountLuxbox (mountLuxbox.ts) with the catalog used when options.catalog is absent passed in, so
 * this module does not import the bundled demo catalog: the package's React and element doors
 * load that catalog only when a page gives none (createMountController.ts; docs/package.md, "Budgets").
 * Throws an InputError subclass for bad options before touching the element.
 */
export function mountConfigurator(element: Element, options: LuxboxOptions, bundledCatalog: Catalog | undefined): LuxboxInstance {
  if (typeof Element === 'undefined' || !(element instanceof Element)) throw new EmbedOptionsError('mountLuxbox needs a DOM element to mount into');
  const catalog = resolveCatalog(options, bundledCatalog);
  if (options.quality !== undefined && !isQualityLevel(options.quality)) throw new EmbedOptionsError(`options.quality: '${String(options.quality)}' is not a quality level (expected ${QUALITY_LEVEL_NAMES.join(', ')})`);
  const quality = options.quality;
  if (options.exposure !== undefined && options.exposure !== 'auto' && !isEv100(options.exposure)) {
    throw new EmbedOptionsError(`options.exposure: ${JSON.stringify(options.exposure)} is neither 'auto' nor an EV100 number in ${EV100_MIN}..${EV100_MAX}`);
  }
  const adaptation = options.adapt === undefined ? undefined : parseAdaptation(String(options.adapt));
  if (adaptation === null) throw new EmbedOptionsError(`options.adapt: ${JSON.stringify(options.adapt)} is neither 'eye', 'none' nor 'camera:<K>' with K in 1000..20000`);
  if (options.landmarks !== undefined && options.landmarks !== 'page' && options.landmarks !== 'region') {
    throw new EmbedOptionsError(`options.landmarks: ${JSON.stringify(options.landmarks)} is neither 'page' nor 'region'`);
  }
  const brand = checkBrand(options.brand);
  const expert = checkExpert(options.expert, options.rememberExpert === true);
  if (options.apiLanguage !== undefined && options.apiLanguage !== 'ui' && options.apiLanguage !== 'en') {
    throw new EmbedOptionsError(`options.apiLanguage: ${JSON.stringify(options.apiLanguage)} is neither 'ui' nor 'en'`);
  }
  const i18n = createI18n({ locale: checkLocale(options.locale), currency: catalog.currency, onLanguageChange: options.onLanguageChange });
  /** A text the API returns, in the configurator's language unless the host asked for English (docs/embedding.md, `apiLanguage`). */
  const apiText = (msg: CodedMessage): string => {
    const english = msg.reason ?? msg.text ?? msg.message ?? '';
    const { t, language, ready } = i18n.getSnapshot();
    // Before the language's texts have loaded (whenReady() waits for them) the sentence stays whole, in English.
    if (options.apiLanguage === 'en' || !ready) return english;
    return noticeText(t, language, catalog, msg);
  };

  const storageKey = options.storageKey || null;
  const saved = storageKey ? readLocal(storageKey) : null;
  const startupInput = { catalog, hash: options.shareLinks ? currentHash() : '', saved, room: options.room, demo: options.demo };
  // A saved or shared room of any shape (or a file before version 8) waits for the room-shape chunk (roomShapeSupport.ts): until
  // then an empty plan shows and nothing is autosaved, so the user's shaped room is never lost.
  let shapePending = !roomShapeSupport() && startupNeedsRoomShape(startupInput.hash, saved);
  const start: Startup = shapePending ? { config: createConfiguration(), phase: 'planner', banner: null, saveNow: false, clearHash: false } : resolveStartup(startupInput);
  let store;
  try {
    store = createConfiguratorStore({ catalog, initial: start.config });
  } catch (e) {
    if (e instanceof InputError) throw new EmbedOptionsError(`options.room: ${e.message}`);
    throw e;
  }
  const ui = createUiStore({ phase: start.phase, banner: start.banner, brand, ...expert });
  // The user's Expert switch: remembered where the host asked for it, and told to the host.
  const unsubscribeExpert = ui.subscribe((s, prev) => {
    if (s.expert === prev.expert) return;
    if (options.rememberExpert) writeLocal(EXPERT_KEY, s.expert ? '1' : '0');
    options.onExpertChange?.(s.expert);
  });
  const apiBom = (): BillOfMaterials => {
    const bom = billOfMaterials(store.getState().config, catalog);
    const { t, language, format, ready } = i18n.getSnapshot();
    if (options.apiLanguage === 'en' || language === 'en' || !ready) return bom;
    return { ...bom, lines: bom.lines.map((line) => ({ ...line, name: bomLineName(line, catalog, language, t, format) })) };
  };
  const settle = (s: Startup) => {
    if (s.clearHash && typeof history !== 'undefined') history.replaceState(null, '', location.pathname + location.search);
    if (storageKey && s.saveNow) writeLocal(storageKey, serializeConfiguration(s.config, catalog));
  };
  settle(start);

  const listeners = new Set<(json: string) => void>();
  if (options.onChange) listeners.add(options.onChange);
  const unsubscribeStore = store.subscribe((s, prev) => {
    if (s.config === prev.config) return;
    const json = serializeConfiguration(s.config, catalog);
    // Autosave only on changes: opening a broken link (no change) never overwrites the saved work,
    // nor does anything done while a saved or shared room of any shape is still loading.
    if (storageKey && !shapePending) writeLocal(storageKey, json);
    for (const l of [...listeners]) {
      try {
        l(json);
      } catch (err) {
        console.error('luxbox: a change listener threw', err);
      }
    }
  });

  // The filters' spectra load when the configuration first uses a filter (not with the first screen).
  const colourData = keepColourFilterSpectra(store);

  // A saved room of any shape has its chunk already: startup loaded it (startupNeedsRoomShape looks at the autosave too).
  const restoreSaved = (): void => {
    const text = storageKey ? readLocal(storageKey) : null;
    if (!text) return;
    try {
      store.getState().load(deserializeConfiguration(text, catalog, 'saved configuration'));
      ui.setState({ banner: null, phase: 'planner' });
    } catch (e) {
      const problem = e instanceof InputError ? e.message : 'unexpected error';
      const detail = e instanceof InputError && e.code ? { detail: codedText(e.message, e) } : {};
      ui.setState({ banner: { text: `Your saved configuration could not be read (${problem}).`, code: 'savedUnreadable', params: { problem }, ...detail, canRestore: false } });
    }
  };

  const shareLink = () => {
    const base = typeof location === 'undefined' ? '' : location.origin + location.pathname + location.search;
    // Imported models are not in links (they can be megabytes): say so instead of dropping them silently.
    const link = encodeShareLink(store.getState().config, catalog);
    if (link.notice) showStatus(ui, `Share link: ${link.notice}`, { code: 'shareLinkNotice', params: { notice: link.notice } });
    return `${base}${SHARE_HASH_PREFIX}${link.text}`;
  };

  // The planner's Share link button: the same link, and the notice shown next to it (not only in the status line).
  const shareLinkForUi = () => {
    const link = encodeShareLink(store.getState().config, catalog);
    const base = typeof location === 'undefined' ? '' : location.origin + location.pathname + location.search;
    return { link: `${base}${SHARE_HASH_PREFIX}${link.text}`, leftOut: [...new Set(link.leftOut.map((o) => o.name))] };
  };

  const footprints = createFootprintSource(options.assetBase ?? import.meta.env.BASE_URL);
  // The 3D bake lives as long as this configurator (started in idle time once the plan shows).
  const bakeHost = createBakeHost(store, footprints.loadPhotometry, { quality: quality ?? null, remember: options.rememberQuality === true, exposure: options.exposure ?? 'auto', ...(adaptation ? { adaptation } : {}) });
  // Light-scene playback, shared by the scene panel, the keyboard and the API below; fades relight the bake host's engine.
  // (The player's code is a lazy chunk, made in idle time: scenePlayerHandle.ts.)
  const scenePlayer = scenePlayerHandle(store, { feed: () => bakeHost.current() });
  preparePlayerWhenIdle(store);
  // The class scopes every luxbox style rule to this element and makes it the container whose
  // width the layout's breakpoints query (app.css); a class the host put there itself stays on destroy.
  const hadRootClass = element.classList.contains(ROOT_CLASS);
  element.classList.add(ROOT_CLASS);
  const root = createRoot(element);
  root.render(
    <StrictMode>
      <I18nProvider i18n={i18n}>
        <Configurator
          store={store}
          ui={ui}
          languageSwitch={options.languageSwitch === true}
          onRestoreSaved={restoreSaved}
          shareLink={shareLinkForUi}
          footprints={footprints}
          landmarks={options.landmarks ?? 'region'}
          firstRun={options.firstRun}
        />
      </I18nProvider>
    </StrictMode>,
  );

  let destroyed = false;
  const alive = () => {
    if (destroyed) throw new InputError('this luxbox instance was destroyed');
  };
  if (shapePending) {
    // What the configurator would have opened with, once the shape can be read: a fresh history, as at mount.
    loadRoomShapeSupport().then(
      () => {
        if (destroyed) return;
        const s = resolveStartup(startupInput);
        store.setState({ history: createHistory(s.config), config: s.config, canUndo: false, canRedo: false, selection: null });
        shapePending = false;
        ui.setState({ phase: s.phase, banner: s.banner });
        settle(s);
      },
      // Not fetched (offline): said in the status line; the autosave stays untouched (shapePending).
      (e: unknown) => showStatus(ui, `rooms of any shape could not be loaded (${String(e)})`, { code: 'roomShapeUnavailable', params: { problem: String(e) } }),
    );
  }

  return {
    getConfig() {
      alive();
      return serializeConfiguration(store.getState().config, catalog);
    },
    setConfig(sceneFile) {
      alive();
      let config;
      try {
        config = typeof sceneFile === 'string' ? deserializeConfiguration(sceneFile, catalog, 'setConfig') : configurationFromData(sceneFile, catalog, 'setConfig');
      } catch (e) {
        // A room of any shape (or a file before version 8) before its chunk: fetch it; whenReady() waits for it (docs/embedding.md).
        if (!(e instanceof RoomShapeSupportMissing)) throw e;
        loadRoomShapeSupport().catch(() => undefined);
        throw new InputError('setConfig: this configuration needs a part of luxbox that is still loading (rooms of any shape, files before version 8); await whenReady() first', { code: 'roomShapeLoading' });
      }
      const r = store.getState().load(config);
      if (!r.ok) throw new InputError(`setConfig: ${r.reason}`);
      ui.setState({ phase: 'planner', banner: null });
    },
    subscribe(listener) {
      alive();
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    getBillOfMaterials() {
      alive();
      return apiBom();
    },
    getInstallationNeeds() {
      alive();
      return installationNeeds(store.getState().config, catalog);
    },
    listActions(paramsByName) {
      alive();
      return store
        .getState()
        .listActions(paramsByName)
        .map((a) => ({ name: a.name, label: a.label, enabled: a.enabled === true, reason: a.enabled === true ? null : apiText(a.enabled) }));
    },
    // Typed for callers (LuxboxInstance.runAction); plain JavaScript may pass anything, refused below.
    runAction(name: string, params: unknown = {}) {
      alive();
      if (!isActionName(name)) return { ok: false, reason: `unknown action '${name}'` };
      if (isRoomShapeActionName(name) && !roomShapeSupport()) {
        // The room-shape editor's actions come with their chunk: fetch it; whenReady() waits for it.
        loadRoomShapeSupport().catch(() => undefined);
        return { ok: false, reason: `${name}: rooms of any shape are still loading; await whenReady() first` };
      }
      const r = store.getState().dispatch(name, params);
      if (r.ok && ui.getState().phase === 'setup') ui.setState({ phase: 'planner' });
      return r.ok ? { ok: true } : { ok: false, reason: apiText(r) };
    },
    undo() {
      alive();
      return store.getState().undo();
    },
    redo() {
      alive();
      return store.getState().redo();
    },
    getShareLink() {
      alive();
      return shareLink();
    },
    getLightingScene() {
      alive();
      try {
        return toLightingScene(store.getState().config, catalog);
      } catch (e) {
        if (e instanceof ColourFilterSpectraPending) throw new InputError("getLightingScene: the colour filters' spectra are still loading; await whenReady() first");
        throw e;
      }
    },
    whenReady() {
      alive();
      // The room-shape chunk too, so that setConfig and runAction take rooms of any shape afterwards.
      return Promise.all([colourData.ready(), i18n.ready, loadRoomShapeSupport()]).then(() => undefined);
    },
    scenes() {
      alive();
      const current = scenePlayer.getState().current;
      return (store.getState().config.lightScenes ?? []).map((s) => ({ id: s.id, name: s.name, fade: s.fade, current: s.id === current }));
    },
    recordScene(name) {
      alive();
      const r = store.getState().dispatch('recordScene', { name });
      return r.ok ? { ok: true } : { ok: false, reason: apiText(r) };
    },
    recall(name, options = {}) {
      alive();
      const scene = typeof name === 'string' ? sceneByName(store.getState().config, name) : undefined;
      if (!scene) return Promise.resolve({ ok: false, reason: `no light scene named '${String(name)}'` });
      if (options.fade !== undefined && !(Number.isFinite(options.fade) && options.fade >= FADE_LIMITS.min && options.fade <= FADE_LIMITS.max))
        return Promise.resolve({ ok: false, reason: `fade must be between ${FADE_LIMITS.min} and ${FADE_LIMITS.max} s (got ${String(options.fade)})` });
      return scenePlayer.recall(scene.id, { fade: options.fade }).then((r) => (r.ok ? { ok: true as const } : { ok: false as const, reason: apiText(r) }));
    },
    view3d() {
      alive();
      return getViewerStatus(store);
    },
    getLanguage() {
      alive();
      const { language, locale } = i18n.getSnapshot();
      return { language, locale };
    },
    setLanguage(language) {
      alive();
      if (!isLanguage(language)) throw new InputError(`setLanguage: '${String(language)}' is not a luxbox language (expected ${LANGUAGES.join(', ')})`);
      return i18n.setLanguage(language);
    },
    destroy() {
      if (destroyed) return;
      destroyed = true;
      unsubscribeStore();
      unsubscribeExpert();
      colourData.stop();
      listeners.clear();
      root.unmount();
      scenePlayer.dispose();
      bakeHost.dispose();
      if (!hadRootClass) element.classList.remove(ROOT_CLASS);
    },
  };
}
