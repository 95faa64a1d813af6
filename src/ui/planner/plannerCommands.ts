import { checkAction, type ActionName } from '../../core/model/actions/actionDefinitions';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { optionsShown, type UiStore } from '../../core/store/uiStore';
import { deleteTarget } from './deleteTarget';
import type { KeySpec } from './keyChord';
import { placementStep } from '../../core/model/rails/freePositions';
import { moduleOnRail, stepAlongRail } from './moduleMoves';
import { followableDelta, movedPlacement } from './objectMoves';
import { selectionPath } from './selection';
import { ENGLISH } from '../i18n/english';
import type { MessageKey, Translate } from '../i18n/messageTypes';
import { translateCoded } from '../i18n/translateCoded';

/** What a command may use: the stores, the action runner and the view. The PlannerController provides it. */
export interface CommandContext {
  readonly store: ConfiguratorStore;
  readonly ui: UiStore;
  /** Dispatches an action; a refusal is explained in the status line. */
  run(name: ActionName, params: unknown): void;
  /** Zoom by a factor about the selected system when it is on screen, else the plan's middle. */
  zoom(factor: number): void;
  /** Show the whole room. */
  fit(): void;
  /** The UI language's texts for labels and reasons (docs/i18n.md); English when absent. */
  readonly tr?: Translate;
}

const tr = (c: CommandContext): Translate => c.tr ?? ENGLISH.t;

/**
 * One UI command, used alike by the bottom bar, the zoom buttons and the keyboard, so a
 * button and its key can never disagree about what they do or when they may.
 */
export interface PlannerCommand {
  readonly id: string;
  /** Accessible name of its button (commands that change with the state compute it). */
  readonly label: string | ((c: CommandContext) => string);
  /** Keys that run it (keyChord.ts syntax); empty for button-only commands. */
  readonly keys: readonly KeySpec[];
  /** null when it may run now, else why not: the disabled button's title, and what a key press explains. */
  readonly disabledReason: (c: CommandContext) => string | null;
  readonly action: (c: CommandContext) => void;
  /** For toggles: whether the button shows as pressed. */
  readonly pressed?: (c: CommandContext) => boolean;
}

/** Degrees the rotate command (button and R) turns a system: a quarter turn, counterclockwise. */
export const ROTATE_STEP = 90;

/** Degrees the rotate command (button and R), and [ / ] for anything, turn furniture: fine enough to line a sofa up with a rail. */
export const OBJECT_ROTATE_STEP = 15;

/**
 * Zoom factor of one zoom-in (button or +) step; zoom-out divides by it. 1.5 is what the
 * zoom buttons have always used: e2e/helpers.ts `zoomToModuleLevel` clicks it and the golden
 * screenshot `module-level-desktop.png` is taken at the scale those clicks reach.
 */
export const ZOOM_STEP = 1.5;

/** Arrow keys move the selected system this far (metres); with Shift, a tenth of it. */
export const KEY_MOVE_STEP = 0.1;

const always = () => null;

function selectedSystem(c: CommandContext) {
  const { config, selection } = c.store.getState();
  const id = selectionPath(config, selection).systemId;
  return config.systems.find((s) => s.id === id);
}

function selectedObject(c: CommandContext) {
  const { config, selection } = c.store.getState();
  const id = selectionPath(config, selection).objectId;
  return config.objects.find((o) => o.id === id);
}

/** The model's reason an action may not run now, null when it may. */
function refusal(c: CommandContext, name: ActionName, params: unknown): string | null {
  const { config, catalog } = c.store.getState();
  const e = checkAction(config, name, params, catalog);
  return e === true ? null : translateCoded(tr(c), 'notices', e);
}

function deleteCommand(): PlannerCommand {
  const target = (c: CommandContext) => {
    const { config, selection } = c.store.getState();
    return deleteTarget(selectionPath(config, selection));
  };
  return {
    id: 'delete',
    label: (c) => tr(c)('commands.delete'),
    keys: ['Delete', 'Backspace'],
    disabledReason: (c) => {
      const t = target(c);
      // deleteTarget's only reason: nothing is selected.
      return 'reason' in t ? tr(c)('commands.selectAnythingFirst') : refusal(c, t.name, t.params);
    },
    action: (c) => {
      const t = target(c);
      if (!('reason' in t)) c.run(t.name, t.params);
    },
  };
}

/**
 * Turns the selected system by `systemBy` or the selected object by `objectBy` degrees
 * (counterclockwise seen from above positive), as the model's rotateSystem / rotateObject.
 */
function rotateCommand(id: string, label: MessageKey, keys: KeySpec[], systemBy: number, objectBy: number): PlannerCommand {
  const target = (c: CommandContext): { name: ActionName; params: Record<string, unknown> } | null => {
    const o = selectedObject(c);
    if (o) return { name: 'rotateObject', params: { objectId: o.id, by: objectBy } };
    const s = selectedSystem(c);
    return s ? { name: 'rotateSystem', params: { systemId: s.id, by: systemBy } } : null;
  };
  return {
    id,
    label: (c) => tr(c)(label, { degrees: Math.abs(objectBy) }),
    keys,
    disabledReason: (c) => {
      const t = target(c);
      return t ? refusal(c, t.name, t.params) : tr(c)('commands.selectFirst');
    },
    action: (c) => {
      const t = target(c);
      if (t) c.run(t.name, t.params);
    },
  };
}

/**
 * Where an arrow step puts the selection, rounded to the millimetre so repeated steps do not
 * gather float noise: the system, or the object (a wall item only along its wall; an arrow
 * across the wall is refused with the reason).
 */
function stepped(c: CommandContext, dx: number, dz: number): { name: ActionName; params: Record<string, unknown> } | { reason: MessageKey } {
  const { config, catalog, selection } = c.store.getState();
  const moduleId = selectionPath(config, selection).moduleId;
  if (moduleId) {
    // A selected module slides along its rail by one snap step (docs/planner.md, "Moving a module").
    const on = moduleOnRail(config, catalog, moduleId);
    if (!on) return { reason: 'commands.moduleOffRail' };
    const sign = stepAlongRail(on, dx, dz);
    if (sign === 0) return { reason: 'commands.moduleAlongRail' };
    return { name: 'moveModule', params: { moduleId, offset: on.offset + sign * placementStep(catalog) } };
  }
  const o = selectedObject(c);
  if (o) {
    const d = followableDelta(o.placement, { x: dx, z: dz });
    if (d.x === 0 && d.z === 0) return { reason: 'commands.wallItemAlongWall' };
    return { name: 'moveObject', params: { objectId: o.id, placement: movedPlacement(o.placement, d, KEY_SNAP) } };
  }
  const s = selectedSystem(c);
  if (!s) return { reason: 'commands.selectFirst' };
  const round = (v: number) => Math.round(v * 1000) / 1000;
  return { name: 'moveSystem', params: { systemId: s.id, x: dx ? round(s.x + dx) : s.x, z: dz ? round(s.z + dz) : s.z } };
}

/** Arrow-key positions are rounded to this (metres). */
const KEY_SNAP = 0.001;

function moveCommand(key: string, dx: number, dz: number, fine: boolean): PlannerCommand {
  const step = fine ? KEY_MOVE_STEP / 10 : KEY_MOVE_STEP;
  return {
    id: `move-${key}${fine ? '-fine' : ''}`,
    label: (c) => tr(c)(MOVE_LABELS[key], { step }),
    keys: [fine ? `Shift+${key}` : key],
    disabledReason: (c) => {
      const t = stepped(c, dx * step, dz * step);
      return 'reason' in t ? tr(c)(t.reason) : refusal(c, t.name, t.params);
    },
    action: (c) => {
      const t = stepped(c, dx * step, dz * step);
      if (!('reason' in t)) c.run(t.name, t.params);
    },
  };
}

const MOVE_LABELS: Record<string, MessageKey> = { ArrowLeft: 'commands.moveLeft', ArrowRight: 'commands.moveRight', ArrowUp: 'commands.moveUp', ArrowDown: 'commands.moveDown' };

const ARROWS: [string, number, number][] = [
  ['ArrowLeft', -1, 0],
  ['ArrowRight', 1, 0],
  ['ArrowUp', 0, -1],
  ['ArrowDown', 0, 1],
];

function historyCommand(id: 'undo' | 'redo', keys: KeySpec[]): PlannerCommand {
  return {
    id,
    label: (c) => tr(c)(id === 'undo' ? 'commands.undo' : 'commands.redo'),
    keys,
    disabledReason: (c) => {
      const st = c.store.getState();
      return (id === 'undo' ? st.canUndo : st.canRedo) ? null : tr(c)(id === 'undo' ? 'commands.nothingToUndo' : 'commands.nothingToRedo');
    },
    action: (c) => void c.store.getState()[id](),
  };
}

/**
 * Every command of the planner's bottom bar, zoom buttons and keyboard (docs/planner.md,
 * "Bottom bar and keys"). Keys are only listened to outside text fields, in the 2D plan.
 */
export const PLANNER_COMMANDS: readonly PlannerCommand[] = [
  deleteCommand(),
  {
    id: 'select-next',
    label: (c) => tr(c)('commands.selectNext'),
    keys: [],
    disabledReason: (c) => {
      const { systems, objects } = c.store.getState().config;
      return systems.length + objects.length === 0 ? tr(c)('commands.placeSomethingFirst') : null;
    },
    action: (c) => {
      // Systems first, then objects, round and round.
      const { config, selection } = c.store.getState();
      const all = [...config.systems.map((s) => ({ kind: 'system' as const, id: s.id })), ...config.objects.map((o) => ({ kind: 'object' as const, id: o.id }))];
      const path = selectionPath(config, selection);
      const i = all.findIndex((x) => x.id === (path.objectId ?? path.systemId));
      c.store.getState().select(all[(i + 1) % all.length]);
    },
  },
  {
    id: 'options',
    label: (c) => tr(c)('commands.options'),
    keys: [],
    disabledReason: always,
    // Pressed only while the options are on screen: in a closed drawer they are not (docs/planner.md, "Phone drawer").
    pressed: (c) => optionsShown(c.ui.getState()),
    action: (c) => c.ui.setState((s) => (optionsShown(s) ? { optionsOpen: false, panelOpen: false } : { optionsOpen: true, panelOpen: true })),
  },
  rotateCommand('rotate', 'commands.rotate', ['r'], ROTATE_STEP, OBJECT_ROTATE_STEP),
  rotateCommand('rotate-back', 'commands.rotateBack', ['Shift+r'], -ROTATE_STEP, -OBJECT_ROTATE_STEP),
  rotateCommand('rotate-left-fine', 'commands.rotateLeftFine', ['['], OBJECT_ROTATE_STEP, OBJECT_ROTATE_STEP),
  rotateCommand('rotate-right-fine', 'commands.rotateRightFine', [']'], -OBJECT_ROTATE_STEP, -OBJECT_ROTATE_STEP),
  historyCommand('undo', ['Mod+z']),
  historyCommand('redo', ['Mod+Shift+z', 'Mod+y']),
  {
    id: 'toggle-3d',
    label: (c) => tr(c)(c.ui.getState().mode === '2d' ? 'commands.show3d' : 'commands.show2d'),
    keys: [],
    disabledReason: always,
    pressed: (c) => c.ui.getState().mode === '3d',
    action: (c) => c.ui.setState((s) => ({ mode: s.mode === '2d' ? '3d' : '2d' })),
  },
  { id: 'zoom-in', label: (c) => tr(c)('commands.zoomIn'), keys: ['+', '='], disabledReason: always, action: (c) => c.zoom(ZOOM_STEP) },
  { id: 'zoom-out', label: (c) => tr(c)('commands.zoomOut'), keys: ['-', '_'], disabledReason: always, action: (c) => c.zoom(1 / ZOOM_STEP) },
  { id: 'zoom-fit', label: (c) => tr(c)('commands.zoomFit'), keys: [], disabledReason: always, action: (c) => c.fit() },
  {
    id: 'deselect',
    label: (c) => tr(c)('commands.deselect'),
    keys: ['Escape'],
    disabledReason: always,
    action: (c) => {
      c.store.getState().select(null);
      c.ui.setState({ optionsOpen: false });
    },
  },
  ...ARROWS.flatMap(([key, dx, dz]) => [moveCommand(key, dx, dz, false), moveCommand(key, dx, dz, true)]),
];

export function plannerCommand(id: string): PlannerCommand {
  const c = PLANNER_COMMANDS.find((x) => x.id === id);
  if (!c) throw new Error(`unknown planner command '${id}'`);
  return c;
}

export function commandLabel(command: PlannerCommand, c: CommandContext): string {
  return typeof command.label === 'string' ? command.label : command.label(c);
}

/** Runs a command, or explains why it may not run (a disabled button's tap and a refused key alike). */
export function runCommand(command: PlannerCommand, c: CommandContext, explain: (reason: string) => void): void {
  const reason = command.disabledReason(c);
  if (reason !== null) explain(reason);
  else command.action(c);
}
