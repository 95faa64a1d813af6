import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { createConfiguration, type Configuration } from '../../core/model/configuration/configuration';
import { deserializeConfiguration } from '../../core/model/files/sceneFile';
import { decodeShareString, shareStringText } from '../../core/model/files/shareLink';
import { sceneTextNeedsLazyModel } from '../../core/model/configuration/roomShapeSupport';
import { codedText, InputError, type CodedText } from '../../core/inputError';
import { firstImpression } from '../../ui/viewer/firstImpression';
import type { UiMessage } from '../../core/store/uiStore';

/** The URL hash prefix of a share link: `#c=<base64url scene file>` (src/core/model/files/sceneFile.ts). */
export const SHARE_HASH_PREFIX = '#c=';

export interface StartupInput {
  catalog: Catalog;
  /** location.hash, when share links are read ('' otherwise). */
  hash: string;
  /** The autosaved scene-file JSON, if any. */
  saved: string | null;
  /** A room the host page asked for (embedding option). */
  room?: { width: number; depth: number; height: number };
  /** Open the demo instead of the room setup when nothing else applies (dev server, `?demo`). */
  demo?: boolean;
}

export interface Startup {
  config: Configuration;
  phase: 'setup' | 'planner';
  /** A message to show until dismissed (broken link, unreadable autosave). */
  banner: (UiMessage & { canRestore: boolean }) | null;
  /** Whether to write `config` to the autosave right away (a valid share link was opened). */
  saveNow: boolean;
  /** Whether the hash was consumed and should be removed from the address bar. */
  clearHash: boolean;
}

function message(e: unknown): string {
  return e instanceof InputError ? e.message : 'unexpected error';
}

/** The error as a coded sentence, for a banner that quotes it (docs/i18n.md); nothing for an uncoded one. */
function detail(e: unknown): { detail?: CodedText } {
  return e instanceof InputError && e.code ? { detail: codedText(e.message, e) } : {};
}

/**
 * Decides what the configurator opens with, in order: a share link in the URL hash, the local
 * autosave, the host's room, the demo when asked for, else the room-setup screen. A broken or foreign link opens an
 * empty valid room with a message and never touches the autosave (saveNow false, and nothing
 * is saved until the user changes something), so the user's own work survives a bad link.
 */
export function resolveStartup({ catalog, hash, saved, room, demo }: StartupInput): Startup {
  let savedConfig: Configuration | null = null;
  let savedError: string | null = null;
  if (saved) {
    try {
      savedConfig = deserializeConfiguration(saved, catalog, 'saved configuration');
    } catch (e) {
      savedError = message(e);
    }
  }

  if (hash && hash !== '#') {
    if (hash.startsWith(SHARE_HASH_PREFIX)) {
      try {
        const config = decodeShareString(hash.slice(SHARE_HASH_PREFIX.length), catalog);
        return { config, phase: 'planner', banner: null, saveNow: true, clearHash: true };
      } catch (e) {
        return {
          config: createConfiguration(),
          phase: 'planner',
          banner: { text: `This link could not be opened: ${message(e)}. Showing an empty room instead.`, code: 'linkBroken', params: { problem: message(e) }, ...detail(e), canRestore: savedConfig !== null },
          saveNow: false,
          clearHash: true,
        };
      }
    }
    return {
      config: createConfiguration(),
      phase: 'planner',
      banner: { text: 'This link does not contain a luxbox configuration. Showing an empty room instead.', code: 'linkForeign', canRestore: savedConfig !== null },
      saveNow: false,
      clearHash: true,
    };
  }

  if (savedConfig) return { config: savedConfig, phase: 'planner', banner: null, saveNow: false, clearHash: false };
  const banner = savedError ? { text: `Your saved configuration could not be read (${savedError}).`, code: 'savedUnreadable', params: { problem: savedError }, canRestore: false } : null;
  if (room) return { config: createConfiguration(room), phase: 'planner', banner, saveNow: false, clearHash: false };
  if (demo) return { config: firstImpression(catalog), phase: 'planner', banner, saveNow: false, clearHash: false };
  return { config: createConfiguration(), phase: 'setup', banner, saveNow: false, clearHash: false };
}

/**
 * Whether what the configurator opens with (resolveStartup's order: the share link, else the
 * autosave) has a room of any shape, so that the room-shape chunk must load first
 * (roomShapeSupport.ts): the user's shaped room then opens shaped, never as a refusal or a box.
 */
export function startupNeedsRoomShape(hash: string, saved: string | null): boolean {
  // The autosave counts even under a link: the link's banner offers to restore it.
  if (sceneTextNeedsLazyModel(saved)) return true;
  if (!hash.startsWith(SHARE_HASH_PREFIX)) return false;
  try {
    return sceneTextNeedsLazyModel(shareStringText(hash.slice(SHARE_HASH_PREFIX.length)));
  } catch {
    // A damaged link opens as an empty room with its message.
    return false;
  }
}
