import { useStore } from 'zustand';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { useI18n } from '../i18n/useI18n';
import { selectionLabel } from './selectionLabel';

/** 'Selected: …' for the store's selected object or module, by the name a shopper knows; nothing when neither is selected. */
export function SelectionNote({ store }: { store: ConfiguratorStore }) {
  const { t, language } = useI18n();
  const config = useStore(store, (s) => s.config);
  const catalog = useStore(store, (s) => s.catalog);
  const selection = useStore(store, (s) => s.selection);
  const label = selectionLabel(t, language, catalog, config, selection);
  if (!label) return null;
  return (
    <p className="viewer3d-selected" data-testid="view3d-selected" data-kind={selection?.kind} data-id={selection?.id}>
      {t('view3d.selected', { name: label })}
    </p>
  );
}
