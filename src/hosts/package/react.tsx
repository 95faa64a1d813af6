// The package's React door, `luxbox/react` (docs/package.md): `<Luxbox />` for React and Next.js
// shops. Built against the shop's own React (a peer dependency, vite.lib.config.ts), so the page
// ships one React; the configurator renders into its own root inside the component's element.
import { forwardRef, useEffect, useImperativeHandle, useRef, useState, type CSSProperties } from 'react';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { LuxboxInstance, LuxboxOptions } from '../embed/types';
import { createMountController, type MountController } from './createMountController';

export type { LuxboxInstance, LuxboxOptions } from '../embed/types';
export type { ActionName, ActionParams } from '../../core/model/actions/actionDefinitions';
export type { BillOfMaterials } from '../../core/model/power/billOfMaterials';
export type { Catalog } from '../../core/model/catalogSchema/catalogSchema';

/** Props of `<Luxbox>`: mountLuxbox's options (docs/embedding.md), the catalog also as a URL, and the element's class and style. */
export interface LuxboxProps extends Omit<LuxboxOptions, 'catalog'> {
  /**
   * The URL of a catalog.json (fetched; the photometry is looked up beside it unless `assetBase`
   * says otherwise), or catalog data (docs/catalog-format.md); default: the bundled demo catalog.
   */
  catalog?: string | Catalog;
  /** Called with the instance once the configurator is mounted (again after a remount). */
  onReady?: (instance: LuxboxInstance) => void;
  /** Called when mounting fails: a catalog that does not load or validate, or bad options (an InputError naming the option). Without it the error is logged. */
  onError?: (error: Error) => void;
  className?: string;
  /** Give the element a height (e.g. `{ height: '80vh' }`): the configurator fills it (docs/embedding.md, "Styles"). */
  style?: CSSProperties;
}

const CALLBACKS = ['onChange', 'onLanguageChange', 'onExpertChange', 'onReady', 'onError'] as const;

/** The mount-time options a change of which remounts (callbacks are read through a ref and never remount). */
function mountKey(props: LuxboxProps): string {
  const { className: _c, style: _s, ...rest } = props;
  for (const name of CALLBACKS) delete (rest as Record<string, unknown>)[name];
  return JSON.stringify(rest);
}

/**
 * The luxbox configurator as a React component. `ref` receives the LuxboxInstance (typed
 * actions, bill of materials, undo; null until mounted). Options are mount-time: when a prop other
 * than a callback changes, the configurator mounts again and keeps the user's configuration if the
 * catalog is the same.
 */
export const Luxbox = forwardRef<LuxboxInstance, LuxboxProps>(function Luxbox(props, ref) {
  const element = useRef<HTMLDivElement>(null);
  const latest = useRef(props);
  latest.current = props;
  const controller = useRef<MountController | null>(null);
  const [instance, setInstance] = useState<LuxboxInstance | null>(null);
  // Before mounting (and after a failed mount) the ref holds null, as React's refs do until set.
  useImperativeHandle(ref, () => instance as LuxboxInstance, [instance]);

  useEffect(() => {
    const host = element.current!;
    const c = createMountController(host, {
      onMount: (next) => {
        setInstance(next);
        latest.current.onReady?.(next);
      },
      onError: (error) => {
        setInstance(null);
        if (latest.current.onError) latest.current.onError(error);
        else console.error('luxbox: mounting failed', error);
      },
    });
    controller.current = c;
    return () => {
      c.destroy();
      controller.current = null;
      setInstance(null);
    };
  }, []);

  const key = mountKey(props);
  useEffect(() => {
    const { catalog, className: _c, style: _s, onReady: _r, onError: _e, ...options } = latest.current;
    void controller.current?.mount({
      ...(catalog !== undefined ? { catalog } : {}),
      options: {
        ...options,
        onChange: (json) => latest.current.onChange?.(json),
        onLanguageChange: (language) => latest.current.onLanguageChange?.(language),
        onExpertChange: (on) => latest.current.onExpertChange?.(on),
      },
    });
  }, [key]);

  return <div ref={element} className={props.className} style={props.style} />;
});
