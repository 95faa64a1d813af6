/**
 * The configurator's store: a zustand vanilla store (no React; the UI reads it
 * through selectors) holding the configuration with undo/redo, the selection
 * (outside the undo history) and every action by name. dispatch() runs an
 * action only when enabled, and a bound action is enabled only when its result
 * passes validate() (bindDefinition.ts), so the store only ever holds valid
 * configurations; refusals and bad names/params come back as values.
 */
import { createStore, type StoreApi } from 'zustand/vanilla';
import { InputError } from '../inputError';
import { refuse, type Enablement, type Refusal } from '../model/actions/action';
import { ACTION_NAMES, actionLabel, attemptAction, checkAction, type ActionName } from '../model/actions/actionDefinitions';
import type { Catalog } from '../model/catalogSchema/catalogSchema';
import { createConfiguration, type Configuration } from '../model/configuration/configuration';
import { createHistory, pushHistory, redo, undo, type History } from '../model/configuration/history';
import { validate } from '../model/validation/validate';

export type Selection = { readonly kind: 'system' | 'rail' | 'module' | 'object'; readonly id: string } | null;

export type DispatchResult = { readonly ok: true } | Refusal;

export interface ActionListing {
  readonly name: ActionName;
  readonly label: string;
  readonly enabled: Enablement;
}

export interface ConfiguratorState {
  readonly catalog: Catalog;
  readonly history: History<Configuration>;
  /** The current configuration (history.present). */
  readonly config: Configuration;
  readonly selection: Selection;
  readonly canUndo: boolean;
  readonly canRedo: boolean;
  /** Runs an action by name if enabled; returns the refusal otherwise (never throws for bad input). */
  dispatch(name: string, params?: unknown): DispatchResult;
  isEnabled(name: string, params?: unknown): Enablement;
  /** Every action with its enablement for the params given per action name (missing params usually refuse). */
  listActions(paramsByName?: Partial<Record<ActionName, unknown>>): ActionListing[];
  undo(): boolean;
  redo(): boolean;
  select(selection: Selection): void;
  /** Replaces the configuration (undoable), e.g. from a scene file; refused if it is not valid. */
  load(config: Configuration): DispatchResult;
}

export interface ConfiguratorStoreOptions {
  readonly catalog: Catalog;
  readonly initial?: Configuration;
}

export type ConfiguratorStore = StoreApi<ConfiguratorState>;

function selectionExists(config: Configuration, sel: Selection): boolean {
  if (!sel) return true;
  if (sel.kind === 'object') return config.objects.some((o) => o.id === sel.id);
  return config.systems.some((s) => (sel.kind === 'system' ? s.id === sel.id : s.rails.some((r) => (sel.kind === 'rail' ? r.id === sel.id : r.modules.some((m) => m.id === sel.id)))));
}

export function createConfiguratorStore(options: ConfiguratorStoreOptions): ConfiguratorStore {
  const { catalog } = options;
  const initial = options.initial ?? createConfiguration();
  const problems = validate(initial, catalog, { firstOnly: true });
  if (problems.length > 0) throw new InputError(`initial configuration is invalid: ${problems[0].path}: ${problems[0].message}`);

  return createStore<ConfiguratorState>()((set, get) => {
    const commit = (history: History<Configuration>) => {
      const sel = get().selection;
      set({
        history,
        config: history.present,
        canUndo: history.past.length > 0,
        canRedo: history.future.length > 0,
        selection: selectionExists(history.present, sel) ? sel : null,
      });
    };
    const history = createHistory(initial);
    return {
      catalog,
      history,
      config: initial,
      selection: null,
      canUndo: false,
      canRedo: false,
      dispatch(name, params = {}) {
        // One perform and one validation, reused when the UI asked isEnabled on this state first.
        const outcome = attemptAction(get().config, name, params, catalog);
        if (!outcome.ok) return outcome;
        commit(pushHistory(get().history, outcome.next));
        return { ok: true };
      },
      isEnabled(name, params = {}) {
        return checkAction(get().config, name, params, catalog);
      },
      listActions(paramsByName = {}) {
        const state = get().config;
        return ACTION_NAMES.map((name) => ({
          name,
          label: actionLabel(name),
          enabled: checkAction(state, name, paramsByName[name] ?? {}, catalog),
        }));
      },
      undo() {
        const h = get().history;
        if (h.past.length === 0) return false;
        commit(undo(h));
        return true;
      },
      redo() {
        const h = get().history;
        if (h.future.length === 0) return false;
        commit(redo(h));
        return true;
      },
      select(selection) {
        set({ selection: selectionExists(get().config, selection) ? selection : null });
      },
      load(config) {
        const p = validate(config, catalog, { firstOnly: true });
        if (p.length > 0) return refuse(`${p[0].path}: ${p[0].message}`);
        commit(pushHistory(get().history, config));
        return { ok: true };
      },
    };
  });
}
