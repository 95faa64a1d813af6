import { useSyncExternalStore, type ReactNode } from 'react';
import type { I18n } from './createI18n';
import { I18nContext } from './i18nContext';

export interface I18nProviderProps {
  i18n: I18n;
  children: ReactNode;
}

/**
 * Gives its subtree the language of `i18n`. Renders nothing until that language's messages are
 * loaded, so a German shopper never sees an English first frame.
 */
export function I18nProvider({ i18n, children }: I18nProviderProps) {
  const snapshot = useSyncExternalStore(i18n.subscribe, i18n.getSnapshot, i18n.getSnapshot);
  if (!snapshot.ready) return null;
  return <I18nContext.Provider value={snapshot}>{children}</I18nContext.Provider>;
}
