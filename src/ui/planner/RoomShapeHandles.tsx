import './registerRoomShapeEnglish';
import type { RoomShape } from '../../core/model/configuration/configuration';
import type { PlanPoint } from '../../core/room/planPolygon';
import type { ActionGate } from './actionGate';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';
import { worldToScreen, type PlanView } from './viewTransform';
import { shapeWall } from './RoomShapeDrawing';
import { snapCorner, slideOpening } from './roomShapeDrag';
import type { Picked, ShapeDrag } from './useShapeDrag';

/** A corner's move per arrow key, metres (plan x right, z down on screen). */
const ARROW_STEPS: Record<string, PlanPoint | undefined> = { ArrowLeft: [-0.05, 0], ArrowRight: [0.05, 0], ArrowUp: [0, -0.05], ArrowDown: [0, 0.05] };
/** How far inside its wall a wall's length label's centre sits, px: half the label (32 px high, about 56 wide) and a little. */
const LABEL_CLEAR_PX = { across: 22, along: 34 };
/** How far outside its wall an opening's handle sits, px. */
export const HANDLE_OUT_PX = 16;

export const KIND_KEYS = { door: 'roomShape.door', window: 'roomShape.window', opening: 'roomShape.opening' } as const satisfies Record<string, MessageKey>;

interface HandleProps {
  view: PlanView;
  picked: Picked;
  setPicked: (p: Picked) => void;
}

/** A length label on every wall (inside it), a button that picks the wall. */
export function WallLabels({ view, shown, picked, setPicked, planWidth }: HandleProps & { shown: readonly PlanPoint[]; planWidth: number }) {
  const { t, format } = useI18n();
  const m = (v: number) => format.number(v, { minimumFractionDigits: 2, maximumFractionDigits: 2 });
  const labels = shown.map((_, i) => {
    const a = worldToScreen(view, { x: shown[i][0], z: shown[i][1] });
    const b = worldToScreen(view, { x: shown[(i + 1) % shown.length][0], z: shown[(i + 1) % shown.length][1] });
    const { length, n } = shapeWall(shown, i);
    // Inside the wall (outside, the labels of an L's notch walls would crowd its inner corner), clear of the opening handles, which sit outside; labels are wider than tall, so further in from an upright wall. The view does not turn the plan: screen and plan normals agree.
    const out = LABEL_CLEAR_PX.across * Math.abs(n[1]) + LABEL_CLEAR_PX.along * Math.abs(n[0]);
    const left = Math.min(Math.max((a.sx + b.sx) / 2 + n[0] * out, 30), planWidth - 30);
    const selected = picked?.kind === 'wall' && picked.index === i;
    return (
      <button
        key={`w${i}`}
        type="button"
        className={`room-wall-label${selected ? ' picked' : ''}`}
        style={{ left, top: (a.sy + b.sy) / 2 + n[1] * out }}
        aria-label={t('roomShape.wallButton', { wall: i, length: m(length) })}
        data-plan-control
        data-testid={`room-wall-${i}`}
        onClick={() => setPicked({ kind: 'wall', index: i })}
      >
        {m(length)}
      </button>
    );
  });
  return <>{labels}</>;
}

/** A handle on every corner: drag to move it, tap to edit its angle, arrows to nudge it. */
export function CornerHandles({ view, outline, shown, picked, setPicked, drag, gate }: HandleProps & { outline: readonly PlanPoint[]; shown: readonly PlanPoint[]; drag: ShapeDrag; gate: ActionGate }) {
  const { t } = useI18n();
  const handles = shown.map((p, i) => {
    const s = worldToScreen(view, { x: p[0], z: p[1] });
    const { dragging } = drag;
    return (
      <button
        key={`c${i}`}
        type="button"
        className={`room-corner-handle${picked?.kind === 'corner' && picked.index === i ? ' picked' : ''}`}
        style={{ left: s.sx, top: s.sy }}
        aria-label={t('roomShape.cornerHandle', { corner: i })}
        data-plan-control
        data-testid={`room-corner-${i}`}
        onPointerDown={drag.begin}
        onPointerMove={(e) => {
          if (!drag.moved(e)) return;
          drag.markMoved();
          drag.setDragging({ kind: 'corner', index: i, at: snapCorner(outline, i, drag.planPoint(e), view.scale) });
        }}
        onPointerUp={() => drag.finish(() => (dragging?.kind === 'corner' ? gate.attempt('moveRoomCorner', { corner: i, x: dragging.at[0], z: dragging.at[1] }) : null), { kind: 'corner', index: i })}
        onPointerCancel={drag.cancel}
        onKeyDown={(e) => {
          if (e.key === 'Enter' || e.key === ' ') setPicked({ kind: 'corner', index: i });
          // Arrow keys move the corner 5 cm (no pointer needed).
          const step = ARROW_STEPS[e.key];
          if (!step) return;
          e.preventDefault();
          const refused = gate.attempt('moveRoomCorner', { corner: i, x: Math.round((outline[i][0] + step[0]) * 1000) / 1000, z: Math.round((outline[i][1] + step[1]) * 1000) / 1000 });
          if (refused) gate.explain(refused);
        }}
      />
    );
  });
  return <>{handles}</>;
}

/** A handle just outside its wall on every opening: drag along the wall, tap to edit. */
export function OpeningHandles({ view, shape, picked, setPicked, drag, gate }: HandleProps & { shape: RoomShape; drag: ShapeDrag; gate: ActionGate }) {
  const { t } = useI18n();
  const handles = shape.openings.map((o, k) => {
    const { a, u, n, length } = shapeWall(shape.outline, o.wall);
    const { dragging } = drag;
    const offset = dragging?.kind === 'opening' && dragging.index === k ? dragging.offset : o.offset;
    const centre = worldToScreen(view, { x: a[0] + u[0] * (offset + o.width / 2), z: a[1] + u[1] * (offset + o.width / 2) });
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
          drag.begin(e);
          const p = drag.planPoint(e);
          drag.setDragging({ kind: 'opening', index: k, offset: o.offset, grab: (p[0] - a[0]) * u[0] + (p[1] - a[1]) * u[1] - o.offset });
        }}
        onPointerMove={(e) => {
          if (!drag.moved(e) || dragging?.kind !== 'opening') return;
          drag.markMoved();
          const p = drag.planPoint(e);
          drag.setDragging({ ...dragging, offset: slideOpening((p[0] - a[0]) * u[0] + (p[1] - a[1]) * u[1] - dragging.grab, o.width, length) });
        }}
        onPointerUp={() => drag.finish(() => (dragging?.kind === 'opening' ? gate.attempt('setRoomOpening', { opening: k, offset: dragging.offset }) : null), { kind: 'opening', index: k })}
        onPointerCancel={drag.cancel}
        onKeyDown={(e) => {
          if (e.key === 'Enter' || e.key === ' ') setPicked({ kind: 'opening', index: k });
        }}
      >
        {t(KIND_KEYS[o.kind]).charAt(0)}
      </button>
    );
  });
  return <>{handles}</>;
}
