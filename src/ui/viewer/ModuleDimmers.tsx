import { useMemo } from 'react';
import { useStore } from 'zustand';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { localName } from '../i18n/localName';
import { useI18n } from '../i18n/useI18n';
import { DimmerRow } from './DimmerRow';

/** A dimmer per module of the configuration (folded away), each named as the shopper knows it; nothing when there are no modules. */
export function ModuleDimmers({ store }: { store: ConfiguratorStore }) {
  const { t, language } = useI18n();
  const config = useStore(store, (s) => s.config);
  const catalog = useStore(store, (s) => s.catalog);
  const modules = useMemo(
    () =>
      config.systems.flatMap((s, si) =>
        s.rails.flatMap((r, ri) =>
          r.modules.map((m, mi) => {
            // The shopper's words (issue 27): the catalog's name and the module's place, never its id.
            const type = catalog.moduleTypes.find((x) => x.id === m.type);
            const where = t(config.systems.length > 1 ? 'a11y.moduleInSystem' : 'a11y.module', { index: mi + 1, count: r.modules.length, rail: ri + 1, system: si + 1 });
            return { id: m.id, name: `${type ? localName(type, language) : m.type}, ${where}`, dimming: m.dimming, on: m.on };
          }),
        ),
      ),
    [config, catalog, t, language],
  );
  if (modules.length === 0) return null;
  return (
    <details className="viewer3d-modules">
      <summary>{t('view3d.dimmingModules', { count: modules.length })}</summary>
      {modules.map((m) => (
        <DimmerRow
          key={m.id}
          id={m.id}
          name={m.name}
          dimming={m.dimming}
          onCommit={(d) => store.getState().dispatch('setModuleDimming', { moduleId: m.id, dimming: d })}
          on={m.on !== false}
          onSwitch={(on) => store.getState().dispatch('setModuleOn', { moduleId: m.id, on })}
        />
      ))}
    </details>
  );
}
