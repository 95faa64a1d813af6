import './registerRoomShapeEnglish';
import './roomShape.css';
import { useLayoutEffect, useRef, useState } from 'react';
import type { Configuration } from '../../core/model/configuration/configuration';
import { currentShape, SHAPE_PRESETS } from '../../core/model/actions/roomShapeGeometry';
import type { PlanPoint } from '../../core/room/planPolygon';
import type { ActionGate } from './actionGate';
import { GatedButton } from './GatedButton';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';
import { worldToScreen, type PlanView } from './viewTransform';
import { CornerHandles, HANDLE_OUT_PX, OpeningHandles, WallLabels } from './RoomShapeHandles';
import { RoomShapeSheet } from './RoomShapeSheet';
import { useShapeDrag, type Picked } from './useShapeDrag';

export interface RoomShapeEditorProps {
  config: Configuration;
  view: PlanView;
  gate: ActionGate;
  onDone: () => void;
  /** The plan pixels the bar (top) and the sheet's room (bottom) cover: the planner fits the room between them (a stable callback). */
  onInsets: (top: number, bottom: number) => void;
}

const PRESET_KEYS = { rectangle: 'roomShape.rectangle', L: 'roomShape.L', U: 'roomShape.U', T: 'roomShape.T' } as const satisfies Record<(typeof SHAPE_PRESETS)[number], MessageKey>;

/** The sheet's room at the bottom (40 % of the plan's height, at most 280 px) and the plan's width, measured; the planner is told the insets. */
function useEditorInsets(onInsets: RoomShapeEditorProps['onInsets']) {
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
  return { rootRef, barRef, sheetRoom, planWidth };
}

/** The outline as drawn (the corner being dragged at its preview place) and the picked wall's line. */
function ShapeLines({ view, outline, shown, dragging, selectedWall }: { view: PlanView; outline: readonly PlanPoint[]; shown: readonly PlanPoint[]; dragging: boolean; selectedWall: number }) {
  const screen = (p: PlanPoint) => worldToScreen(view, { x: p[0], z: p[1] });
  return (
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
  );
}

/**
 * The room-shape mode (issue 29, docs/planner.md "Rooms of any shape"): over the plan, a handle on
 * every corner and opening and a length label on every wall; a bar of presets at the top and, for
 * what was tapped, a sheet at the bottom with its fields and buttons (a window's glazing too, issue
 * 30). Every change is one model action through the gate, so a refused edit shows the model's
 * reason and changes nothing. A chunk of its own (LazyRoomShapeEditor): nothing of it is on the first screen.
 */
export default function RoomShapeEditor({ config, view, gate, onDone, onInsets }: RoomShapeEditorProps) {
  const { t } = useI18n();
  const shape = currentShape(config.room);
  const { outline } = shape;
  const [picked, setPicked] = useState<Picked>(null);
  const drag = useShapeDrag(view, gate, setPicked);
  const { rootRef, barRef, sheetRoom, planWidth } = useEditorInsets(onInsets);
  const { dragging } = drag;
  const shown = dragging?.kind === 'corner' ? outline.map((p, i) => (i === dragging.index ? dragging.at : p)) : outline;
  const handles = { view, picked, setPicked };
  return (
    <div ref={rootRef} className="room-shape-editor plan-overlay" data-testid="room-shape-editor">
      <ShapeLines view={view} outline={outline} shown={shown} dragging={dragging !== null} selectedWall={picked?.kind === 'wall' ? picked.index : -1} />
      <WallLabels {...handles} shown={shown} planWidth={planWidth} />
      <CornerHandles {...handles} outline={outline} shown={shown} drag={drag} gate={gate} />
      <OpeningHandles {...handles} shape={shape} drag={drag} gate={gate} />
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
        <RoomShapeSheet config={config} picked={picked} gate={gate} onClose={() => setPicked(null)} maxHeight={sheetRoom} />
      )}
    </div>
  );
}
