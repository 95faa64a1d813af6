import { InputError } from '../../core/inputError';
import { isActionName } from '../../core/model/actions/actionDefinitions';
import { isRoomShapeActionName } from '../../core/model/actions/roomShapeActionNames';
import { roomShapeSupport, RoomShapeSupportMissing } from '../../core/model/configuration/roomShapeSupport';
import { loadRoomShapeSupport } from '../../core/model/actions/loadRoomShapeSupport';
import { billOfMaterials, type BillOfMaterials } from '../../core/model/power/billOfMaterials';
import { installationNeeds } from '../../core/model/power/installationNeeds';
import { configurationFromData, deserializeConfiguration, serializeConfiguration } from '../../core/model/files/sceneFile';
import { toLightingScene } from '../../core/model/files/toLightingScene';
import { shareLink, type Mounted } from './startConfigurator';
import type { LuxboxInstance } from './types';
import { ColourFilterSpectraPending } from '../../core/colour/colourFilterSpectra';
import { getViewerStatus } from '../../ui/viewer/viewerStatus';
import type { ScenePlayerHandle } from '../../ui/scenes/scenePlayerHandle';
import { FADE_LIMITS, sceneByName } from '../../core/model/cues/lightScenes';
import { isLanguage, LANGUAGES } from '../../ui/i18n/languages';
import { noticeText } from '../../ui/i18n/noticeText';
import { bomLineName } from '../../ui/i18n/bomLineName';
import type { CodedMessage } from '../../ui/i18n/translateCoded';

/** A text the API returns, in the configurator's language unless the host asked for English (docs/embedding.md, `apiLanguage`). */
function apiText(m: Mounted, msg: CodedMessage): string {
  const english = msg.reason ?? msg.text ?? msg.message ?? '';
  const { t, language, ready } = m.i18n.getSnapshot();
  // Before the language's texts have loaded (whenReady() waits for them) the sentence stays whole, in English.
  if (m.options.apiLanguage === 'en' || !ready) return english;
  return noticeText(t, language, m.catalog, msg);
}

/** The bill of materials, its line names in the configurator's language unless the host asked for English. */
function apiBom(m: Mounted): BillOfMaterials {
  const bom = billOfMaterials(m.store.getState().config, m.catalog);
  const { t, language, format, ready } = m.i18n.getSnapshot();
  if (m.options.apiLanguage === 'en' || language === 'en' || !ready) return bom;
  return { ...bom, lines: bom.lines.map((line) => ({ ...line, name: bomLineName(line, m.catalog, language, t, format) })) };
}

type ConfigurationApi = Pick<LuxboxInstance, 'getConfig' | 'setConfig' | 'subscribe' | 'getBillOfMaterials' | 'getInstallationNeeds' | 'listActions' | 'runAction' | 'undo' | 'redo'>;

/** The configuration's part of the instance: read and replace it, follow it, its bill and needs, its actions and their undo. */
function configurationApi(m: Mounted, alive: () => void): ConfigurationApi {
  const { store, ui, catalog, listeners } = m;
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
      return apiBom(m);
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
        .map((a) => ({ name: a.name, label: a.label, enabled: a.enabled === true, reason: a.enabled === true ? null : apiText(m, a.enabled) }));
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
      return r.ok ? { ok: true } : { ok: false, reason: apiText(m, r) };
    },
    undo() {
      alive();
      return store.getState().undo();
    },
    redo() {
      alive();
      return store.getState().redo();
    },
  };
}

/** The rest: the share link and lighting scene, readiness, light scenes, the 3D view's status, the language and destroy(). */
function sceneApi(m: Mounted, alive: () => void, scenePlayer: ScenePlayerHandle, unmount: () => void): Omit<LuxboxInstance, keyof ConfigurationApi> {
  const { store, i18n } = m;
  return {
    getShareLink() {
      alive();
      return shareLink(m);
    },
    getLightingScene() {
      alive();
      try {
        return toLightingScene(store.getState().config, m.catalog);
      } catch (e) {
        if (e instanceof ColourFilterSpectraPending) throw new InputError("getLightingScene: the colour filters' spectra are still loading; await whenReady() first");
        throw e;
      }
    },
    whenReady() {
      alive();
      // The room-shape chunk too, so that setConfig and runAction take rooms of any shape afterwards.
      return Promise.all([m.colourData.ready(), i18n.ready, loadRoomShapeSupport()]).then(() => undefined);
    },
    scenes() {
      alive();
      const current = scenePlayer.getState().current;
      return (store.getState().config.lightScenes ?? []).map((s) => ({ id: s.id, name: s.name, fade: s.fade, current: s.id === current }));
    },
    recordScene(name) {
      alive();
      const r = store.getState().dispatch('recordScene', { name });
      return r.ok ? { ok: true } : { ok: false, reason: apiText(m, r) };
    },
    recall(name, options = {}) {
      alive();
      const scene = typeof name === 'string' ? sceneByName(store.getState().config, name) : undefined;
      if (!scene) return Promise.resolve({ ok: false, reason: `no light scene named '${String(name)}'` });
      if (options.fade !== undefined && !(Number.isFinite(options.fade) && options.fade >= FADE_LIMITS.min && options.fade <= FADE_LIMITS.max))
        return Promise.resolve({ ok: false, reason: `fade must be between ${FADE_LIMITS.min} and ${FADE_LIMITS.max} s (got ${String(options.fade)})` });
      return scenePlayer.recall(scene.id, { fade: options.fade }).then((r) => (r.ok ? { ok: true as const } : { ok: false as const, reason: apiText(m, r) }));
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
      if (m.destroyed) return;
      m.destroyed = true;
      m.stop();
      unmount();
    },
  };
}

/** The instance mountLuxbox returns (docs/embedding.md, "The instance"): every method refuses once destroyed. */
export function configuratorApi(m: Mounted, scenePlayer: ScenePlayerHandle, unmount: () => void): LuxboxInstance {
  // Every method but destroy() starts with it.
  const alive = () => {
    if (m.destroyed) throw new InputError('this luxbox instance was destroyed');
  };
  return { ...configurationApi(m, alive), ...sceneApi(m, alive, scenePlayer, unmount) };
}
