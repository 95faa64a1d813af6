import { mountConfigurator } from '../embed/mountConfigurator';
import type { LuxboxInstance, LuxboxOptions } from '../embed/types';
import { loadCatalogFromUrl } from './loadCatalogFromUrl';

/** What a wrapper mounts: mountLuxbox's options, with the catalog also allowed as the URL of a catalog.json. */
export interface MountRequest {
  options: Omit<LuxboxOptions, 'catalog'>;
  /** A catalog.json URL (fetched; its folder becomes the asset base unless options.assetBase is set), parsed catalog data, or undefined for the bundled demo catalog. */
  catalog?: string | object;
}

export interface MountController {
  /** (Re)mounts with these options; a configuration the user has changed is carried over when the catalog is the same. */
  mount(request: MountRequest): Promise<void>;
  current(): LuxboxInstance | null;
  destroy(): void;
}

/**
 * The mount, remount and unmount that `<Luxbox>` (luxbox/react) and `<luxbox-configurator>`
 * (luxbox/element) share. mountLuxbox's options are read once, at mount; a wrapper whose props or
 * attributes change mounts again. Catalog URLs load asynchronously, so a mount that a newer one
 * overtook (or a destroy) while its catalog was loading is dropped, not mounted.
 */
export function createMountController(element: HTMLElement, handlers: { onMount: (instance: LuxboxInstance) => void; onError: (error: Error) => void }): MountController {
  let instance: LuxboxInstance | null = null;
  let initialConfig = '';
  let mountedCatalog: MountRequest['catalog'];
  let generation = 0;

  const release = () => {
    instance?.destroy();
    instance = null;
  };

  return {
    async mount(request) {
      const mine = ++generation;
      // Carried over only if the user changed something: a configurator still on its room setup stays there.
      const carried = instance && request.catalog === mountedCatalog && instance.getConfig() !== initialConfig ? instance.getConfig() : null;
      release();
      try {
        let catalogOptions: Pick<LuxboxOptions, 'catalog' | 'assetBase'> = {};
        if (typeof request.catalog === 'string') {
          const folder = await loadCatalogFromUrl(request.catalog);
          if (mine !== generation) return;
          catalogOptions = { catalog: folder.catalog, assetBase: request.options.assetBase ?? folder.assetBase };
        } else if (request.catalog !== undefined) {
          catalogOptions = { catalog: request.catalog };
        }
        // The bundled demo catalog (26 kB of JSON, 5 kB gzip) is a lazy chunk here: a shop that passes its own never loads it (docs/package.md, "Budgets").
        const bundled = catalogOptions.catalog === undefined ? (await import('../../core/catalog/defaultCatalog')).defaultCatalog : undefined;
        if (mine !== generation) return;
        const next = mountConfigurator(element, { ...request.options, ...catalogOptions }, bundled);
        initialConfig = next.getConfig();
        if (carried) next.setConfig(carried);
        instance = next;
        mountedCatalog = request.catalog;
        handlers.onMount(next);
      } catch (e) {
        if (mine === generation) handlers.onError(e instanceof Error ? e : new Error(String(e)));
      }
    },
    current: () => instance,
    destroy() {
      generation++;
      release();
    },
  };
}
