import type { ModuleTypeSpec } from '../../../core/model/catalogSchema/moduleTypeSchema';

/**
 * The key of a module type's loaded L3D body (catalog `model`, and `modelEmitter` when it names the
 * light-emitting object: the same file with another emitter is another body, its photometric centre
 * elsewhere), or null without a model.
 */
export function modelBodyKey(type: Pick<ModuleTypeSpec, 'model' | 'modelEmitter'>): string | null {
  if (!type.model) return null;
  return type.modelEmitter === undefined ? type.model : `${type.model}#${type.modelEmitter}`;
}
