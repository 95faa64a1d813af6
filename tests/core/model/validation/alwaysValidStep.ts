import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import type { Configuration } from '../../../../src/core/model/configuration/configuration';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog } from '../helpers';

/**
 * One step of an always-valid property test: an enabled action must leave validate() empty; a
 * refused one, performed anyway, must break it (or throw). Counts both in `tally`; returns the state
 * after the step (unchanged when refused).
 */
export function alwaysValidStep(s: Configuration, name: string, params: unknown, tally: { enabled: number; refused: number }): Configuration {
  const action = bindAction(name, params, catalog);
  const e = action.isEnabled(s);
  if (e === true) {
    tally.enabled++;
    const next = action.perform(s);
    const problems = validate(next, catalog);
    if (problems.length) throw new Error(`${name} ${JSON.stringify(params)} was enabled but left: ${problems[0].path}: ${problems[0].message}`);
    return next;
  }
  tally.refused++;
  let broken: Configuration;
  try {
    broken = action.perform(s);
  } catch {
    return s;
  }
  if (validate(broken, catalog).length === 0) throw new Error(`${name} ${JSON.stringify(params)} was refused (${e.reason}) but would have been valid`);
  return s;
}
