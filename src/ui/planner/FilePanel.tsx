import { lazy, Suspense, type ChangeEvent } from 'react';
import { useStore } from 'zustand';
import { showStatus, type UiStore } from '../../core/store/uiStore';
import { InputError } from '../../core/inputError';
import { serializeConfiguration } from '../../core/model/files/sceneFile';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { Photometry } from '../../core/photometry/types';
import { downloadText } from './downloadText';
import { readSceneFile } from './readSceneFile';
import { sceneFileName } from './sceneFileName';
import { useI18n } from '../i18n/useI18n';
import { noticeText } from '../i18n/noticeText';

// The Radiance download is an expert tool: its button and texts load only when the expert tools are on.
const RadianceButton = lazy(() => import('./RadianceButton'));

export interface FilePanelProps {
  store: ConfiguratorStore;
  ui: UiStore;
  /** The page's photometry loader (the Radiance export converts the same files the plan shows). */
  loadPhotometry: (path: string) => Promise<Photometry>;
}

/**
 * "Save file" and "Open file…": the configuration as a scene file on the user's disk
 * (docs/model.md, "Scene file"). Opening goes through the store's `load`, one undoable step, so
 * Undo returns to what was there before; a file that cannot be opened leaves the configuration
 * untouched and says why in the banner (it stays until dismissed, unlike the status line, so a
 * long message about a file can be read in full).
 */
export function FilePanel({ store, ui, loadPhotometry }: FilePanelProps) {
  const { t, language } = useI18n();
  // The Radiance export is an expert tool (docs/embedding.md, option `expert`).
  const expert = useStore(ui, (s) => s.expert);
  const save = () => {
    const { config, catalog } = store.getState();
    const name = sceneFileName(config);
    downloadText(name, `${serializeConfiguration(config, catalog)}\n`);
    showStatus(ui, t('files.saved', { name }));
  };

  const open = async (e: ChangeEvent<HTMLInputElement>) => {
    const input = e.currentTarget;
    const file = input.files?.[0];
    // Cleared so that picking the same file again (after fixing it on disk) fires change again.
    input.value = '';
    if (!file) return;
    try {
      const config = await readSceneFile(file, store.getState().catalog);
      const r = store.getState().load(config);
      // The refusal and the file's own errors carry codes (docs/i18n.md): shown in the UI language.
      if (!r.ok) throw new InputError(t('files.cannotOpen', { name: file.name, problem: noticeText(t, language, store.getState().catalog, r) }));
      ui.setState({ banner: null, optionsOpen: false, panelOpen: false });
      showStatus(ui, t('files.opened', { name: file.name }));
    } catch (err) {
      const text = err instanceof InputError ? (err.code ? noticeText(t, language, store.getState().catalog, err) : err.message) : t('files.couldNotOpen', { name: file.name, problem: err instanceof Error ? err.message : String(err) });
      ui.setState({ banner: { text, canRestore: false } });
    }
  };

  return (
    <div className="setup-actions file-actions">
      <button type="button" className="btn" onClick={save} data-testid="save-file">
        {t('files.saveFile')}
      </button>
      {/* A label is the one element that opens a file picker on click or tap without script;
          the input inside stays focusable (visually hidden, not display:none) for the keyboard. */}
      <label className="btn file-button">
        <input type="file" accept=".json,application/json" className="file-input" onChange={(e) => void open(e)} data-testid="open-file" />
        {t('files.openFile')}
      </label>
      {expert && (
        <Suspense fallback={null}>
          <RadianceButton store={store} ui={ui} loadPhotometry={loadPhotometry} />
        </Suspense>
      )}
    </div>
  );
}
