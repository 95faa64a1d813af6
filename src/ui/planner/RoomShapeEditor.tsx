import './registerRoomShapeEnglish';
import './roomShape.css';
import { useLayoutEffect, useRef, useState, type PointerEvent as ReactPointerEvent } from 'react';
import type { Configuration } from '../../core/model/configuration/configuration';
import { cornerAngle, currentShape, SHAPE_PRESETS, wallFinishes, wallLength } from '../../core/model/actions/roomShapeGeometry';
import type { PlanPoint } from '../../core/room/planPolygon';
import type { ActionGate } from './actionGate';
import { GatedButton } from './GatedButton';
import { FinishSelect } from './FinishSelect';
import { defaultSurfaceFinishes } from '../../core/catalog/surfaceFinishes';
import { CommitField } from '../shared/CommitField';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';
import { screenToWorld, worldToScreen, type PlanView } from './viewTransform';
import { shapeWall } from './RoomShapeDrawing';
import { snapCorner, slideOpening } from './roomShapeDrag';

export interface RoomShapeEditorProps {
  config: Configuration;
  view: PlanView;
  gate: ActionGate;
  onDone: () => void;
  /** The plan pixels the bar (top) and the sheet's room (bottom) cover: the planner fits the room between them (a stable callback). */
  onInsets: (top: number, bottom: number) => void;
}

type Picked = { kind: 'wall' | 'corner' | 'opening'; index: number } | null;
type Dragging = { kind: 'corner'; index: number; at: PlanPoint } | { kind: 'opening'; index: number; offset: number; grab: number } | null;

/** A press that moves less than this (px) is a tap: it picks what it is on instead of dragging it. */
const TAP_PX = 6;
/** A corner's move per arrow key, metres (plan x right, z down on screen). */
const ARROW_STEPS: Record<string, PlanPoint | undefined> = { ArrowLeft: [-0.05, 0], ArrowRight: [0.05, 0], ArrowUp: [0, -0.05], ArrowDown: [0, 0.05] };
/** How far inside its wall a wall's length label's centre sits, px: half the label (32 px high, about 56 wide) and a little. */
const LABEL_CLEAR_PX = { across: 22, along: 34 };
/** How far outside its wall an opening's handle sits, px. */
const HANDLE_OUT_PX = 16;

const KIND_KEYS = { door: 'roomShape.door', window: 'roomShape.window', opening: 'roomShape.opening' } as const satisfies Record<string, MessageKey>;
const PRESET_KEYS = { rectangle: 'roomShape.rectangle', L: 'roomShape.L', U: 'roomShape.U', T: 'roomShape.T' } as const satisfies Record<(typeof SHAPE_PRESETS)[number], MessageKey>;

/**
 * The room-shape mode (issue 29, docs/planner.md "Rooms of any shape"): over the plan, a handle on
 * every corner and opening and a length label on every wall; a bar of presets at the top and, for
 * what was tapped, a sheet at the bottom with its fields and buttons. Every change is one model
 * action through the gate, so a refused edit shows the model's reason and changes nothing. A chunk
 * of its own (LazyRoomShapeEditor): nothing of it is on the first screen.
 */
export default function RoomShapeEditor({ config, view, gate, onDone, onInsets }: RoomShapeEditorProps) {
  const { t, format } = useI18n();
  const shape = currentShape(config.room);
  const { outline } = shape;
  const [picked, setPicked] = useState<Picked>(null);
  const [dragging, setDragging] = useState<Dragging>(null);
  const [press, setPress] = useState<{ x: number; y: number; moved: boolean } | null>(null);
  // The sheet's room at the bottom: 40 % of the plan's height, at most 280 px, kept free whatever is picked so the room does not jump.
  const rootRef = useRef<HTMLDivElement>(null);
  const barRef = useRef<HTMLDivElement>(null);
  const [sheetRoom, setSheetRoom] = useState(0);
  const [planWidth, setPlanWidth] = useState(Infinity);
  useLayoutEffect(() => {
    const root = rootRef.current;
    const bar = barRef.current;
    if (!root || !bar) return;
    const measure = () => {
      const reserve = Math.min(280, Math.round(0.4 * root.clientHeight));
      setSheetRoom(reserve);
      setPlanWidth(root.clientWidth);
      // Room for the opening handles outside the top and bottom walls too.
      onInsets(bar.offsetTop + bar.offsetHeight + 8 + HANDLE_OUT_PX, reserve + 16 + HANDLE_OUT_PX);
    };
    measure();
    const ro = new ResizeObserver(measure);
    ro.observe(root);
    ro.observe(bar);
    return () => ro.disconnect();
  }, [onInsets]);
  const screen = (p: PlanPoint) => worldToScreen(view, { x: p[0], z: p[1] });
  const m = (v: number) => format.number(v, { minimumFractionDigits: 2, maximumFractionDigits: 2 });

  // Where a pointer is on the plan, metres.
  const planPoint = (e: ReactPointerEvent): PlanPoint => {
    const box = (e.currentTarget as HTMLElement).closest('.plan-wrap')!.getBoundingClientRect();
    const w = screenToWorld(view, { sx: e.clientX - box.left, sy: e.clientY - box.top });
    return [w.x, w.z];
  };
  const begin = (e: ReactPointerEvent) => {
    (e.currentTarget as HTMLElement).setPointerCapture?.(e.pointerId);
    setPress({ x: e.clientX, y: e.clientY, moved: false });
  };
  const moved = (e: ReactPointerEvent) => press !== null && (press.moved || Math.hypot(e.clientX - press.x, e.clientY - press.y) > TAP_PX);
  const finish = (run: () => string | null, tap: Picked) => {
    if (press && !press.moved) setPicked(tap);
    else {
      const refused = run();
      if (refused) gate.explain(refused);
    }
    setPress(null);
    setDragging(null);
  };

  const shown = dragging?.kind === 'corner' ? outline.map((p, i) => (i === dragging.index ? dragging.at : p)) : outline;
  const selectedWall = picked?.kind === 'wall' ? picked.index : -1;

  return (
    <div ref={rootRef} className="room-shape-editor plan-overlay" data-testid="room-shape-editor">
      <svg className="room-shape-lines" aria-hidden>
        <path d={`M${shown.map((p) => `${screen(p).sx},${screen(p).sy}`).join('L')}Z`} className={dragging ? 'room-shape-preview' : 'room-shape-outline'} />
        {selectedWall >= 0 && (
          <line
            x1={screen(outline[selectedWall]).sx}
            y1={screen(outline[selectedWall]).sy}
            x2={screen(outline[(selectedWall + 1) % outline.length]).sx}
            y2={screen(outline[(selectedWall + 1) % outline.length]).sy}
            className="room-shape-picked"
          />
        )}
      </svg>
      {outline.map((_, i) => {
        const a = screen(shown[i]);
        const b = screen(shown[(i + 1) % shown.length]);
        const { length, n } = shapeWall(shown, i);
        // Inside the wall (outside, the labels of an L's notch walls would crowd its inner corner), clear of the opening handles, which sit outside; labels are wider than tall, so further in from an upright wall. The view does not turn the plan: screen and plan normals agree.
        const out = LABEL_CLEAR_PX.across * Math.abs(n[1]) + LABEL_CLEAR_PX.along * Math.abs(n[0]);
        const left = Math.min(Math.max((a.sx + b.sx) / 2 + n[0] * out, 30), planWidth - 30);
        return (
          <button
            key={`w${i}`}
            type="button"
            className={`room-wall-label${selectedWall === i ? ' picked' : ''}`}
            style={{ left, top: (a.sy + b.sy) / 2 + n[1] * out }}
            aria-label={t('roomShape.wallButton', { wall: i, length: m(length) })}
            data-plan-control
            data-testid={`room-wall-${i}`}
            onClick={() => setPicked({ kind: 'wall', index: i })}
          >
            {m(length)}
          </button>
        );
      })}
      {shown.map((p, i) => {
        const s = screen(p);
        return (
          <button
            key={`c${i}`}
            type="button"
            className={`room-corner-handle${picked?.kind === 'corner' && picked.index === i ? ' picked' : ''}`}
            style={{ left: s.sx, top: s.sy }}
            aria-label={t('roomShape.cornerHandle', { corner: i })}
            data-plan-control
            data-testid={`room-corner-${i}`}
            onPointerDown={begin}
            onPointerMove={(e) => {
              if (!moved(e)) return;
              setPress((old) => old && { ...old, moved: true });
              setDragging({ kind: 'corner', index: i, at: snapCorner(outline, i, planPoint(e), view.scale) });
            }}
            onPointerUp={() => finish(() => (dragging?.kind === 'corner' ? gate.attempt('moveRoomCorner', { corner: i, x: dragging.at[0], z: dragging.at[1] }) : null), { kind: 'corner', index: i })}
            onPointerCancel={() => (setPress(null), setDragging(null))}
            onKeyDown={(e) => {
              if (e.key === 'Enter' || e.key === ' ') setPicked({ kind: 'corner', index: i });
              // Arrow keys move the corner 5 cm (no pointer needed).
              const step = ARROW_STEPS[e.key];
              if (!step) return;
              e.preventDefault();
              const refused = gate.attempt('moveRoomCorner', { corner: i, x: Math.round((p[0] + step[0]) * 1000) / 1000, z: Math.round((p[1] + step[1]) * 1000) / 1000 });
              if (refused) gate.explain(refused);
            }}
          />
        );
      })}
      {shape.openings.map((o, k) => {
        const { a, u, n, length } = shapeWall(outline, o.wall);
        const offset = dragging?.kind === 'opening' && dragging.index === k ? dragging.offset : o.offset;
        const centre = screen([a[0] + u[0] * (offset + o.width / 2), a[1] + u[1] * (offset + o.width / 2)]);
        // Just outside its wall, so it covers neither the door's swing nor the wall's length label.
        const s = { sx: centre.sx - n[0] * HANDLE_OUT_PX, sy: centre.sy - n[1] * HANDLE_OUT_PX };
        return (
          <button
            key={`o${k}`}
            type="button"
            className={`room-opening-handle${picked?.kind === 'opening' && picked.index === k ? ' picked' : ''}`}
            style={{ left: s.sx, top: s.sy }}
            aria-label={t('roomShape.openingHandle', { kind: t(KIND_KEYS[o.kind]), wall: o.wall })}
            data-plan-control
            data-testid={`room-opening-${k}`}
            onPointerDown={(e) => {
              begin(e);
              const p = planPoint(e);
              setDragging({ kind: 'opening', index: k, offset: o.offset, grab: (p[0] - a[0]) * u[0] + (p[1] - a[1]) * u[1] - o.offset });
            }}
            onPointerMove={(e) => {
              if (!moved(e) || dragging?.kind !== 'opening') return;
              setPress((old) => old && { ...old, moved: true });
              const p = planPoint(e);
              setDragging({ ...dragging, offset: slideOpening((p[0] - a[0]) * u[0] + (p[1] - a[1]) * u[1] - dragging.grab, o.width, length) });
            }}
            onPointerUp={() => finish(() => (dragging?.kind === 'opening' ? gate.attempt('setRoomOpening', { opening: k, offset: dragging.offset }) : null), { kind: 'opening', index: k })}
            onPointerCancel={() => (setPress(null), setDragging(null))}
            onKeyDown={(e) => {
              if (e.key === 'Enter' || e.key === ' ') setPicked({ kind: 'opening', index: k });
            }}
          >
            {t(KIND_KEYS[o.kind]).charAt(0)}
          </button>
        );
      })}
      <div ref={barRef} className="room-shape-bar" data-plan-control role="toolbar" aria-label={t('roomShape.title')}>
        <span className="room-shape-title">{t('roomShape.startFrom')}</span>
        {SHAPE_PRESETS.map((preset) => (
          <GatedButton key={preset} gate={gate} action="setRoomShapePreset" params={{ preset }} label={t(PRESET_KEYS[preset])} testId={`room-preset-${preset}`} onRan={() => setPicked(null)}>
            {t(PRESET_KEYS[preset])}
          </GatedButton>
        ))}
        <button type="button" className="btn btn-primary" onClick={onDone} data-testid="room-shape-done">
          {t('roomShape.done')}
        </button>
      </div>
      {picked === null ? (
        <p className="room-shape-sheet room-shape-hint" data-plan-control style={{ maxHeight: sheetRoom }}>
          {t('roomShape.hint')}
        </p>
      ) : (
        <Sheet config={config} picked={picked} gate={gate} onClose={() => setPicked(null)} maxHeight={sheetRoom} />
      )}
    </div>
  );
}

/** What was tapped, edited: a wall's length, split, slope and openings; a corner's angle; an opening's place and size. */
function Sheet({ config, picked, gate, onClose, maxHeight }: { config: Configuration; picked: NonNullable<Picked>; gate: ActionGate; onClose: () => void; maxHeight: number }) {
  const { t } = useI18n();
  const shape = currentShape(config.room);
  const n = shape.outline.length;
  const field = (label: MessageKey, value: number, commit: (v: number) => string | null, testId: string, decimals = 2) => (
    <label className="room-shape-field">
      <span>{t(label)}</span>
      <CommitField label={t(label)} value={value} decimals={decimals} onCommit={commit} onRefused={gate.explain} testId={testId} />
    </label>
  );
  let title: string;
  let body;
  if (picked.kind === 'wall' && picked.index < n) {
    const wall = picked.index;
    const length = wallLength(shape.outline, wall);
    const slope = shape.slopes.find((s) => s.wall === wall);
    title = t('roomShape.wall', { wall });
    body = (
      <>
        {field('roomShape.wallLength', length, (v) => gate.attempt('setRoomWallLength', { wall, length: v }), 'room-wall-length')}
        <div className="room-shape-buttons">
          <GatedButton gate={gate} action="splitRoomWall" params={{ wall, at: Math.round((length / 2) * 1000) / 1000 }} label={t('roomShape.split')} testId="room-wall-split">
            {t('roomShape.split')}
          </GatedButton>
          {(['door', 'window', 'opening'] as const).map((kind) => (
            <GatedButton
              key={kind}
              gate={gate}
              action="addRoomOpening"
              params={{ wall, kind }}
              label={t(kind === 'door' ? 'roomShape.addDoor' : kind === 'window' ? 'roomShape.addWindow' : 'roomShape.addOpening')}
              testId={`room-add-${kind}`}
            >
              {t(kind === 'door' ? 'roomShape.addDoor' : kind === 'window' ? 'roomShape.addWindow' : 'roomShape.addOpening')}
            </GatedButton>
          ))}
          {!slope && (
            <GatedButton gate={gate} action="setRoomSlope" params={{ wall, kneeHeight: Math.min(1.2, config.room.height), pitch: 40 }} label={t('roomShape.addSlope')} testId="room-add-slope">
              {t('roomShape.addSlope')}
            </GatedButton>
          )}
        </div>
        <FinishSelect
          id={`room-wall-finish-${wall}`}
          label={t('app.walls')}
          use="walls"
          value={wallFinishes(config.room, shape)[wall]}
          finishes={defaultSurfaceFinishes}
          onChoose={(f) => gate.run('setWallFinish', { wall, value: f.reflectance })}
          disabledReason={(f) => gate.reason('setWallFinish', { wall, value: f.reflectance })}
          testId="room-wall-finish"
        />
        {slope && (
          <div className="room-shape-slope" data-testid="room-slope-fields">
            {field('roomShape.knee', slope.kneeHeight, (v) => gate.attempt('setRoomSlope', { wall, kneeHeight: v, pitch: slope.pitch }), 'room-slope-knee')}
            {field('roomShape.pitch', slope.pitch, (v) => gate.attempt('setRoomSlope', { wall, kneeHeight: slope.kneeHeight, pitch: v }), 'room-slope-pitch', 0)}
            <GatedButton gate={gate} action="removeRoomSlope" params={{ wall }} label={t('roomShape.removeSlope')} testId="room-remove-slope">
              {t('roomShape.removeSlope')}
            </GatedButton>
          </div>
        )}
      </>
    );
  } else if (picked.kind === 'corner' && picked.index < n) {
    const corner = picked.index;
    title = t('roomShape.corner', { corner });
    body = (
      <>
        {field('roomShape.angle', cornerAngle(shape.outline, corner), (v) => gate.attempt('setRoomCornerAngle', { corner, degrees: v }), 'room-corner-angle', 1)}
        <GatedButton gate={gate} action="removeRoomCorner" params={{ corner }} label={t('roomShape.removeCorner')} testId="room-remove-corner" onRan={onClose}>
          {t('roomShape.removeCorner')}
        </GatedButton>
      </>
    );
  } else if (picked.kind === 'opening' && shape.openings[picked.index]) {
    const opening = picked.index;
    const o = shape.openings[opening];
    title = `${t(KIND_KEYS[o.kind])} · ${t('roomShape.wall', { wall: o.wall })}`;
    body = (
      <>
        {field('roomShape.offset', o.offset, (v) => gate.attempt('setRoomOpening', { opening, offset: v }), 'room-opening-offset')}
        {field('roomShape.width', o.width, (v) => gate.attempt('setRoomOpening', { opening, width: v }), 'room-opening-width')}
        {field('roomShape.height', o.height, (v) => gate.attempt('setRoomOpening', { opening, height: v }), 'room-opening-height')}
        {o.kind !== 'door' && field('roomShape.sill', o.sill, (v) => gate.attempt('setRoomOpening', { opening, sill: v }), 'room-opening-sill')}
        <GatedButton gate={gate} action="removeRoomOpening" params={{ opening }} label={t('roomShape.remove')} testId="room-remove-opening" onRan={onClose}>
          {t('roomShape.remove')}
        </GatedButton>
      </>
    );
  } else {
    // What was picked is gone (an undo, a preset): nothing to edit.
    return null;
  }
  return (
    <section className="room-shape-sheet" data-plan-control aria-label={title} data-testid="room-shape-sheet" style={{ maxHeight }}>
      <header>
        <h3>{title}</h3>
        <button type="button" className="btn" onClick={onClose} aria-label={t('common.close')}>
          ×
        </button>
      </header>
      <div className="room-shape-fields">{body}</div>
    </section>
  );
}
