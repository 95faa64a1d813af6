import { useCallback, useMemo, useSyncExternalStore, type DragEvent } from 'react';
import { mixLevels, outputLevels } from '../../core/model/cues/sceneFade';
import { sentenceStart } from '../i18n/sentenceStart';
import { noticeText } from '../i18n/noticeText';
import { scenePlayerHandle } from '../scenes/scenePlayerHandle';
import { addLibraryItem } from './addFurniture';
import { CommandButton } from './CommandButton';
import { detailLevel } from './detailLevel';
import { FURNITURE_DRAG_TYPE } from './FurniturePanel';
import { LazyRoomShapeEditor } from './LazyRoomShape';
import { LazyGuidance } from './lazyGuidance';
import { daylightFactorOffered, LazyDaylightFactor } from './LazyDaylightFactor';
import { PlanControls } from './PlanControls';
import type { PlannerScope } from './plannerScope';
import { PlanSvg } from './PlanSvg';

/** A library item dragged from the panel may be dropped on the plan. */
const dragOver = (e: DragEvent) => {
  if (!e.dataTransfer.types.includes(FURNITURE_DRAG_TYPE)) return;
  e.preventDefault();
  e.dataTransfer.dropEffect = 'copy';
};

/** The 2D plan: its drawing, the controls on it, zoom buttons, first-run suggestions, the room-shape editor and the status line. */
export function PlanPane({ p }: { p: PlannerScope }) {
  const { store, ui, controller, config, catalog, view, viewport, drag, gate, path, wrapRef, status, roomEdit, firstRun } = p;
  // A light-scene crossfade: the plan shows each module's level as it fades (docs/light-scenes.md).
  const player = scenePlayerHandle(store);
  const fading = useSyncExternalStore(player.subscribe, () => player.getState().fading);
  const fadeLevelsShown = useMemo(() => (fading ? mixLevels(fading.fromLevels, outputLevels(fading.to), fading.e) : null), [fading]);
  const level = detailLevel(view.scale);
  // The daylight-factor overlay (issue 30): offered when daylight comes in through a window; its code loads then.
  const dfOffered = daylightFactorOffered(config);
  // The room-shape mode's bar and sheet cover the plan's edges: the room is fitted between them (a stable callback: the editor's effect depends on it).
  const fitBetween = useCallback((top: number, bottom: number) => controller.setFitInsets(top, bottom), [controller]);
  // A library item dropped on the plan lands where it was dropped.
  const drop = (e: DragEvent) => {
    const itemId = e.dataTransfer.getData(FURNITURE_DRAG_TYPE);
    const el = wrapRef.current;
    if (!itemId || !el) return;
    e.preventDefault();
    const r = el.getBoundingClientRect();
    addLibraryItem(controller, itemId, { sx: e.clientX - r.left, sy: e.clientY - r.top });
  };
  return (
    <div className="plan-wrap" ref={wrapRef} data-testid="plan" data-scale={view.scale.toFixed(3)} data-level={level} onDragOver={dragOver} onDrop={drop}>
      <PlanSvg config={config} catalog={catalog} view={view} selection={path} drag={drag} footprints={p.footprints} levels={fadeLevelsShown} daylightFactorOf={dfOffered ? store : null} />
      <PlanControls config={config} catalog={catalog} view={view} viewport={viewport} level={level} selection={path} gate={gate} onSelect={p.select} onOpenOptions={() => ui.setState({ optionsOpen: true, panelOpen: true })} drag={drag} />
      <div className="zoom-controls" data-plan-control>
        <CommandButton controller={controller} id="zoom-in" testId="zoom-in">
          +
        </CommandButton>
        <CommandButton controller={controller} id="zoom-out" testId="zoom-out">
          −
        </CommandButton>
        <CommandButton controller={controller} id="zoom-fit" testId="zoom-fit">
          ⤢
        </CommandButton>
      </div>
      {dfOffered && <LazyDaylightFactor part="controls" store={store} hidden={roomEdit} onInsets={fitBetween} />}
      {config.systems.length === 0 && config.objects.length === 0 && firstRun !== false && !roomEdit && <LazyGuidance firstRun={{ room: config.room, catalog, gate, options: firstRun, onPlaced: p.placedNew, ui }} />}
      {roomEdit && (
        <LazyRoomShapeEditor
          config={config}
          view={view}
          gate={gate}
          onInsets={fitBetween}
          onDone={() => {
            controller.setFitInsets(0, 0);
            ui.setState({ roomEdit: false });
          }}
        />
      )}
      {status && (
        <div className="status-line" role="status" data-testid="status-line" key={status.seq}>
          {sentenceStart(noticeText(p.t, p.language, catalog, status), p.locale)}
        </div>
      )}
    </div>
  );
}
