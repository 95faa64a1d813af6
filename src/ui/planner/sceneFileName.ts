import type { Configuration } from '../../core/model/configuration/configuration';

/**
 * The name a saved configuration is offered under: `luxbox-<W>x<D>x<H>.luxbox.json` with the
 * room's width, depth and height in metres (e.g. `luxbox-5x4x2.8.luxbox.json`), so several saved
 * rooms are told apart in a downloads folder and the `.json` ending opens in any editor.
 */
export function sceneFileName(config: Configuration): string {
  const { width, depth, height } = config.room;
  return `luxbox-${width}x${depth}x${height}.luxbox.json`;
}
