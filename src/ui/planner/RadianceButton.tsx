import './registerPanelExtrasEnglish';
import { showStatus, type UiStore } from '../../core/store/uiStore';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { Photometry } from '../../core/photometry/types';
import { downloadRadiance } from './downloadRadiance';
import { useI18n } from '../i18n/useI18n';

/**
 * "Download for Radiance" (docs/radiance.md), an expert tool (docs/embedding.md, option `expert`):
 * a chunk of its own, loaded when the expert tools are on, so a shopper's first download carries
 * neither the button nor its texts.
 */
export default function RadianceButton({ store, ui, loadPhotometry }: { store: ConfiguratorStore; ui: UiStore; loadPhotometry: (path: string) => Promise<Photometry> }) {
  const { t } = useI18n();
  const radiance = async () => {
    const { config, catalog } = store.getState();
    try {
      const name = await downloadRadiance(config, catalog, loadPhotometry);
      showStatus(ui, t('expert.savedRadiance', { name }));
    } catch (err) {
      // The configuration is untouched; the message names the file that could not be read.
      ui.setState({ banner: { text: t('expert.radianceFailed', { problem: err instanceof Error ? err.message : String(err) }), canRestore: false } });
    }
  };
  return (
    <button type="button" className="btn btn-export" onClick={() => void radiance()} data-testid="download-radiance" title={t('expert.radianceTitle')}>
      {t('expert.downloadRadiance')}
    </button>
  );
}
