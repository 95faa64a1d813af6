import { attemptAction, type ActionName } from '../../core/model/actions/actionDefinitions';
import { remedyFor } from '../../core/model/guidance/remedy';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { Format } from '../i18n/createFormat';
import type { Language } from '../i18n/languages';
import type { Translate } from '../i18n/messageTypes';
import { remedyText } from './remedyText';

/** A remedy as the tip offers it: its words in the UI language and the one tap that performs it. */
export interface RemedyOffer {
  readonly label: string;
  run(): void;
}

/**
 * The model's remedy for a refused action on the store's configuration (core remedyFor), worded in
 * the UI language. Its run performs the steps and commits the result as one undoable change (the
 * store's load, which validates it once more); `onRefused` hears why, should the configuration have
 * changed in between so that a step is refused.
 */
export function remedyOffer(store: ConfiguratorStore, name: ActionName, params: unknown, words: { t: Translate; format: Format; language: Language }, onRefused: (reason: string) => void = () => {}): RemedyOffer | null {
  const { config, catalog } = store.getState();
  const r = remedyFor(config, name, params as Record<string, unknown>, catalog);
  if (!r) return null;
  return {
    label: remedyText(words.t, words.format, words.language, r),
    run() {
      let next = store.getState().config;
      for (const step of r.steps) {
        const o = attemptAction(next, step.name, step.params, catalog);
        if (!o.ok) return onRefused(o.reason);
        next = o.next;
      }
      const done = store.getState().load(next);
      if (!done.ok) onRefused(done.reason);
    },
  };
}
