import en from './messages/en/index';
import type { Language } from './languages';
import type { MessageTree } from './messageTypes';

// English ships in the first-screen bundle; every other language is its own lazy chunk, fetched
// before the first render only when the locale asks for it (docs/i18n.md, "Bundles"). English's
// 3D-only areas join the tree when the 3D chunk registers them (registerEnglishAreas).
const english = en as MessageTree;
const loaded: Partial<Record<Language, MessageTree>> = { en: english };

/**
 * Adds English areas that ship in a lazy chunk (the 3D view's) to the English tree, which is
 * also every language's fallback; idempotent. Called by that chunk before it renders.
 */
export function registerEnglishAreas(areas: Partial<MessageTree>): void {
  Object.assign(english, areas);
}

const loaders: Record<Exclude<Language, 'en'>, () => Promise<{ default: MessageTree }>> = {
  de: () => import('./messages/de/index'),
  fr: () => import('./messages/fr/index'),
  it: () => import('./messages/it/index'),
};

/** The messages of `language` if already loaded (English always is). */
export function loadedMessages(language: Language): MessageTree | undefined {
  return loaded[language];
}

/**
 * English messages of the core's codes (messages/en/core.ts): an English page shows the core's own
 * sentences, so they come with the first other language, whose lookups of `refusals.<code>` …
 * they make known (isMessageKey); registered once.
 */
let coreEnglish: Promise<void> | undefined;
export function loadCoreEnglish(): Promise<void> {
  coreEnglish ??= import('./messages/en/core').then((m) => registerEnglishAreas(m.default as Partial<MessageTree>));
  return coreEnglish;
}

/** Loads (once) and returns the messages of `language`. */
export async function loadMessages(language: Language): Promise<MessageTree> {
  const have = loaded[language];
  if (have) return have;
  const [mod] = await Promise.all([loaders[language as Exclude<Language, 'en'>](), loadCoreEnglish()]);
  loaded[language] = mod.default;
  return mod.default;
}
