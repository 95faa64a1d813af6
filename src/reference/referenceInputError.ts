import { InputError } from '../core/inputError';

/** Bad input to the CPU reference solver (a malformed scene, a missing photometry, impossible options). */
export class ReferenceInputError extends InputError {
  override name = 'ReferenceInputError';
}
