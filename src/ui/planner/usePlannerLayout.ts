import { useEffect, useLayoutEffect, useState, type RefObject } from 'react';
import type { UiState, UiStore } from '../../core/store/uiStore';
import { DEFAULT_VIEWPORT } from './PlannerController';
import type { Viewport } from './viewTransform';

/** The box width (px) up to which the side panel is a drawer: `@container luxbox (max-width: 900px)` in app.css. */
const DRAWER_MAX_WIDTH = 900;

/** The plan's size in whole pixels, measured when it mounts (again with each mode) and whenever it resizes. */
export function usePlanViewport(wrapRef: RefObject<HTMLDivElement | null>, mode: string): Viewport {
  const [viewport, setViewport] = useState<Viewport>(DEFAULT_VIEWPORT);
  useLayoutEffect(() => {
    const el = wrapRef.current;
    if (!el) return;
    const measure = () => {
      const r = el.getBoundingClientRect();
      if (r.width < 1 || r.height < 1) return;
      const vp = { width: Math.round(r.width), height: Math.round(r.height) };
      setViewport((old) => (old.width === vp.width && old.height === vp.height ? old : vp));
    };
    measure();
    const ro = new ResizeObserver(measure);
    ro.observe(el);
    return () => ro.disconnect();
  }, [mode, wrapRef]);
  return viewport;
}

/** Status messages disappear after a few seconds (they explain, they do not block). */
export function useStatusExpiry(ui: UiStore, status: UiState['status']): void {
  useEffect(() => {
    if (!status) return;
    const t = window.setTimeout(() => ui.setState({ status: null }), 4000);
    return () => window.clearTimeout(t);
  }, [status, ui]);
}

/**
 * The side panel as a drawer: whether it is one (the same 900 px of the box as the container query
 * in app.css), and a press beside the open drawer closes it and still reaches what it was on (the
 * plan, a bottom-bar button): the veil only dims what is beside the drawer and takes no taps. The
 * header's toggle closes it by itself, and a tip at a refused control in the drawer belongs to the drawer.
 */
export function useDrawer(ui: UiStore, bodyRef: RefObject<HTMLDivElement | null>, panelRef: RefObject<HTMLElement | null>, panelOpen: boolean): void {
  useLayoutEffect(() => {
    const el = bodyRef.current;
    if (!el) return;
    const measure = () => {
      const drawer = el.getBoundingClientRect().width <= DRAWER_MAX_WIDTH;
      if (ui.getState().drawer !== drawer) ui.setState({ drawer });
    };
    measure();
    const ro = new ResizeObserver(measure);
    ro.observe(el);
    return () => ro.disconnect();
  }, [ui, bodyRef]);
  useEffect(() => {
    const body = bodyRef.current;
    if (!panelOpen || !body) return;
    const press = (e: PointerEvent) => {
      const target = e.target as Element;
      if (ui.getState().drawer && !panelRef.current?.contains(target) && !target.closest('.panel-toggle, .disabled-tip')) ui.setState({ panelOpen: false });
    };
    body.addEventListener('pointerdown', press, true);
    return () => body.removeEventListener('pointerdown', press, true);
  }, [panelOpen, ui, bodyRef, panelRef]);
}
