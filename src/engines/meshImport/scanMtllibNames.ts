import { decodeText } from './decodeText';

/** The material library names an OBJ file's `mtllib` lines list, each once (no other checks: scanObjText does those). */
export function scanMtllibNames(bytes: Uint8Array): string[] {
  const names: string[] = [];
  for (const match of decodeText(bytes).matchAll(/^[ \t]*mtllib[ \t]+([^\r\n]+)/gm)) {
    for (const name of match[1].trim().split(/\s+/)) if (!names.includes(name)) names.push(name);
  }
  return names;
}
