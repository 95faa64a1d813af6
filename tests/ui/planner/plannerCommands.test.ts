import { describe, expect, it } from 'vitest';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import { chordMatches, findByChord } from '../../../src/ui/planner/keyChord';
import { KEY_MOVE_STEP, PLANNER_COMMANDS, ROTATE_STEP, ZOOM_STEP, plannerCommand } from '../../../src/ui/planner/plannerCommands';
import { TestPlanner } from './testPlanner';

describe('the command table', () => {
  it('has one command per id, each of whose keys finds it', () => {
    const ids = PLANNER_COMMANDS.map((c) => c.id);
    expect(new Set(ids).size).toBe(ids.length);
    for (const c of PLANNER_COMMANDS) {
      for (const spec of c.keys) {
        const key = spec.endsWith('+') ? '+' : spec.slice(spec.lastIndexOf('+') + 1);
        const mods = spec.slice(0, spec.length - key.length);
        expect(findByChord(PLANNER_COMMANDS, { key, mod: mods.includes('Mod'), shift: mods.includes('Shift') })?.id, spec).toBe(c.id);
      }
    }
  });

  it('zooms by one step of 1.5 (what e2e/helpers zoomToModuleLevel and the golden screenshots rely on)', () => {
    expect(ZOOM_STEP).toBe(1.5);
  });

  it('Shift picks a variant only where the table names one; Alt and unknown Ctrl chords are left to the browser', () => {
    expect(chordMatches({ key: 'R', shift: true }, ['Shift+r'], false)).toBe(true);
    expect(chordMatches({ key: 'R', shift: true }, ['r'], false)).toBe(false);
    expect(findByChord(PLANNER_COMMANDS, { key: 'Delete', shift: true })?.id).toBe('delete');
    expect(findByChord(PLANNER_COMMANDS, { key: 'Y', mod: true, shift: true })?.id).toBe('redo');
    expect(findByChord(PLANNER_COMMANDS, { key: 'z', alt: true })).toBeUndefined();
    expect(findByChord(PLANNER_COMMANDS, { key: 'r', mod: true })).toBeUndefined();
    expect(findByChord(PLANNER_COMMANDS, { key: '+', mod: true })).toBeUndefined();
  });
});

describe('keys and buttons run the same commands', () => {
  it('arrows move the selected system 0.1 m (Shift: 0.01 m), R / Shift+R rotate ±90°, Delete removes, Mod+Z / Mod+Shift+Z / Mod+Y', () => {
    const t = new TestPlanner();
    const s0 = t.system();
    expect(t.press('ArrowLeft')).toBe(true);
    expect(t.status).toBe('select a system or an object first');
    expect(t.config.systems[0]).toBe(s0);

    t.store.getState().select({ kind: 'system', id: s0.id });
    t.press('ArrowLeft');
    expect(t.system().x).toBe(Math.round((s0.x - KEY_MOVE_STEP) * 1000) / 1000);
    t.press('Shift+ArrowDown');
    expect(t.system().z).toBe(Math.round((s0.z + KEY_MOVE_STEP / 10) * 1000) / 1000);
    const r0 = t.system().rotation;
    t.press('r');
    expect(t.system().rotation).toBe((r0 + ROTATE_STEP) % 360);
    t.press('Shift+r');
    expect(t.system().rotation).toBe(r0);

    t.press('Delete');
    expect(t.config.systems).toHaveLength(0);
    t.press('Mod+z');
    expect(t.config.systems).toHaveLength(1);
    t.press('Mod+Shift+z');
    expect(t.config.systems).toHaveLength(0);
    t.press('Mod+z');
    t.press('Mod+y');
    expect(t.config.systems).toHaveLength(0);
  });

  it('a disabled command explains itself, by key or by button, and changes nothing', () => {
    const t = new TestPlanner(createConfiguration());
    for (const [id, key, reason] of [
      ['delete', 'Backspace', 'select a system, a module or an object first'],
      ['undo', 'Mod+z', 'nothing to undo'],
      ['redo', 'Mod+y', 'nothing to redo'],
      ['rotate', 'r', 'select a system or an object first'],
    ] as const) {
      expect(plannerCommand(id).disabledReason(t.controller)).toBe(reason);
      t.ui.setState({ status: null });
      t.press(key);
      expect(t.status).toBe(reason);
      t.ui.setState({ status: null });
      t.controller.command(id);
      expect(t.status).toBe(reason);
    }
    expect(plannerCommand('select-next').disabledReason(t.controller)).toBe('place a preset or a piece of furniture first');
    expect(t.store.getState().canUndo).toBe(false);
  });

  it('the bottom bar rotate refuses with the model reason where a turn would leave the room', () => {
    const t = new TestPlanner();
    const s = t.system();
    t.store.getState().select({ kind: 'system', id: s.id });
    const check = t.store.getState().isEnabled('rotateSystem', { systemId: s.id, by: ROTATE_STEP });
    expect(plannerCommand('rotate').disabledReason(t.controller)).toBe(check === true ? null : check.reason);
  });

  it('select-next cycles through the systems; Escape deselects and closes the options; the toggles flip the UI state', () => {
    const t = new TestPlanner();
    t.controller.command('select-next');
    expect(t.store.getState().selection).toEqual({ kind: 'system', id: t.system().id });
    t.controller.command('options');
    expect(t.ui.getState()).toMatchObject({ optionsOpen: true, panelOpen: true });
    expect(plannerCommand('options').pressed?.(t.controller)).toBe(true);
    t.press('Escape');
    expect(t.store.getState().selection).toBeNull();
    expect(t.ui.getState().optionsOpen).toBe(false);
    expect(plannerCommand('toggle-3d').label).toBeTypeOf('function');
    t.controller.command('toggle-3d');
    expect(t.ui.getState().mode).toBe('3d');
  });
});

describe('the Options button and the phone drawer (issue 27)', () => {
  const options = plannerCommand('options');
  it('in a drawer: closing the drawer by any way closes the options, and the button is pressed exactly while they are on screen', () => {
    const t = new TestPlanner();
    t.ui.setState({ drawer: true });
    const pressed = () => options.pressed!(t.controller);
    expect(pressed()).toBe(false);
    t.controller.command('options');
    expect(t.ui.getState()).toMatchObject({ optionsOpen: true, panelOpen: true });
    expect(pressed()).toBe(true);
    // The header's toggle, a tap beside the drawer, a placed preset: each just closes the drawer.
    t.ui.setState({ panelOpen: false });
    expect(t.ui.getState().optionsOpen).toBe(false);
    expect(pressed()).toBe(false);
    // The next tap opens them again (it used to toggle a hidden state and show nothing).
    t.controller.command('options');
    expect(t.ui.getState()).toMatchObject({ optionsOpen: true, panelOpen: true });
    t.controller.command('options');
    expect(t.ui.getState()).toMatchObject({ optionsOpen: false, panelOpen: false });
    expect(pressed()).toBe(false);
  });

  it('on a wide screen (no drawer) the options stay open when the drawer flag closes, and the box narrowing closes them', () => {
    const t = new TestPlanner();
    t.controller.command('options');
    t.ui.setState({ panelOpen: false });
    expect(t.ui.getState().optionsOpen).toBe(true);
    expect(options.pressed!(t.controller)).toBe(true);
    // The window narrows below 900 px: the options were in the side panel, which is now a closed drawer.
    t.ui.setState({ drawer: true });
    expect(t.ui.getState().optionsOpen).toBe(false);
    expect(options.pressed!(t.controller)).toBe(false);
  });
});
