import { StrictMode } from 'react';
import { checkEmbedOptions } from './embedOptions';
import { createRoot } from 'react-dom/client';
import { configuratorApi } from './configuratorApi';
import { loadPendingShape, restoreSaved, shareLinkForUi, startConfigurator } from './startConfigurator';
import { Configurator } from '../../ui/app/Configurator';
import { createFootprintSource } from '../../ui/planner/footprintSource';
import type { LuxboxInstance, LuxboxOptions } from './types';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { EmbedOptionsError } from './resolveCatalog';
import { createBakeHost } from '../../ui/viewer/bakeHost';
import { preparePlayerWhenIdle, scenePlayerHandle } from '../../ui/scenes/scenePlayerHandle';
import { I18nProvider } from '../../ui/i18n/I18nProvider';

export { EmbedOptionsError };
export { checkExpert, EXPERT_KEY } from './embedOptions';

/** Class on the element luxbox renders into: the scope of its stylesheet and its size container. */
const ROOT_CLASS = 'luxbox';

/**
 * mountLuxbox (mountLuxbox.ts) with the catalog used when options.catalog is absent passed in, so
 * this module does not import the bundled demo catalog: the package's React and element doors
 * load that catalog only when a page gives none (createMountController.ts; docs/package.md, "Budgets").
 * Throws an InputError subclass for bad options before touching the element. Its steps: the options
 * checked (embedOptions.ts), the stores started (startConfigurator.ts), the UI rendered, the instance
 * returned (configuratorApi.ts).
 */
export function mountConfigurator(element: Element, options: LuxboxOptions, bundledCatalog: Catalog | undefined): LuxboxInstance {
  const checked = checkEmbedOptions(element, options, bundledCatalog);
  const m = startConfigurator(options, checked);
  const footprints = createFootprintSource(options.assetBase ?? import.meta.env.BASE_URL);
  // The 3D bake lives as long as this configurator (started in idle time once the plan shows).
  const bakeHost = createBakeHost(m.store, footprints.loadPhotometry, {
    quality: options.quality ?? null,
    remember: options.rememberQuality === true,
    exposure: options.exposure ?? 'auto',
    ...(checked.adaptation ? { adaptation: checked.adaptation } : {}),
  });
  // Light-scene playback, shared by the scene panel, the keyboard and the API; fades relight the bake host's engine.
  // (The player's code is a lazy chunk, made in idle time: scenePlayerHandle.ts.)
  const scenePlayer = scenePlayerHandle(m.store, { feed: () => bakeHost.current() });
  preparePlayerWhenIdle(m.store);
  // The class scopes every luxbox style rule to this element and makes it the container whose
  // width the layout's breakpoints query (app.css); a class the host put there itself stays on destroy.
  const hadRootClass = element.classList.contains(ROOT_CLASS);
  element.classList.add(ROOT_CLASS);
  const root = createRoot(element);
  root.render(
    <StrictMode>
      <I18nProvider i18n={m.i18n}>
        <Configurator
          store={m.store}
          ui={m.ui}
          languageSwitch={options.languageSwitch === true}
          onRestoreSaved={() => restoreSaved(m)}
          shareLink={() => shareLinkForUi(m)}
          footprints={footprints}
          landmarks={options.landmarks ?? 'region'}
          firstRun={options.firstRun}
        />
      </I18nProvider>
    </StrictMode>,
  );
  if (m.shapePending) loadPendingShape(m);
  return configuratorApi(m, scenePlayer, () => {
    root.unmount();
    scenePlayer.dispose();
    bakeHost.dispose();
    if (!hadRootClass) element.classList.remove(ROOT_CLASS);
  });
}
