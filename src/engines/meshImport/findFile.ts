import type { MeshFile } from './importedMesh';

/**
 * The file a model refers to (`mtllib kitchen.mtl`, a glTF buffer `uri`) among the files the user
 * picked: by its last path component, exactly, else ignoring case (Windows exporters write names in
 * any case). URIs are percent-decoded (glTF 2.0 §3.6.2: URIs are RFC 3986).
 */
export function findFile(files: readonly MeshFile[], reference: string): MeshFile | undefined {
  const base = lastComponent(reference);
  return files.find((f) => lastComponent(f.name) === base) ?? files.find((f) => lastComponent(f.name).toLowerCase() === base.toLowerCase());
}

function lastComponent(path: string): string {
  let decoded: string;
  try {
    decoded = decodeURIComponent(path);
  } catch {
    decoded = path;
  }
  const parts = decoded.split(/[\\/]/);
  return parts[parts.length - 1];
}
