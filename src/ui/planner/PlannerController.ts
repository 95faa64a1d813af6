import { systemBounds } from '../../core/model/rails/geometry';
import type { CodedText } from '../../core/inputError';
import { chainCoordinateAt } from '../../core/model/rails/chainCoordinates';
import { suspensionCoordinates } from '../../core/model/rails/suspensionPoints';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { type UiStore, showStatus } from '../../core/store/uiStore';
import { detailLevel } from './detailLevel';
import { type KeyChord, findByChord } from './keyChord';
import { type PlanHit, planHitTest } from './planHitTest';
import type { ActionParams } from '../../core/model/actions/actionDefinitions';
import { attemptAction } from '../../core/model/actions/actionDefinitions';
import type { LightSystem, MeshUnits, ObjectPlacement } from '../../core/model/configuration/configuration';
import { type ModuleOnRail, alongRail, moduleOnRail } from './moduleMoves';
import { findFurnitureItem, furnitureMesh } from '../../core/model/objects/furniture/furnitureLibrary';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import { followableDelta, movedPlacement, wallPlacementNear } from './objectMoves';
import { selectionPath } from './selection';
import { aimAtMode } from '../shared/aimAtMode';
import { type CommandContext, type PlannerCommand, PLANNER_COMMANDS, plannerCommand, runCommand } from './plannerCommands';
import {
  type PlanPoint,
  type PlanView,
  type ScreenPoint,
  type Viewport,
  fitRoom,
  panBy,
  screenToWorld,
  wheelZoomFactor,
  worldToScreen,
  zoomAt,
} from './viewTransform';
import { ENGLISH } from '../i18n/english';
import type { Translate } from '../i18n/messageTypes';
import { clampObjectDelta } from './clampObjectDelta';
import { freeFloorSpot } from '../../core/model/objects/freeFloorSpot';

/**
 * A system or an object being dragged: drawn offset by `delta` (metres) until dropped; `invalid`
 * where it may not be dropped. A wall item's delta is only the part along its wall.
 */
export type DragPreview =
  | { systemId: string; delta: PlanPoint; invalid: boolean }
  | { objectId: string; delta: PlanPoint; invalid: boolean }
  | ModuleDragPreview
  | FixingDragPreview;

/**
 * A fixing point being dragged along its chain (system level, its system selected): the system as
 * it would be with the point at `s`, the last position moveFixingPoint accepts (snapped to 1 cm);
 * `invalid` while the pointer is at a refused one (the reason is in the status line).
 */
export interface FixingDragPreview {
  fixingIndex: number;
  preview: LightSystem;
  s: number;
  invalid: boolean;
}

/**
 * A module being dragged along its rail: its system as it would be with the module at `offset`,
 * the last position moveModule accepts (snapped); `invalid` while the pointer is at a refused one
 * (the reason is in the status line and the module stays at `offset`).
 */
export interface ModuleDragPreview {
  moduleId: string;
  /** The module's system with the module at `offset` (what the plan draws in its place). */
  preview: LightSystem;
  offset: number;
  invalid: boolean;
}

/** What changed: the view (animated for buttons, wheel and keys; at once for fingers), or the drag preview. */
export type PlannerEvent = { kind: 'view'; animate: boolean } | { kind: 'drag' };

/**
 * Pixels a pointer must travel on either axis before a press becomes a drag; less is a tap.
 * PlanGestureRecognizer uses the same threshold to tell them apart (docs/planner.md, "Gestures").
 */
export const DRAG_THRESHOLD_PX = 3;

/** The plan's size until it is measured. */
export const DEFAULT_VIEWPORT: Viewport = { width: 800, height: 600 };

/** Dropped systems and objects land on whole centimetres, so the fields show clean numbers. */
export const DROP_SNAP = 0.01;

/** A plan point as the model's [x, z] vector. */
const worldVec = (p: PlanPoint): readonly [number, number] => [p.x, p.z];

type Gesture =
  | { mode: 'pending'; down: ScreenPoint; hit: PlanHit }
  | { mode: 'pan'; last: ScreenPoint }
  | { mode: 'system'; id: string; down: ScreenPoint; startScale: number }
  | { mode: 'object'; id: string; down: ScreenPoint; startScale: number }
  | { mode: 'module'; id: string; on: ModuleOnRail; grab: number; lastValid: number; lastReason: string | null }
  | { mode: 'fixing'; systemId: string; index: number; start: number; grab: number; lastValid: number; lastReason: string | null }
  | { mode: 'pinch'; view: PlanView; world: PlanPoint; d0: number };

/**
 * The plan's interaction logic without React or a DOM, in the manner of tldraw's TestEditor:
 * pointer, wheel, pinch and key input in screen pixels (relative to the plan's top-left
 * corner) becomes selection, panning, zooming and the model's actions through the store.
 * The React hooks feed it DOM events and draw what it holds; tests drive it directly.
 *
 * `view` is where the view is heading: the React side animates towards it, and gestures
 * build on it so fast wheel turns accumulate.
 */
export class PlannerController implements CommandContext {
  readonly store: ConfiguratorStore;
  readonly ui: UiStore;
  private currentView: PlanView;
  private currentViewport: Viewport;
  private dragPreview: DragPreview | null = null;
  private gesture: Gesture | null = null;
  private fittedFor: string | null = null;
  private readonly listeners = new Set<(e: PlannerEvent) => void>();
  private translate: Translate = ENGLISH.t;

  constructor(store: ConfiguratorStore, ui: UiStore, viewport: Viewport = DEFAULT_VIEWPORT) {
    this.store = store;
    this.ui = ui;
    this.currentViewport = viewport;
    this.currentView = fitRoom(store.getState().config.room, viewport);
  }

  /** The UI language's texts for the commands' labels and reasons (CommandContext.tr); English until the planner sets it. */
  get tr(): Translate {
    return this.translate;
  }

  /** Called by the planner on every render, so the command buttons rendered after it use the current language. */
  setTranslator(t: Translate): void {
    this.translate = t;
  }

  /** The view the plan is heading to (changed through setView, gestures and commands). */
  get view(): PlanView {
    return this.currentView;
  }

  get viewport(): Viewport {
    return this.currentViewport;
  }

  /** The system or object being dragged, while it is. */
  get drag(): DragPreview | null {
    return this.dragPreview;
  }

  /** Listens for view and drag-preview changes; returns the unsubscribe function. */
  subscribe = (listener: (e: PlannerEvent) => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };

  private emit(e: PlannerEvent): void {
    for (const l of this.listeners) l(e);
  }

  setView(next: PlanView, animate: boolean): void {
    this.currentView = next;
    this.emit({ kind: 'view', animate });
  }

  private setDrag(drag: DragPreview | null): void {
    this.dragPreview = drag;
    this.emit({ kind: 'drag' });
  }

  /** The plan's size changed (or the room did): fits the room when either differs from the last fit. */
  setViewport(viewport: Viewport): void {
    this.currentViewport = viewport;
    const { room } = this.store.getState().config;
    const key = `${room.width}x${room.depth}@${viewport.width}x${viewport.height}`;
    if (this.fittedFor === key) return;
    this.fittedFor = key;
    this.setView(fitRoom(room, viewport), false);
  }

  // --- actions and commands -------------------------------------------------------------

  explain = (reason: string): void => showStatus(this.ui, reason);

  /** A refusal in the status line with its code, so the planner shows it in the UI language (docs/i18n.md). */
  private explainRefusal(r: { reason: string; code?: string; params?: Readonly<Record<string, string | number>>; detail?: CodedText }): void {
    // The quoted problem (a refusal's non-enumerable detail) goes along: the status line words it as {problem}.
    showStatus(this.ui, r.reason, r.code ? { code: r.code, params: r.params ? { ...r.params } : undefined, ...(r.detail ? { detail: r.detail } : {}) } : undefined);
  }

  run = (name: string, params: unknown): void => {
    const r = this.store.getState().dispatch(name, params);
    if (!r.ok) this.explainRefusal(r);
  };

  /** Runs a command of the table by id (or explains why it may not run). */
  command(id: string): void {
    runCommand(plannerCommand(id), this, this.explain);
  }

  /**
   * A key pressed outside text fields. Returns whether a command took it (the caller then
   * keeps the browser from acting on it too).
   */
  keyDown(chord: KeyChord): boolean {
    const command: PlannerCommand | undefined = findByChord(PLANNER_COMMANDS, chord);
    if (!command) return false;
    runCommand(command, this, this.explain);
    return true;
  }

  // --- view -----------------------------------------------------------------------------

  /**
   * Buttons and keys zoom about the selected system when it is on screen (so zooming in on it
   * reaches the module level without panning), else about the middle of the plan.
   */
  zoom = (factor: number): void => {
    const { config, catalog, selection } = this.store.getState();
    const { width, height } = this.viewport;
    let anchor = { sx: width / 2, sy: height / 2 };
    const systemId = selectionPath(config, selection).systemId;
    const system = config.systems.find((s) => s.id === systemId);
    if (system) {
      const b = systemBounds(system, catalog);
      const c = worldToScreen(this.view, { x: (b.minX + b.maxX) / 2, z: (b.minZ + b.maxZ) / 2 });
      if (c.sx >= 0 && c.sy >= 0 && c.sx <= width && c.sy <= height) anchor = c;
    }
    this.setView(zoomAt(this.view, anchor, factor), true);
  };

  fit = (): void => this.setView(fitRoom(this.store.getState().config.room, this.viewport), true);

  /** A wheel turn at a point, in pixels (wheels that count lines or pages converted by the caller): zooms about it. */
  wheel(at: ScreenPoint, deltaYPixels: number): void {
    this.setView(zoomAt(this.view, at, wheelZoomFactor(deltaYPixels)), true);
  }

  /** Two fingers (or a trackpad pinch) start `distance` px apart about `centre`; a pointer drag in progress is dropped. */
  pinchStart(centre: ScreenPoint, distance: number): void {
    this.pointerCancel();
    this.gesture = { mode: 'pinch', view: this.view, world: screenToWorld(this.view, centre), d0: Math.max(1, distance) };
  }

  /**
   * The fingers moved: the zoom is the ratio of their distance to the starting one (so it does
   * not depend on earlier pinches), and the world point that started under them is put back
   * under their centre (two-finger pan).
   */
  pinchMove(centre: ScreenPoint, distance: number): void {
    const g = this.gesture;
    if (g?.mode !== 'pinch') return;
    const scaled = zoomAt(g.view, centre, Math.max(1, distance) / g.d0);
    const drift = worldToScreen(scaled, g.world);
    this.setView(panBy(scaled, centre.sx - drift.sx, centre.sy - drift.sy), false);
  }

  pinchEnd(): void {
    if (this.gesture?.mode === 'pinch') this.gesture = null;
  }

  // --- pointer --------------------------------------------------------------------------

  /** What is under a screen point, as drawn now. */
  hitTest(at: ScreenPoint): PlanHit {
    const { config, catalog } = this.store.getState();
    return planHitTest(config, catalog, this.view, at);
  }

  /** A press on the plan (not on a control): on a system it may become a move, elsewhere a pan, or a tap. */
  pointerDown(at: ScreenPoint): void {
    this.gesture = { mode: 'pending', down: at, hit: this.hitTest(at) };
  }

  pointerMove(at: ScreenPoint): void {
    const g = this.gesture;
    if (!g) return;
    if (g.mode === 'pending') {
      // Below the threshold the press may still be a tap: nothing moves yet.
      if (Math.abs(at.sx - g.down.sx) < DRAG_THRESHOLD_PX && Math.abs(at.sy - g.down.sy) < DRAG_THRESHOLD_PX) return;
      const on = g.hit.moduleId && detailLevel(this.view.scale) === 'module' ? this.moduleOn(g.hit.moduleId) : null;
      const fixingSystem = g.hit.fixing !== undefined && detailLevel(this.view.scale) !== 'module' && this.store.getState().selection?.id === g.hit.systemId ? this.systemById(g.hit.systemId) : null;
      if (fixingSystem && g.hit.fixing !== undefined) {
        // At system level, on a selected system: its fixing dot slides along the chain (the pointer projected onto the rails).
        const { catalog } = this.store.getState();
        const start = suspensionCoordinates(fixingSystem, catalog)[g.hit.fixing].s;
        const grab = chainCoordinateAt(fixingSystem, catalog, worldVec(screenToWorld(this.view, g.down))) - start;
        this.gesture = { mode: 'fixing', systemId: fixingSystem.id, index: g.hit.fixing, start, grab, lastValid: start, lastReason: null };
      } else if (g.hit.moduleId && on) {
        // Zoomed in to modules: the module slides along its rail (the pointer projected onto it).
        this.gesture = { mode: 'module', id: g.hit.moduleId, on, grab: alongRail(on, screenToWorld(this.view, g.down)) - on.offset, lastValid: on.offset, lastReason: null };
        if (this.store.getState().selection?.id !== g.hit.moduleId) this.store.getState().select({ kind: 'module', id: g.hit.moduleId });
      } else if (g.hit.systemId) {
        this.gesture = { mode: 'system', id: g.hit.systemId, down: g.down, startScale: this.view.scale };
        if (this.store.getState().selection?.id !== g.hit.systemId) this.store.getState().select({ kind: 'system', id: g.hit.systemId });
      } else if (g.hit.objectId) {
        this.gesture = { mode: 'object', id: g.hit.objectId, down: g.down, startScale: this.view.scale };
        if (this.store.getState().selection?.id !== g.hit.objectId) this.store.getState().select({ kind: 'object', id: g.hit.objectId });
      } else {
        // The pan starts where the press became a drag, so the plan does not jump by the threshold.
        this.gesture = { mode: 'pan', last: at };
        return;
      }
    }
    const cur = this.gesture;
    if (cur?.mode === 'pan') {
      this.setView(panBy(this.view, at.sx - cur.last.sx, at.sy - cur.last.sy), false);
      this.gesture = { mode: 'pan', last: at };
    } else if (cur?.mode === 'system') {
      const delta = this.pointerDelta(cur, at);
      // Preview whether dropping here would be accepted (the model's isEnabled, live).
      const s = this.store.getState().config.systems.find((x) => x.id === cur.id);
      const invalid = !s || this.store.getState().isEnabled('moveSystem', { systemId: cur.id, x: s.x + delta.x, z: s.z + delta.z }) !== true;
      this.setDrag({ systemId: cur.id, delta, invalid });
    } else if (cur?.mode === 'module') {
      this.moduleDragTo(cur, alongRail(cur.on, screenToWorld(this.view, at)) - cur.grab);
    } else if (cur?.mode === 'fixing') {
      const system = this.systemById(cur.systemId);
      if (system) this.fixingDragTo(cur, chainCoordinateAt(system, this.store.getState().catalog, worldVec(screenToWorld(this.view, at))) - cur.grab);
    } else if (cur?.mode === 'object') {
      const o = this.store.getState().config.objects.find((x) => x.id === cur.id);
      if (!o) return;
      const { config } = this.store.getState();
      const delta = clampObjectDelta(config, o, followableDelta(o.placement, this.pointerDelta(cur, at)), DROP_SNAP);
      const invalid = this.store.getState().isEnabled('moveObject', { objectId: cur.id, placement: movedPlacement(o.placement, delta, DROP_SNAP) }) !== true;
      this.setDrag({ objectId: cur.id, delta, invalid });
    }
  }

  /** The press ends: a tap selects, a system drag is committed as one undoable move, a pan just stops. */
  pointerUp(at: ScreenPoint): void {
    this.pointerMove(at);
    const g = this.gesture;
    this.gesture = null;
    if (g?.mode === 'pending') {
      if (!this.aimAtTap(g.down)) this.tap(g.hit);
    } else if (g?.mode === 'system') this.drop(g.id, this.pointerDelta(g, at));
    else if (g?.mode === 'object') this.dropObject(g.id, this.pointerDelta(g, at));
    else if (g?.mode === 'module') this.dropModule(g);
    else if (g?.mode === 'fixing') this.dropFixing(g);
  }

  private systemById(id: string | undefined): LightSystem | null {
    return this.store.getState().config.systems.find((s) => s.id === id) ?? null;
  }

  /**
   * The dragged fixing point asked to sit at chain coordinate `requested`: previewed there (snapped)
   * when moveFixingPoint accepts it; otherwise it stays at the last accepted position and the
   * reason is shown (once per new reason), as a dragged module does.
   */
  private fixingDragTo(g: Extract<Gesture, { mode: 'fixing' }>, requested: number): void {
    const { config, catalog } = this.store.getState();
    const outcome = attemptAction(config, 'moveFixingPoint', { systemId: g.systemId, index: g.index, s: requested }, catalog);
    if (outcome.ok) {
      const preview = outcome.next.systems.find((x) => x.id === g.systemId);
      if (!preview) return;
      const s = suspensionCoordinates(preview, catalog)[g.index].s;
      this.gesture = { ...g, lastValid: s, lastReason: null };
      this.setDrag({ fixingIndex: g.index, preview, s, invalid: false });
      return;
    }
    if (outcome.reason !== g.lastReason) this.explainRefusal(outcome);
    this.gesture = { ...g, lastReason: outcome.reason };
    const kept = this.drag && 'fixingIndex' in this.drag ? this.drag.preview : this.systemById(g.systemId);
    if (kept) this.setDrag({ fixingIndex: g.index, preview: kept, s: g.lastValid, invalid: true });
  }

  /** One undoable moveFixingPoint to the last accepted position, when it differs from where the point was. */
  private dropFixing(g: Extract<Gesture, { mode: 'fixing' }>): void {
    this.setDrag(null);
    if (Math.abs(g.lastValid - g.start) < 1e-9) return;
    this.run('moveFixingPoint', { systemId: g.systemId, index: g.index, s: g.lastValid });
  }

  private moduleOn(moduleId: string): ModuleOnRail | null {
    const { config, catalog } = this.store.getState();
    return moduleOnRail(config, catalog, moduleId);
  }

  /**
   * The dragged module asked to start at `requested` metres along its rail: previewed there
   * (snapped) when moveModule accepts it; otherwise it stays at the last accepted position and
   * the reason is shown (once per new reason, not on every pointer move).
   */
  private moduleDragTo(g: Extract<Gesture, { mode: 'module' }>, requested: number): void {
    const { config, catalog } = this.store.getState();
    const outcome = attemptAction(config, 'moveModule', { moduleId: g.id, offset: requested }, catalog);
    const systemOf = (c: typeof config) => c.systems.find((x) => x.id === g.on.systemId);
    if (outcome.ok) {
      const on = moduleOnRail(outcome.next, catalog, g.id);
      const preview = systemOf(outcome.next);
      if (!on || !preview) return;
      this.gesture = { ...g, lastValid: on.offset, lastReason: null };
      this.setDrag({ moduleId: g.id, preview, offset: on.offset, invalid: false });
      return;
    }
    if (outcome.reason !== g.lastReason) this.explainRefusal(outcome);
    this.gesture = { ...g, lastReason: outcome.reason };
    const kept = this.drag && 'moduleId' in this.drag ? this.drag.preview : systemOf(config);
    if (kept) this.setDrag({ moduleId: g.id, preview: kept, offset: g.lastValid, invalid: true });
  }

  /** One undoable moveModule to the last accepted position, when it differs from where the module was. */
  private dropModule(g: Extract<Gesture, { mode: 'module' }>): void {
    this.setDrag(null);
    if (Math.abs(g.lastValid - g.on.offset) < 1e-9) return;
    this.run('moveModule', { moduleId: g.id, offset: g.lastValid });
  }

  /** The press was taken over (a second finger, the browser): a drag is dropped without moving anything. */
  pointerCancel(): void {
    if (this.gesture?.mode !== 'pinch') this.gesture = null;
    if (this.drag) this.setDrag(null);
  }

  /** The pointer's movement since the press, in metres at the scale the drag started at: the grabbed point stays under it. */
  private pointerDelta(g: { down: ScreenPoint; startScale: number }, at: ScreenPoint): PlanPoint {
    return { x: (at.sx - g.down.sx) / g.startScale, z: (at.sy - g.down.sy) / g.startScale };
  }

  private drop(systemId: string, delta: PlanPoint): void {
    this.setDrag(null);
    const s = this.store.getState().config.systems.find((x) => x.id === systemId);
    if (!s) return;
    // Positions snap to whole centimetres so the move fields show clean numbers.
    const x = Math.round((s.x + delta.x) * 100) / 100;
    const z = Math.round((s.z + delta.z) * 100) / 100;
    this.run('moveSystem', { systemId, x, z });
  }

  /** One undoable moveObject to where the object was dropped (snapped to the centimetre), or snaps back and says why. */
  private dropObject(objectId: string, delta: PlanPoint): void {
    this.setDrag(null);
    const o = this.store.getState().config.objects.find((x) => x.id === objectId);
    if (!o) return;
    const d = clampObjectDelta(this.store.getState().config, o, followableDelta(o.placement, delta), DROP_SNAP);
    if (d.x === 0 && d.z === 0) return;
    this.run('moveObject', { objectId, placement: movedPlacement(o.placement, d, DROP_SNAP) });
  }

  /**
   * Adds a furniture library item where it was dropped (`at`, plan pixels) or, tapped in the
   * panel, at the middle of the visible plan — a floor item at the nearest free floor there
   * (freeFloorSpot: never inside another piece); a wall item goes on the nearest wall at its
   * hanging height. The model moves it to the nearest spot where it fits. The new object is
   * selected. Returns the refusal, if any (also shown in the status line).
   */
  addLibraryItem(itemId: string, at?: ScreenPoint): string | null {
    const item = findFurnitureItem(itemId);
    if (!item) return this.refused({ reason: `no furniture item '${itemId}' in the library` });
    const p = at ? this.insideRoom(screenToWorld(this.view, at)) : this.visibleCentre();
    const { room } = this.store.getState().config;
    const free = item.mount === 'wall' ? null : freeFloorSpot(this.store.getState().config, furnitureMesh(itemId), p);
    const placement: ObjectPlacement = item.mount === 'wall' ? wallPlacementNear(room, p, Math.min(item.hangHeight ?? room.height / 2, room.height - item.height / 2)) : { on: 'floor', x: free?.x ?? p.x, z: free?.z ?? p.z };
    return this.addObject({ source: { kind: 'library', item: itemId }, placement });
  }

  /** Adds an imported model (already read and converted to metres) at the middle of the visible plan and selects it. */
  addImported(name: string, mesh: TriangleMesh, units: MeshUnits): string | null {
    const c = this.visibleCentre();
    const free = freeFloorSpot(this.store.getState().config, mesh, c) ?? c;
    return this.addObject({ source: { kind: 'import', name, mesh, units }, placement: { on: 'floor', x: free.x, z: free.z } });
  }

  private addObject(params: ActionParams<'addObject'>): string | null {
    const r = this.store.getState().dispatch('addObject', params);
    if (!r.ok) return this.refused(r);
    const objects = this.store.getState().config.objects;
    this.store.getState().select({ kind: 'object', id: objects[objects.length - 1].id });
    return null;
  }

  private refused(r: { reason: string; code?: string; params?: Readonly<Record<string, string | number>> }): string {
    this.explainRefusal(r);
    return r.reason;
  }

  private insideRoom(p: PlanPoint): PlanPoint {
    const { width, depth } = this.store.getState().config.room;
    return { x: Math.min(width, Math.max(0, p.x)), z: Math.min(depth, Math.max(0, p.z)) };
  }

  /** The plan point at the middle of the plan, kept inside the room: where a tapped library item goes. */
  visibleCentre(): PlanPoint {
    return this.insideRoom(screenToWorld(this.view, { sx: this.viewport.width / 2, sy: this.viewport.height / 2 }));
  }

  /**
   * Aim-at mode (docs/aiming.md): a tap aims the module at that floor point (one undoable aimAt,
   * the nearest reachable aim) and ends the mode. False when the mode is off (the tap selects).
   */
  aimAtTap(at: ScreenPoint): boolean {
    const mode = aimAtMode(this.store);
    const moduleId = mode.get();
    if (!moduleId) return false;
    const p = screenToWorld(this.view, at);
    this.run('aimAt', { moduleId, point: [p.x, 0, p.z] });
    mode.set(null);
    return true;
  }

  /**
   * Like the controls, what a tap selects follows the zoom level: whole systems when zoomed
   * out, rails and modules when zoomed in. A tap on the floor deselects.
   */
  tap(hit: PlanHit): void {
    const select = this.store.getState().select;
    if (hit.objectId) return select({ kind: 'object', id: hit.objectId });
    if (!hit.systemId) return select(null);
    const zoomedIn = detailLevel(this.view.scale) === 'module';
    if (zoomedIn && hit.moduleId) select({ kind: 'module', id: hit.moduleId });
    else if (zoomedIn && hit.railId) select({ kind: 'rail', id: hit.railId });
    else select({ kind: 'system', id: hit.systemId });
  }
}
