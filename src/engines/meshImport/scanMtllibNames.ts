import { checkByteCap, MODEL_BYTE_CAPS } from './byteCaps';
import { decodeText } from './decodeText';

/**
 * The material library names an OBJ file's `mtllib` lines list, each once (no other checks:
 * scanObjText does those); the OBJ byte cap first, so a huge file is never decoded.
 */
export function scanMtllibNames(bytes: Uint8Array, file: string): string[] {
  checkByteCap(file, bytes.length, MODEL_BYTE_CAPS.obj, 'an OBJ file');
  const names: string[] = [];
  for (const match of decodeText(bytes).matchAll(/^[ \t]*mtllib[ \t]+([^\r\n]+)/gm)) {
    for (const name of match[1].trim().split(/\s+/)) if (!names.includes(name)) names.push(name);
  }
  return names;
}
