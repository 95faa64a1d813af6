import { writeFileSync } from 'node:fs';

/**
 * Portable float map, colour ("PF"): header `PF\n<w> <h>\n-1.0\n` (a negative
 * scale means little-endian), then RGB float32 rows from the BOTTOM row up
 * (the PFM convention, http://www.pauldebevec.com/Research/HDR/PFM/). Our maps
 * already store row j = 0 (v = 0) first, so they are written as they are and
 * the image's up is +v (docs/baker.md).
 */
export function encodePfm(width: number, height: number, rgb: Float32Array): Buffer {
  if (rgb.length !== width * height * 3) throw new Error(`PFM: ${rgb.length} floats for ${width}×${height} RGB`);
  const header = Buffer.from(`PF\n${width} ${height}\n-1.0\n`, 'ascii');
  const body = Buffer.alloc(rgb.length * 4);
  for (let i = 0; i < rgb.length; i++) body.writeFloatLE(rgb[i], i * 4);
  return Buffer.concat([header, body]);
}

/** Portable float map, grey ("Pf"): one float32 per texel, same layout and header rules as encodePfm. */
export function encodePfmGrey(width: number, height: number, values: Float32Array): Buffer {
  if (values.length !== width * height) throw new Error(`PFM: ${values.length} floats for ${width}×${height} grey`);
  const header = Buffer.from(`Pf\n${width} ${height}\n-1.0\n`, 'ascii');
  const body = Buffer.alloc(values.length * 4);
  for (let i = 0; i < values.length; i++) body.writeFloatLE(values[i], i * 4);
  return Buffer.concat([header, body]);
}

export function writePfm(path: string, width: number, height: number, rgb: Float32Array): void {
  writeFileSync(path, encodePfm(width, height, rgb));
}

/** Read a PFM written by encodePfm (or any colour/grey PFM of either endianness): RGB floats, bottom row first. */
export function decodePfm(data: Buffer): { width: number; height: number; rgb: Float32Array } {
  const text = data.subarray(0, 64).toString('latin1');
  const m = /^(PF|Pf)\s+(\d+)\s+(\d+)\s+(-?[\d.eE+-]+)\s/.exec(text);
  if (!m) throw new Error('not a PFM file');
  const channels = m[1] === 'PF' ? 3 : 1;
  const width = Number(m[2]);
  const height = Number(m[3]);
  const little = Number(m[4]) < 0;
  let offset = m[0].length;
  const rgb = new Float32Array(width * height * 3);
  for (let i = 0; i < width * height; i++) {
    for (let c = 0; c < 3; c++) {
      const k = channels === 3 ? c : 0;
      rgb[i * 3 + c] = little ? data.readFloatLE(offset + k * 4) : data.readFloatBE(offset + k * 4);
    }
    offset += channels * 4;
  }
  return { width, height, rgb };
}
