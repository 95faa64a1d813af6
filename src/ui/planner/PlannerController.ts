import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { type UiStore, showStatus } from '../../core/store/uiStore';
import { aimAtMode } from '../shared/aimAtMode';
import { ENGLISH } from '../i18n/english';
import type { Translate } from '../i18n/messageTypes';
import type { DragPreview } from './dragPreview';
import { fixingDragToward, dropFixingDrag } from './fixingDrag';
import { type KeyChord, findByChord } from './keyChord';
import { dropModuleDrag, moduleDragToward } from './moduleDrag';
import { dropObjectDrag, previewObjectDrag } from './objectDrag';
import { pannedView } from './panGesture';
import { pinchedView, startPinch } from './pinchGesture';
import type { PlanGesture } from './planGesture';
import { type PlanHit, planHitTest } from './planHitTest';
import { type CommandContext, type PlannerCommand, PLANNER_COMMANDS, plannerCommand, runCommand } from './plannerCommands';
import type { PlannerGestureHost, RefusalToShow } from './plannerGestureHost';
import { startDrag } from './startDrag';
import { dropSystemDrag, previewSystemDrag } from './systemDrag';
import { tapSelection } from './tapSelection';
import { type PlanView, type ScreenPoint, type Viewport, fitRoom, screenToWorld, wheelZoomFactor, zoomAt } from './viewTransform';
import { zoomAnchor } from './zoomAnchor';

/** What changed: the view (animated for buttons, wheel and keys; at once for fingers), or the drag preview. */
export type PlannerEvent = { kind: 'view'; animate: boolean } | { kind: 'drag' };

/**
 * Pixels a pointer must travel on either axis before a press becomes a drag; less is a tap.
 * PlanGestureRecognizer uses the same threshold to tell them apart (docs/planner.md, "Gestures").
 */
export const DRAG_THRESHOLD_PX = 3;

/** The plan's size until it is measured. */
export const DEFAULT_VIEWPORT: Viewport = { width: 800, height: 600 };

/**
 * The plan's interaction logic without React or a DOM, in the manner of tldraw's TestEditor:
 * pointer, wheel, pinch and key input in screen pixels (relative to the plan's top-left
 * corner) becomes selection, panning, zooming and the model's actions through the store.
 * The React hooks feed it DOM events and draw what it holds; tests drive it directly.
 * Each gesture is its own file (pinchGesture, panGesture, systemDrag, objectDrag, moduleDrag,
 * fixingDrag; startDrag tells them apart; addFurniture places new pieces); the controller holds
 * the gesture under way and the view.
 *
 * `view` is where the view is heading: the React side animates towards it, and gestures
 * build on it so fast wheel turns accumulate.
 */
export class PlannerController implements CommandContext, PlannerGestureHost {
  readonly store: ConfiguratorStore;
  readonly ui: UiStore;
  private currentView: PlanView;
  private currentViewport: Viewport;
  private dragPreview: DragPreview | null = null;
  private gesture: PlanGesture | null = null;
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

  /** The drag preview the plan draws (null: none); set by the drags. */
  setDrag(drag: DragPreview | null): void {
    this.dragPreview = drag;
    this.emit({ kind: 'drag' });
  }

  /** The plan's size changed (or the room did): fits the room when either differs from the last fit. */
  setViewport(viewport: Viewport): void {
    this.currentViewport = viewport;
    const { room } = this.store.getState().config;
    const { top, bottom } = this.fitInsets;
    const key = `${room.width}x${room.depth}@${viewport.width}x${viewport.height}-${top}-${bottom}`;
    if (this.fittedFor === key) return;
    this.fittedFor = key;
    // The room fits between what covers the plan's top and bottom edges (the room-shape mode's bar and sheet).
    const fitted = fitRoom(room, { width: viewport.width, height: Math.max(1, viewport.height - top - bottom) });
    this.setView({ ...fitted, offsetY: fitted.offsetY + top }, false);
  }

  private fitInsets = { top: 0, bottom: 0 };

  /** Pixels at the plan's top and bottom that panels cover (0, 0: none): the room is fitted between them, now and at every refit. */
  setFitInsets(top: number, bottom: number): void {
    const [t, b] = [Math.round(top), Math.round(bottom)];
    if (t === this.fitInsets.top && b === this.fitInsets.bottom) return;
    this.fitInsets = { top: t, bottom: b };
    this.setViewport(this.currentViewport);
  }

  // --- actions and commands -------------------------------------------------------------

  explain = (reason: string): void => showStatus(this.ui, reason);

  /** A refusal in the status line with its code, so the planner shows it in the UI language (docs/i18n.md). */
  explainRefusal(r: RefusalToShow): void {
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

  /** Buttons and keys zoom about the selected system when it is on screen, else about the middle of the plan (zoomAnchor). */
  zoom = (factor: number): void => {
    this.setView(zoomAt(this.view, zoomAnchor(this.store.getState(), this.view, this.viewport), factor), true);
  };

  fit = (): void => this.setView(fitRoom(this.store.getState().config.room, this.viewport), true);

  /** A wheel turn at a point, in pixels (wheels that count lines or pages converted by the caller): zooms about it. */
  wheel(at: ScreenPoint, deltaYPixels: number): void {
    this.setView(zoomAt(this.view, at, wheelZoomFactor(deltaYPixels)), true);
  }

  /** Two fingers (or a trackpad pinch) start `distance` px apart about `centre`; a pointer drag in progress is dropped. */
  pinchStart(centre: ScreenPoint, distance: number): void {
    this.pointerCancel();
    this.gesture = startPinch(this.view, centre, distance);
  }

  /** The fingers moved: zoom by their spread and pan with their centre (pinchedView). */
  pinchMove(centre: ScreenPoint, distance: number): void {
    const g = this.gesture;
    if (g?.mode === 'pinch') this.setView(pinchedView(g, centre, distance), false);
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
    let g = this.gesture;
    if (!g) return;
    if (g.mode === 'pending') {
      // Below the threshold the press may still be a tap: nothing moves yet.
      if (Math.abs(at.sx - g.down.sx) < DRAG_THRESHOLD_PX && Math.abs(at.sy - g.down.sy) < DRAG_THRESHOLD_PX) return;
      g = this.gesture = startDrag(this, g, at);
      if (g.mode === 'pan') return;
    }
    if (g.mode === 'pan') {
      this.setView(pannedView(this.view, g, at), false);
      this.gesture = { mode: 'pan', last: at };
    } else if (g.mode === 'system') previewSystemDrag(this, g, at);
    else if (g.mode === 'object') previewObjectDrag(this, g, at);
    else if (g.mode === 'module') this.gesture = moduleDragToward(this, g, at);
    else if (g.mode === 'fixing') this.gesture = fixingDragToward(this, g, at);
  }

  /** The press ends: a tap selects, a drag is committed as one undoable move, a pan just stops. */
  pointerUp(at: ScreenPoint): void {
    this.pointerMove(at);
    const g = this.gesture;
    this.gesture = null;
    if (g?.mode === 'pending') {
      if (!this.aimAtTap(g.down)) this.tap(g.hit);
    } else if (g?.mode === 'system') dropSystemDrag(this, g, at);
    else if (g?.mode === 'object') dropObjectDrag(this, g, at);
    else if (g?.mode === 'module') dropModuleDrag(this, g);
    else if (g?.mode === 'fixing') dropFixingDrag(this, g);
  }

  /** The press was taken over (a second finger, the browser): a drag is dropped without moving anything. */
  pointerCancel(): void {
    if (this.gesture?.mode !== 'pinch') this.gesture = null;
    if (this.drag) this.setDrag(null);
  }

  // --- taps -----------------------------------------------------------------------------

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

  /** A tap selects what it hit, following the zoom level (tapSelection); on the floor it deselects. */
  tap(hit: PlanHit): void {
    this.store.getState().select(tapSelection(hit, this.view.scale));
  }
}
