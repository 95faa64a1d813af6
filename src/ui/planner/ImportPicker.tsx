import { useI18n } from '../i18n/useI18n';

/** What the file picker offers: an OBJ with its MTL (picked together), a glTF (with its .bin buffers) or a GLB. */
export const IMPORT_ACCEPT = '.obj,.mtl,.gltf,.glb,.bin';

/**
 * The "Import model…" button and its hint: all the import section shows until files are picked.
 * It is on the first screen; the rest of the section (reading, preview, units) is ImportPanel,
 * loaded by LazyImportPanel, which shows this in its place meanwhile (the same markup, so the
 * side panel does not move when the chunk arrives).
 */
export function ImportPicker({ onPick }: { onPick: (files: File[]) => void }) {
  const { t } = useI18n();
  return (
    <>
      <label className="btn import-file-button">
        <input
          type="file"
          multiple
          accept={IMPORT_ACCEPT}
          className="file-input"
          onChange={(e) => {
            const input = e.currentTarget;
            const list = [...(input.files ?? [])];
            // Cleared so that picking the same files again fires change again.
            input.value = '';
            if (list.length > 0) onPick(list);
          }}
          data-testid="import-file"
        />
        {t('files.importModel')}
      </label>
      <p className="empty-note">{t('files.importHint')}</p>
    </>
  );
}
