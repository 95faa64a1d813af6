/**
 * The always-valid property (configurator paper §3.2): from any valid state, an enabled
 * action leads to a valid state, and a refused action, performed anyway,
 * either throws or leads to a state validate() rejects. Random sequences over
 * every action — rails (removed at any index: splits; flexible connectors turned; fixing points moved),
 * modules (moved to free positions; aimed, in and out of their limits), patches,
 * finishes and objects (furniture, imported meshes) mixed —
 * seeded so failures reproduce. The steps are read as actions by alwaysValidActions.ts; what the
 * reached state must satisfy beyond validate(), and the tallies, are in reachableStateChecks.ts.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../../src/core/model/configuration/configuration';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog } from '../helpers';
import { step, toAction, unit } from './alwaysValidActions';
import { checkReachableState, holds, newTallies } from './reachableStateChecks';

/**
 * Sequences per run. Issue 11 asks for 10 000 in CI: scripts/test.sh (the README's test command,
 * so CI) sets ALWAYS_VALID_RUNS=10000; a plain `vitest run` while developing takes 5 000. Since
 * the model caches its derived data (perCatalog.ts) and the checks below skip expect(), a sequence
 * costs about 3 ms of CPU (10 000: 32 s of CPU, 62 s on the shared 2-core machine with about seven
 * agents on it), where it took 34 ms under load before (341 s; docs/benchmarks.md, "Test suite time").
 */
const RUNS = Number(process.env.ALWAYS_VALID_RUNS ?? 5000);

describe('always-valid property', () => {
  it(
    'enabled actions keep validate() empty; refused ones would break it',
    () => {
      const tallies = newTallies();
      const { counts, finishes, objects, power, free, shape, trees, aims, scenes } = tallies;
      fc.assert(
        fc.property(unit, unit, unit, fc.array(step, { minLength: 5, maxLength: 30 }), (a, b, c, steps) => {
          let s = createConfiguration({ width: 2 + a * 8, depth: 2 + b * 8, height: 2.4 + c * 2 });
          holds(validate(s, catalog).length === 0, 'a new room is valid');
          for (const st of steps) {
            const [name, params] = toAction(s, st);
            const action = bindAction(name, params, catalog);
            const e = action.isEnabled(s);
            if (name === 'setReflectance') finishes[e === true ? 'enabled' : 'refused']++;
            if (/Object$/.test(name)) objects[e === true ? 'enabled' : 'refused']++;
            if (/Feed|Mounting/.test(name)) power[e === true ? 'enabled' : 'refused']++;
            if (e !== true && /driver is full|would carry|cannot carry/.test(e.reason)) power.overloads++;
            if (name === 'moveModule') free[e === true ? 'moves' : 'refusedMoves']++;
            if (name === 'removeRail' && e === true) free.removals++;
            if (name === 'setJointTurn') shape[e === true ? 'turns' : 'refusedTurns']++;
            if (name === 'moveFixingPoint') shape[e === true ? 'fixingMoves' : 'refusedFixingMoves']++;
            if (name === 'setAim' || name === 'aimAt') aims[e === true ? 'enabled' : 'refused']++;
            if (name === 'addBranch') trees[e === true ? 'branches' : 'refusedBranches']++;
            if (/Scene$/.test(name)) scenes[e === true ? 'enabled' : 'refused']++;
            if (name === 'recallScene' && e === true) scenes.recalls++;
            if (name === 'setConnector' && e === true) trees.connectorChanges++;
            if (e === true) {
              counts.enabled++;
              const systemsBefore = s.systems.length;
              s = action.perform(s);
              if (name === 'removeRail' && s.systems.length > systemsBefore) free.splits++;
              if (name === 'removeRail') trees.maxPieces = Math.max(trees.maxPieces, s.systems.length - systemsBefore + 1);
              const problems = validate(s, catalog);
              if (problems.length) throw new Error(`${name} ${JSON.stringify(params)} was enabled but left: ${problems[0].path}: ${problems[0].message}`);
            } else {
              counts.refused++;
              holds(e.reason.length > 0, `${name} is refused with a reason`);
              let broken: Configuration;
              try {
                broken = action.perform(s);
              } catch {
                continue;
              }
              if (validate(broken, catalog).length === 0) throw new Error(`${name} ${JSON.stringify(params)} was refused (${e.reason}) but would have been valid`);
            }
          }
          checkReachableState(s, tallies);
        }),
        { seed: 20240917, numRuns: RUNS },
      );
      console.log(`always-valid: ${RUNS} sequences, ${JSON.stringify({ counts, finishes, objects, power, placed: tallies.placed, free, shape, aims, trees, scenes })}`);
      // both branches were exercised in bulk (at 2 000 sequences: 9 278 enabled, 15 157 refused steps;
      // 371 / 31 finishes, 2 561 / 1 172 object actions, 2 017 objects placed; bounds scale with RUNS)
      expect(counts.enabled).toBeGreaterThan(3 * RUNS);
      expect(counts.refused).toBeGreaterThan(3 * RUNS);
      expect(finishes.enabled).toBeGreaterThan(0.12 * RUNS);
      // scene actions ran both ways, scenes were recalled, and looks survived module removals
      // (at 5 000 sequences: 417 enabled, 201 refused, 9 recalls, 1 308 looks checked; a recall needs a
      // second scene step in the same sequence, rare at one kind in 56)
      expect(scenes.enabled).toBeGreaterThan(0.06 * RUNS);
      expect(scenes.refused).toBeGreaterThan(0.02 * RUNS);
      expect(scenes.recalls).toBeGreaterThan(0.001 * RUNS);
      expect(scenes.looks).toBeGreaterThan(0.1 * RUNS);
      expect(finishes.refused).toBeGreaterThan(0.007 * RUNS);
      expect(objects.enabled).toBeGreaterThan(0.8 * RUNS);
      expect(objects.refused).toBeGreaterThan(0.33 * RUNS);
      expect(tallies.placed).toBeGreaterThan(0.68 * RUNS);
      // the power and mounting actions, and refusals for an overloaded driver, in bulk
      expect(power.enabled).toBeGreaterThan(RUNS / 4);
      // (2 806 at 5 000 and 5 644 at 10 000 sequences)
      expect(power.refused).toBeGreaterThan(0.3 * RUNS);
      // (1 911 at 5 000 and 3 770 at 10 000 sequences: setFeedDriver picks one of the three smallest
      // drivers half the time, which one more module fills or which is too small for the load. The
      // Single rail preset ships with a 240 W driver, so without that only 97 at 5 000 filled one)
      expect(power.overloads).toBeGreaterThan(RUNS / 15);
      // (495 at 5 000 and 956 at 10 000 sequences)
      expect(power.surface).toBeGreaterThan(RUNS / 15);
      // free positions and rail removals at any index (splits included), in bulk
      // (at 5 000 sequences: 739 / 2 419 moves, 598 free rails at the ends, 213 removals, 72 splits)
      expect(free.moves).toBeGreaterThan(RUNS / 12);
      expect(free.refusedMoves).toBeGreaterThan(RUNS / 4);
      expect(free.freeRails).toBeGreaterThan(RUNS / 15);
      expect(free.removals).toBeGreaterThan(RUNS / 40);
      expect(free.splits).toBeGreaterThan(RUNS / 200);
      // flexible connector turns and moved fixing points, kept and refused, in bulk
      // (at 2 000 sequences: 20 / 26 turns, 101 / 657 fixing moves, 84 systems ending with moved points, 41 with a flexible turn)
      expect(shape.turns).toBeGreaterThan(RUNS / 200);
      expect(shape.refusedTurns).toBeGreaterThan(RUNS / 200);
      expect(shape.fixingMoves).toBeGreaterThan(RUNS / 40);
      expect(shape.refusedFixingMoves).toBeGreaterThan(RUNS / 20);
      expect(shape.movedSystems).toBeGreaterThan(RUNS / 60);
      expect(shape.turned).toBeGreaterThan(RUNS / 100);
      // aims set and refused (fixed types) in bulk, and aimed modules in the final states
      expect(aims.enabled).toBeGreaterThan(RUNS / 20);
      expect(aims.refused).toBeGreaterThan(RUNS / 40);
      expect(aims.aimed).toBeGreaterThan(RUNS / 40);
      // trees (issue 11): branches through T and X connectors grown and refused, connector changes, branched systems
      // reached, inner rails removed (at 5 000 sequences: 1 687 / 1 638 branches, 168 changes, 53 branched end states,
      // 445 T and 478 X joints; the six tree kinds thinned the others: finishes 671, refused object actions 1 889,
      // 3 875 objects placed, 514 free moves, 185 fixing moves, 128 systems with moved points; at 10 000: 3 340 / 3 278
      // branches, 332 changes, 102 branched end states, 343 fixing moves)
      expect(trees.branches).toBeGreaterThan(RUNS / 5);
      expect(trees.refusedBranches).toBeGreaterThan(RUNS / 5);
      expect(trees.connectorChanges).toBeGreaterThan(RUNS / 50);
      expect(trees.branched).toBeGreaterThan(RUNS / 400);
      expect(trees.tees).toBeGreaterThan(RUNS / 20);
      expect(trees.crosses).toBeGreaterThan(RUNS / 20);
      // (five more action kinds thinned the others: object actions 0.8·RUNS and 0.4·RUNS, refused finishes 0.007·RUNS;
      // at 5 000 sequences: 66 / 50 turns, 242 / 1 664 fixing moves, 205 systems with moved points, 97 turned)
    },
    Math.max(120_000, 60 * RUNS),
  ); // 60 ms a sequence: ten times the load-time cost of today (about 6 ms), above the 34 ms before the caches
});
