import type { ChangeEvent } from 'react';
import { showStatus, type UiStore } from '../../core/store/uiStore';
import { InputError } from '../../core/inputError';
import { serializeConfiguration } from '../../core/model/sceneFile';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { Photometry } from '../../core/photometry/types';
import { downloadRadiance } from './downloadRadiance';
import { downloadText } from './downloadText';
import { readSceneFile } from './readSceneFile';
import { sceneFileName } from './sceneFileName';

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
  const save = () => {
    const { config, catalog } = store.getState();
    const name = sceneFileName(config);
    downloadText(name, `${serializeConfiguration(config, catalog)}\n`);
    showStatus(ui, `Saved ${name}`);
  };

  const radiance = async () => {
    const { config, catalog } = store.getState();
    try {
      const name = await downloadRadiance(config, catalog, loadPhotometry);
      showStatus(ui, `Saved ${name} (unpack, then sh render.sh)`);
    } catch (err) {
      // The configuration is untouched; the message names the file that could not be read.
      ui.setState({ banner: { text: `The Radiance export failed: ${err instanceof Error ? err.message : String(err)}`, canRestore: false } });
    }
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
      if (!r.ok) throw new InputError(`“${file.name}” cannot be opened: ${r.reason}`);
      ui.setState({ banner: null, optionsOpen: false, panelOpen: false });
      showStatus(ui, `Opened ${file.name}`);
    } catch (err) {
      const text = err instanceof InputError ? err.message : `“${file.name}” could not be opened (${err instanceof Error ? err.message : String(err)})`;
      ui.setState({ banner: { text, canRestore: false } });
    }
  };

  return (
    <div className="setup-actions file-actions">
      <button type="button" className="btn" onClick={save} data-testid="save-file">
        Save file
      </button>
      {/* A label is the one element that opens a file picker on click or tap without script;
          the input inside stays focusable (visually hidden, not display:none) for the keyboard. */}
      <label className="btn file-button">
        <input
          type="file"
          accept=".json,application/json"
          className="file-input"
          onChange={(e) => void open(e)}
          data-testid="open-file"
        />
        Open file…
      </label>
      <button type="button" className="btn btn-export" onClick={() => void radiance()} data-testid="download-radiance" title="A folder for the Radiance renderer: scene, luminaires, views, render.sh">
        Download for Radiance
      </button>
    </div>
  );
}
