import { MAX_STORED_NAME_LENGTH } from '../../core/model/files/storedMeshSize';
import { shortName } from './readMtlMaterials';

/**
 * A name the import keeps (the model's file name, a material's name) cut to what the scene file's
 * schema accepts (MAX_STORED_NAME_LENGTH, 200 characters), with a warning, so the configuration
 * that holds it saves and reopens (issue 32: a 300-character glTF material name made a file that
 * did not reopen). A cut never splits a surrogate pair.
 */
export function keptName(name: string, what: string, warnings: string[]): string {
  if (name.length <= MAX_STORED_NAME_LENGTH) return name;
  let cut = name.slice(0, MAX_STORED_NAME_LENGTH);
  if (/[\uD800-\uDBFF]$/.test(cut)) cut = cut.slice(0, -1);
  warnings.push(`${what} '${shortName(name)}' has ${name.length} characters; cut to ${cut.length}`);
  return cut;
}
