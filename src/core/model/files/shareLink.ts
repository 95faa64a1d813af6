/** Share links: the scene file as URL-safe text (base64url of compact JSON), and back. */
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { Configuration } from '../configuration/configuration';
import { sourceName } from '../objects/objectGeometry';
import { deserializeConfiguration, serializeConfiguration } from './sceneFile';
import { SceneFileError } from './sceneFileError';

/** Share strings longer than this are refused before decoding (browsers cap URLs near 64k). */
export const MAX_SHARE_STRING = 60_000;

/** An object a share link leaves out (imported models are not in links: they can be megabytes). */
export interface LeftOutObject {
  readonly objectId: string;
  /** The imported file's name ('kitchen.obj'). */
  readonly name: string;
}

/** A share link's text and what it could not carry, with the sentence to show the user (null when complete). */
export interface ShareLink {
  readonly text: string;
  readonly leftOut: readonly LeftOutObject[];
  readonly notice: string | null;
}

/**
 * The share string of a configuration: library objects travel in it, imported ones (and their
 * meshes) are left out and listed, so the UI can tell the user — never silently dropped.
 */
export function encodeShareLink(config: Configuration, catalog: Catalog): ShareLink {
  const leftOut: LeftOutObject[] = config.objects.filter((o) => o.source.kind === 'imported').map((o) => ({ objectId: o.id, name: sourceName(config, o.source) }));
  const shared: Configuration = leftOut.length === 0 ? config : { ...config, objects: config.objects.filter((o) => o.source.kind !== 'imported'), importedMeshes: {} };
  const names = [...new Set(leftOut.map((o) => `'${o.name}'`))];
  const notice = names.length === 0 ? null : `the imported model${names.length > 1 ? 's' : ''} ${names.join(', ')} ${names.length > 1 ? 'are' : 'is'} not in the link; save the file to keep ${names.length > 1 ? 'them' : 'it'}`;
  return { text: encodeShareBytes(serializeConfiguration(shared, catalog, 0)), leftOut, notice };
}

/**
 * base64url (RFC 4648 §5, no padding) of the compact scene-file JSON (no indentation), for
 * share links. Links written with indented JSON (before issue 18) decode all the same.
 */
export function encodeShareString(config: Configuration, catalog: Catalog): string {
  const link = encodeShareLink(config, catalog);
  // Never silently incomplete: callers that can tell the user use encodeShareLink.
  if (link.notice) throw new SceneFileError(link.notice);
  return link.text;
}

function encodeShareBytes(json: string): string {
  const bytes = new TextEncoder().encode(json);
  let bin = '';
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** A share string's scene-file text (base64url of UTF-8 JSON); throws SceneFileError when it is damaged. */
export function shareStringText(s: string): string {
  if (s.length === 0) throw new SceneFileError('share link is empty', { code: 'shareLinkEmpty' });
  if (s.length > MAX_SHARE_STRING) throw new SceneFileError(`share link is too long (${s.length} characters, at most ${MAX_SHARE_STRING})`, { code: 'shareLinkTooLong', params: { length: s.length, max: MAX_SHARE_STRING } });
  if (!/^[A-Za-z0-9_-]+$/.test(s)) throw new SceneFileError('share link is damaged (characters outside base64url)', { code: 'shareLinkCharacters' });
  if (s.length % 4 === 1) throw new SceneFileError('share link is damaged (truncated)', { code: 'shareLinkTruncated' });
  const bin = atob(s.replace(/-/g, '+').replace(/_/g, '/') + '='.repeat((4 - (s.length % 4)) % 4));
  try {
    return new TextDecoder('utf-8', { fatal: true }).decode(Uint8Array.from(bin, (c) => c.charCodeAt(0)));
  } catch {
    throw new SceneFileError('share link is damaged (not UTF-8 text)', { code: 'shareLinkNotUtf8' });
  }
}

export function decodeShareString(s: string, catalog: Catalog): Configuration {
  return deserializeConfiguration(shareStringText(s), catalog, 'share link');
}
