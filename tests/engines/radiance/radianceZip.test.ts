import { strFromU8, unzipSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { exportRadiance } from '../../../src/engines/radiance/exportRadiance';
import { radianceZip } from '../../../src/engines/radiance/radianceZip';
import { loadRenderInput } from '../../../src/hosts/node/renderInput';

/** Each central-directory entry's name and Unix mode (PKWARE APPNOTE 4.3.12: signature 0x02014b50). */
function unixModes(zip: Uint8Array): Map<string, number> {
  const view = new DataView(zip.buffer, zip.byteOffset, zip.byteLength);
  const modes = new Map<string, number>();
  for (let i = 0; i + 46 <= zip.length; i++) {
    if (view.getUint32(i, true) !== 0x02014b50) continue;
    const madeBy = view.getUint16(i + 4, true) >> 8;
    const nameLength = view.getUint16(i + 28, true);
    const name = strFromU8(zip.subarray(i + 46, i + 46 + nameLength));
    expect(madeBy).toBe(3);
    modes.set(name, view.getUint32(i + 38, true) >>> 16);
  }
  return modes;
}

describe('radianceZip (the app\'s "Download for Radiance")', () => {
  const files = exportRadiance(loadRenderInput('tests/fixtures/scenes/small-room.json').bakeScene, {}, 'small-room');
  const zip = radianceZip(files, 'small-room-radiance');

  it('holds every file of the export under one folder, byte for byte', () => {
    const unpacked = unzipSync(zip);
    expect(Object.keys(unpacked).sort()).toEqual(files.map((f) => `small-room-radiance/${f.path}`).sort());
    for (const f of files) expect(strFromU8(unpacked[`small-room-radiance/${f.path}`])).toBe(f.text);
  });

  it('keeps render.sh executable (Unix mode 755) and the rest 644', () => {
    const modes = unixModes(zip);
    expect(modes.get('small-room-radiance/render.sh')).toBe(0o100755);
    expect(modes.get('small-room-radiance/scene.rad')).toBe(0o100644);
    expect(modes.size).toBe(files.length);
  });
});
