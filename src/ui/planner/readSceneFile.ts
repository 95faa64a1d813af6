import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { sceneTextNeedsLazyModel } from '../../core/model/configuration/roomShapeSupport';
import { loadRoomShapeSupport } from '../../core/model/actions/loadRoomShapeSupport';
import type { Configuration } from '../../core/model/configuration/configuration';
import { deserializeConfiguration } from '../../core/model/files/sceneFile';
import { SceneFileError } from '../../core/model/files/sceneFileError';

/**
 * Largest scene file "Open file…" reads. A configuration of the model's largest room full of
 * systems is a few hundred kB of pretty JSON; anything bigger is not a luxbox file, and refusing
 * it before reading keeps a mistaken pick (a video, a disk image) from freezing the page.
 */
export const MAX_SCENE_FILE_BYTES = 1_000_000;

/** What readSceneFile needs of a browser File (a Blob with a name); keeps it testable in Node. */
export interface NamedTextFile {
  readonly name: string;
  readonly size: number;
  text(): Promise<string>;
}

/**
 * Reads a user-picked scene file into a validated configuration. Throws SceneFileError (an
 * InputError) whose message names the file and the problem: too large, unreadable, not JSON,
 * not a luxbox configuration, or invalid (deserializeConfiguration's checks).
 */
export async function readSceneFile(file: NamedTextFile, catalog: Catalog): Promise<Configuration> {
  const source = `“${file.name}”`;
  if (file.size > MAX_SCENE_FILE_BYTES) {
    throw new SceneFileError(`${source} is too large to be a luxbox configuration (${(file.size / 1e6).toFixed(1)} MB; at most ${MAX_SCENE_FILE_BYTES / 1e6} MB)`, {
      code: 'fileTooLargeForConfiguration',
      params: { name: file.name, size: Number((file.size / 1e6).toFixed(1)), max: MAX_SCENE_FILE_BYTES / 1e6 },
    });
  }
  let text: string;
  try {
    text = await file.text();
  } catch (e) {
    const problem = e instanceof Error ? e.message : String(e);
    throw new SceneFileError(`${source} could not be read (${problem})`, { code: 'fileUnreadable', params: { name: file.name, problem } });
  }
  // A room of any shape needs its chunk before the reader can judge it (roomShapeSupport.ts).
  if (sceneTextNeedsLazyModel(text)) await loadRoomShapeSupport();
  return deserializeConfiguration(text, catalog, source);
}
