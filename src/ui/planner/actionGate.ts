import { checkAction, type ActionName, type ActionParams } from '../../core/model/actions/actionDefinitions';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { Refusal } from '../../core/model/actions/action';

/**
 * How the planner asks the model whether an action may run and runs it. Every control's
 * disabled state is `reason(...)` — the model's own isEnabled — so the UI cannot disagree with
 * the rules.
 */
export interface ActionGate {
  /** null when enabled, else the model's reason. */
  reason<N extends ActionName>(name: N, params: ActionParams<N>): string | null;
  /** Runs an action (the store re-checks isEnabled and records it for undo). */
  run<N extends ActionName>(name: N, params: ActionParams<N>): void;
  /** Runs an action if it is enabled; returns null when it ran, else the reason (what a CommitField's onCommit returns). */
  attempt<N extends ActionName>(name: N, params: ActionParams<N>): string | null;
  /** Shows why something cannot be done (status line for touch users). */
  explain(reason: string): void;
}

export function createActionGate(
  config: Configuration,
  catalog: Catalog,
  run: (name: ActionName, params: unknown) => void,
  explain: (reason: string) => void,
  /** The refusal as shown: the planner passes the UI language's wording of its code (docs/i18n.md); default its English reason. */
  describe: (refusal: Refusal) => string = (r) => r.reason,
): ActionGate {
  const reason = (name: ActionName, params: unknown): string | null => {
    const e = checkAction(config, name, params, catalog);
    return e === true ? null : describe(e);
  };
  return {
    reason,
    run(name, params) {
      run(name, params);
    },
    attempt(name, params) {
      const r = reason(name, params);
      if (r === null) run(name, params);
      return r;
    },
    explain,
  };
}
