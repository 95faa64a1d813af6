import { lazy, Suspense, useEffect, useRef, useState } from 'react';
import { InputError } from '../../core/inputError';
import { MESH_UNITS, type MeshUnits } from '../../core/model/configuration/configuration';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import type { ImportedMesh, MeshFile } from '../../engines/meshImport/importedMesh';
import { itemDimensions } from './FurniturePanel';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';
import { ImportPicker } from './ImportPicker';

export { IMPORT_ACCEPT } from './ImportPicker';

// The summary of how the model was oriented loads with the first preview (its texts ship with it).
const ImportOrientation = lazy(() => import('./ImportOrientation'));

const UNIT_NAMES: Record<MeshUnits, MessageKey> = { m: 'files.unitMetres', cm: 'files.unitCentimetres', mm: 'files.unitMillimetres', in: 'files.unitInches' };

/**
 * Reads the picked files with the mesh importer (src/engines/meshImport), loaded on first use:
 * it carries three.js's loaders, which the planner's bundle does not (docs/planner.md).
 */
async function readModel(files: readonly MeshFile[], units: 'auto' | MeshUnits): Promise<ImportedMesh> {
  const { importMesh } = await import('../../engines/meshImport/importMesh');
  return importMesh(files, { units });
}

export interface ImportPanelProps {
  /** Adds the model to the room; returns null when it was added, else the model's reason. */
  onAdd: (name: string, mesh: TriangleMesh, units: MeshUnits) => string | null;
  /** Files picked on the stand-in button before this panel's chunk arrived (LazyImportPanel): read at mount. */
  picked?: readonly File[];
}

/**
 * "Import model…": pick an .obj with its .mtl, a .gltf or a .glb. Before anything is added the
 * panel shows what was read — the file, the triangle count, the size, the unit the importer
 * detected with a select to override it, and any warnings — and **Add to room** adds it.
 * Problems with the files are shown here, naming the file; the configuration is untouched
 * until the user adds the model.
 */
export function ImportPanel({ onAdd, picked: pickedEarly }: ImportPanelProps) {
  const { t } = useI18n();
  const [files, setFiles] = useState<MeshFile[] | null>(null);
  const [model, setModel] = useState<ImportedMesh | null>(null);
  const [error, setError] = useState<string | null>(null);
  const [busy, setBusy] = useState(false);
  // Only the latest read is shown (a slow read superseded by another pick or unit change is dropped).
  const seq = useRef(0);

  const read = async (picked: MeshFile[], units: 'auto' | MeshUnits) => {
    const mine = ++seq.current;
    setBusy(true);
    setError(null);
    try {
      const result = await readModel(picked, units);
      if (mine !== seq.current) return;
      setModel(result);
    } catch (err) {
      if (mine !== seq.current) return;
      setModel(null);
      const names = picked.map((f) => f.name).join(', ');
      setError(err instanceof InputError ? err.message : t('files.modelUnreadable', { names, problem: err instanceof Error ? err.message : String(err) }));
    } finally {
      if (mine === seq.current) setBusy(false);
    }
  };

  const pick = async (list: readonly File[]) => {
    const picked = await Promise.all(list.map(async (f) => ({ name: f.name, bytes: new Uint8Array(await f.arrayBuffer()) })));
    setFiles(picked);
    await read(picked, 'auto');
  };

  // Files picked before the chunk arrived are read once, as a pick now would be.
  const early = useRef(pickedEarly);
  useEffect(() => {
    const list = early.current;
    early.current = undefined;
    if (list) void pick(list);
    // eslint-disable-next-line react-hooks/exhaustive-deps -- once, at mount
  }, []);

  const cancel = () => {
    seq.current++;
    setFiles(null);
    setModel(null);
    setError(null);
    setBusy(false);
  };

  const add = () => {
    if (!model) return;
    const refused = onAdd(model.name, model.mesh, model.units);
    if (refused) setError(t('files.modelRefused', { name: model.name, reason: refused }));
    else cancel();
  };

  return (
    <div className="import-model" data-testid="import-panel">
      <ImportPicker onPick={(list) => void pick(list)} />
      {busy && (
        <p className="empty-note" role="status">
          {t('files.readingModel')}
        </p>
      )}
      {error && (
        <p className="import-error" role="alert" data-testid="import-error">
          {error}
        </p>
      )}
      {model && files && model.bounds && <ImportPreview model={model} busy={busy} onUnits={(units) => void read(files, units)} onAdd={add} onCancel={cancel} />}
    </div>
  );
}

interface ImportPreviewProps {
  model: ImportedMesh;
  busy: boolean;
  onUnits: (units: MeshUnits) => void;
  onAdd: () => void;
  onCancel: () => void;
}

/** What was read, before anything is added: name, triangles, size, the unit (detected, changeable), orientation, warnings. */
function ImportPreview({ model, busy, onUnits, onAdd, onCancel }: ImportPreviewProps) {
  const { t, format } = useI18n();
  const b = model.bounds;
  return (
    <div className="import-preview" data-testid="import-preview">
      <p className="preset-name">{model.name}</p>
      <p className="preset-detail" data-testid="import-triangles">
        {t('files.triangles', { count: model.triangleCount })} · {itemDimensions({ width: b.max[0] - b.min[0], depth: b.max[2] - b.min[2], height: b.max[1] - b.min[1] }, 1, format)}
      </p>
      <div className="field">
        <label htmlFor="import-units">{t('files.unitsOfFile', { detected: model.detectedUnits })}</label>
        <select id="import-units" value={model.units} data-testid="import-units" onChange={(e) => onUnits(e.target.value as MeshUnits)}>
          {MESH_UNITS.map((u) => (
            <option key={u} value={u}>
              {u === model.detectedUnits ? t('files.unitDetected', { unit: t(UNIT_NAMES[u]) }) : t(UNIT_NAMES[u])}
            </option>
          ))}
        </select>
      </div>
      <Suspense fallback={null}>
        <ImportOrientation orientation={model.orientation} />
      </Suspense>
      {model.warnings.length > 0 && (
        <ul className="import-warnings" aria-label={t('files.importWarnings')}>
          {model.warnings.map((w) => (
            <li key={w}>{w}</li>
          ))}
        </ul>
      )}
      <div className="setup-actions">
        <button type="button" className="btn btn-primary" onClick={onAdd} disabled={busy} data-testid="import-add">
          {t('files.addToRoom')}
        </button>
        <button type="button" className="btn" onClick={onCancel}>
          {t('common.cancel')}
        </button>
      </div>
    </div>
  );
}
