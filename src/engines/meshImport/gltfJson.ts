/** A JSON object of a glTF file (untrusted: every field is checked where it is read). */
export type Json = Record<string, unknown>;

export interface GltfJson extends Json {
  materials?: Json[];
}

/** A top-level or nested array field; absent = []; anything else is an error naming the field. */
export function list(parent: Json, key: string, fail: (p: string) => never, where = key): unknown[] {
  const value = parent[key];
  if (value === undefined) return [];
  if (!Array.isArray(value)) fail(`${where} must be an array`);
  return value as unknown[];
}

/** The array's i-th entry, which must be an object; anything else is an error naming it. */
export function objectAt(array: unknown[], i: number, where: string, fail: (p: string) => never): Json {
  const value = array[i];
  if (typeof value !== 'object' || value === null || Array.isArray(value)) fail(`${where}[${i}] must be an object`);
  return value as Json;
}
