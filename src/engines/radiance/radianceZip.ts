import { strToU8, zipSync, type Zippable } from 'fflate';
import type { ExportFile } from './exportRadiance';

/**
 * An export as one zip (the app's "Download for Radiance"): every file under `folder/`, with
 * Unix permissions so `render.sh` stays executable when unpacked (external attributes hold the
 * mode in their high 16 bits when the "made by" system is Unix, 3: PKWARE APPNOTE 4.4.2, 4.4.15).
 */
export function radianceZip(files: readonly ExportFile[], folder: string): Uint8Array {
  const entries: Zippable = {};
  for (const file of files) {
    const mode = file.executable ? 0o100755 : 0o100644;
    entries[`${folder}/${file.path}`] = [strToU8(file.text), { os: 3, attrs: mode * 0x10000 }];
  }
  return zipSync(entries, { level: 6 });
}
