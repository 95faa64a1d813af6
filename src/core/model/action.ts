/**
 * The always-valid action contract (configurator paper §3.2): every user action is
 * `{ name, isEnabled(state), perform(state) }` on immutable state. The UI
 * disables exactly what isEnabled refuses and shows the reason. `perform` is
 * the raw operation: it does not re-check isEnabled (the store does), so tests
 * can prove that every refused action really would have broken validate().
 */
import type { z } from 'zod';
import type { Catalog } from './catalogSchema';
import type { Configuration } from './configuration';

export interface Refusal {
  readonly ok: false;
  /** One human-readable sentence: why the action is not possible now. */
  readonly reason: string;
}

/** `true` when the action may run, otherwise a refusal with the reason. */
export type Enablement = true | Refusal;

export function refuse(reason: string): Refusal {
  return { ok: false, reason };
}

/** An action definition: parameterised, catalog-aware. Registered by name in `actionDefinitions`. */
export interface ActionDefinition<P> {
  readonly name: string;
  /** Short label for buttons and menus. */
  readonly label: string;
  /** Validates the parameters (from UI, embedding API or a test). */
  readonly params: z.ZodType<P>;
  isEnabled(state: Configuration, params: P, catalog: Catalog): Enablement;
  /** Raw transition; may throw InputError for unknown ids. Callers check isEnabled first. */
  perform(state: Configuration, params: P, catalog: Catalog): Configuration;
}

/** An action bound to its parameters and catalog: the configurator paper's `{ isEnabled(state), perform(state) }`. */
export interface UserAction {
  readonly name: string;
  readonly params: unknown;
  isEnabled(state: Configuration): Enablement;
  perform(state: Configuration): Configuration;
}
