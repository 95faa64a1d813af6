import { createStore, type StoreApi } from 'zustand/vanilla';
import type { CodedText } from '../inputError';

/**
 * A message for people: the English `text` (logs, the embedding API, tests) and, where the UI
 * translates it, a stable `code` with its `params` (docs/i18n.md, "Messages from the core").
 */
export interface UiMessage {
  text: string;
  code?: string;
  params?: Record<string, string | number>;
  /** The coded sentence the message quotes (a link's or saved file's error): worded by the UI as `{problem}`. */
  detail?: CodedText;
}

/**
 * UI state that is not part of the configuration (so undo/redo never touch it): which screen
 * is shown, panels, the message banner and the transient status line. A plain vanilla store so
 * the embedding API can drive it (setConfig leaves the room-setup screen) without React.
 */
export interface UiState {
  phase: 'setup' | 'planner';
  /** 2D plan or the 3D view. */
  mode: '2d' | '3d';
  optionsOpen: boolean;
  /** The side panel on narrow screens (always shown on wide ones). */
  panelOpen: boolean;
  /**
   * Whether the side panel is a drawer (a narrow box, below 900 px: the planner measures it). In a
   * drawer the options are shown only while the drawer is open, so closing it closes them too.
   */
  drawer: boolean;
  /** A persistent message (e.g. a broken share link) until dismissed. */
  banner: (UiMessage & { canRestore: boolean }) | null;
  /** A short message (why a control is disabled); `seq` lets a repeated message re-trigger. */
  status: (UiMessage & { seq: number }) | null;
  /** The last share link created, shown so it can be copied by hand. */
  shareLink: string | null;
  /** What the header shows as the maker (a shop's or manufacturer's name and logo), or null for nothing; default luxbox. */
  brand: Brand | null;
  /**
   * Whether the expert tools show (docs/embedding.md, option `expert`): DMX live control, the
   * Radiance download and the photometric files' data notes. Shoppers see none of them by default.
   */
  expert: boolean;
  /** Whether the side panel offers the Expert switch (the shop lets the user choose). */
  expertSwitch: boolean;
  /** The plan's room-shape mode (issue 29, docs/planner.md "Rooms of any shape"): corner handles, wall lengths, the edit sheet. */
  roomEdit: boolean;
  /**
   * Which light the 3D view shows (issue 30, docs/daylight.md "The shopper's daylight"): the
   * luminaires, the daylight through the windows, or both (the relight engine's weights, no bake).
   */
  lightSources: 'electric' | 'daylight' | 'both';
}

/** The brand in the configurator's header (docs/embedding.md, option `brand`). */
export interface Brand {
  /** Shown as the heading, and as the logo's text alternative. */
  name: string;
  /** An image URL (the shop's logo) shown instead of the name's text. */
  logo?: string;
}

/** The header's brand when the host sets none. */
export const DEFAULT_BRAND: Brand = { name: 'luxbox' };

export type UiStore = StoreApi<UiState>;

/** Whether the options are on screen: open, and not inside a closed drawer. */
export function optionsShown(s: Pick<UiState, 'optionsOpen' | 'panelOpen' | 'drawer'>): boolean {
  return s.optionsOpen && (s.panelOpen || !s.drawer);
}

export function createUiStore(initial: Partial<UiState> = {}): UiStore {
  const store = createStore<UiState>()(() => ({
    phase: 'setup',
    mode: '2d',
    optionsOpen: false,
    panelOpen: false,
    drawer: false,
    banner: null,
    status: null,
    shareLink: null,
    brand: DEFAULT_BRAND,
    expert: false,
    expertSwitch: false,
    roomEdit: false,
    lightSources: 'both',
    ...initial,
  }));
  // One rule for every way a drawer closes (its toggle, a tap beside it, an action that closes it
  // to show the plan): the options close with it, so the Options button never stays pressed over
  // a closed drawer and its next tap opens them again.
  store.subscribe((s, prev) => {
    if (s.drawer && s.optionsOpen && !s.panelOpen && (prev.panelOpen || !prev.drawer)) store.setState({ optionsOpen: false });
  });
  return store;
}

export function showStatus(ui: UiStore, text: string, coded?: Omit<UiMessage, 'text'>): void {
  const seq = (ui.getState().status?.seq ?? 0) + 1;
  ui.setState({ status: { text, seq, ...coded } });
}
