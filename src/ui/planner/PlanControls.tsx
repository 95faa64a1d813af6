import { useState, type CSSProperties, type ReactNode } from 'react';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration, LightSystem } from '../../core/model/configuration/configuration';
import { isFreeRail } from '../../core/model/rails/freePositions';
import { modulePlacements, railPlacements, type PlanVec } from '../../core/model/rails/geometry';
import { ActionButton } from './ActionButton';
import { LazyDistributionButtons } from './LazyDistributionButtons';
import { GatedButton } from './GatedButton';
import { RailLengthField } from './RailLengthField';
import { CommitField } from '../shared/CommitField';
import type { ActionGate } from './actionGate';
import type { DetailLevel } from './detailLevel';
import type { Selection } from '../../core/store/createConfiguratorStore';
import type { SelectionPath } from './selection';
import { type PlanView, type Viewport, worldToScreen } from './viewTransform';
import { useI18n } from '../i18n/useI18n';
import { drawnSystems } from './drawnSystems';
import type { DragPreview } from './dragPreview';
import { localName } from '../i18n/localName';

export interface PlanControlsProps {
  config: Configuration;
  catalog: Catalog;
  view: PlanView;
  viewport: Viewport;
  level: DetailLevel;
  selection: SelectionPath;
  gate: ActionGate;
  onSelect: (sel: Selection) => void;
  /** Opens the options panel for the current selection. */
  onOpenOptions: () => void;
  /** The drag in progress (PlannerController.drag): controls follow the systems as drawn (drawnSystems). */
  drag?: DragPreview | null;
}

/** Distance of on-plan controls from a rail's centre line, in screen pixels (constant while zooming). */
const NEAR_PX = 34;
const FAR_PX = 92;
/** Rails shorter than this on screen get no length field at system level. */
const MIN_RAIL_PX_FOR_FIELD = 110;
/** Approximate on-screen sizes of the fields, for keeping them from covering each other. */
const MOVE_FIELD_BOX = { w: 170, h: 50 };
const LENGTH_FIELD_BOX = { w: 104, h: 50 };

/**
 * A plan whose short side is below this (px: a phone, upright or on its side) gets the selected
 * system's position and length fields behind one 44 px button instead of over the plan
 * (docs/planner.md, "On-plan fields on a phone").
 */
export const COMPACT_PLAN_PX = 520;
/** The expand/collapse button in front of the move fields on a compact plan. */
const TOGGLE_BOX = { w: 48, h: 50 };

type Box = { sx: number; sy: number; w: number; h: number };
const overlaps = (a: Box, b: Box) => Math.abs(a.sx - b.sx) * 2 < a.w + b.w && Math.abs(a.sy - b.sy) * 2 < a.h + b.h;

/** Short label for a module type's switch button (its first word). */
export function typeShortName(name: string): string {
  return name.split(/\s+/)[0] ?? name;
}

function Positioned({ at, children, className, testId }: { at: { sx: number; sy: number }; children: ReactNode; className?: string; testId?: string }) {
  const style: CSSProperties = { transform: `translate(${at.sx}px, ${at.sy}px) translate(-50%, -50%)` };
  return (
    <div className={`plan-control${className ? ` ${className}` : ''}`} style={style} data-plan-control data-testid={testId}>
      {children}
    </div>
  );
}

/**
 * The on-screen side of a rail for controls "above" it: the unit normal of its screen
 * direction that points up (or left for a vertical rail), so plus buttons read as above the
 * rail whatever its heading.
 */
function upNormal(view: PlanView, start: PlanVec, end: PlanVec): { nx: number; ny: number } {
  const a = worldToScreen(view, { x: start[0], z: start[1] });
  const b = worldToScreen(view, { x: end[0], z: end[1] });
  const len = Math.hypot(b.sx - a.sx, b.sy - a.sy) || 1;
  const dx = (b.sx - a.sx) / len;
  const dy = (b.sy - a.sy) / len;
  let nx = dy;
  let ny = -dx;
  if (ny > 1e-9 || (Math.abs(ny) <= 1e-9 && nx > 0)) {
    nx = -nx;
    ny = -ny;
  }
  return { nx, ny };
}

function visible(p: { sx: number; sy: number }, viewport: Viewport): boolean {
  const m = 120;
  return p.sx > -m && p.sy > -m && p.sx < viewport.width + m && p.sy < viewport.height + m;
}

/** Figure 6: red fields move the system (anchor x, z), blue fields set each rail's length. */
function SystemLevelControls({ system, catalog, view, viewport, gate }: { system: LightSystem; catalog: Catalog; view: PlanView; viewport: Viewport; gate: ActionGate }) {
  const { t } = useI18n();
  // On a phone the fields stay folded behind one button until asked for (PlanControls keys this by system: a new selection folds them again).
  const compact = Math.min(viewport.width, viewport.height) < COMPACT_PLAN_PX;
  const [expanded, setExpanded] = useState(false);
  const rails = railPlacements(system, catalog);
  const anchor = worldToScreen(view, { x: system.x, z: system.z });
  const first = rails[0];
  const n = first ? upNormal(view, first.start, first.end) : { nx: 0, ny: -1 };
  // Put the move fields on the side opposite the length fields, just off the system's start.
  const at = { sx: anchor.sx - n.nx * 44, sy: anchor.sy - n.ny * 44 };
  // On a small plan the group (fold button and fields) is kept inside the plan's width rather than cut off at its edge.
  const half = (expanded ? MOVE_FIELD_BOX.w + TOGGLE_BOX.w : TOGGLE_BOX.w) / 2 + 4;
  const movePos = compact && viewport.width > 2 * half ? { sx: Math.min(viewport.width - half, Math.max(half, at.sx)), sy: at.sy } : at;
  const toggle = compact && (
    <button
      type="button"
      className="action-button fields-toggle"
      aria-expanded={expanded}
      aria-label={expanded ? t('planner.hidePlacement') : t('planner.editPlacement')}
      title={expanded ? t('planner.hidePlacement') : t('planner.editPlacement')}
      data-testid={`fields-toggle-${system.id}`}
      onClick={(e) => {
        e.stopPropagation();
        setExpanded(!expanded);
      }}
    >
      <span aria-hidden>{expanded ? '✕' : '✎'}</span>
    </button>
  );
  const folded = compact && !expanded;
  const placed: Box[] = [{ ...movePos, ...MOVE_FIELD_BOX, w: MOVE_FIELD_BOX.w + (compact ? TOGGLE_BOX.w : 0) }];
  return (
    <>
      {/* One element for both states, so the button keeps the focus when it unfolds or folds the fields. */}
      {visible(movePos, viewport) && (
        <Positioned at={movePos} className={folded ? 'fields-toggle-wrap' : 'move-field'} testId={folded ? `fields-${system.id}` : `move-${system.id}`}>
          {toggle}
          {!folded && (
            <>
              <span aria-hidden>x</span>
              <CommitField label={t('planner.systemPositionX')} value={system.x} onCommit={(x) => gate.attempt('moveSystem', { systemId: system.id, x, z: system.z })} onRefused={gate.explain} />
              <span aria-hidden>z</span>
              <CommitField label={t('planner.systemPositionZ')} value={system.z} onCommit={(z) => gate.attempt('moveSystem', { systemId: system.id, x: system.x, z })} onRefused={gate.explain} />
            </>
          )}
        </Positioned>
      )}
      {!folded &&
        rails.map((r, i) => {
          const mid = worldToScreen(view, { x: (r.start[0] + r.end[0]) / 2, z: (r.start[1] + r.end[1]) / 2 });
          const nn = upNormal(view, r.start, r.end);
          const pos = { sx: mid.sx + nn.nx * NEAR_PX, sy: mid.sy + nn.ny * NEAR_PX };
          // A field longer than its rail on screen, or one that would cover another field, is left
          // out until the user zooms in far enough for it to have room.
          if (!visible(pos, viewport) || r.length * view.scale < MIN_RAIL_PX_FOR_FIELD) return null;
          const box = { ...pos, ...LENGTH_FIELD_BOX };
          if (placed.some((b) => overlaps(b, box))) return null;
          placed.push(box);
          return (
            <Positioned key={r.railId} at={pos} className="length-field" testId={`length-${r.railId}`}>
              <RailLengthField railId={r.railId} railNumber={i + 1} length={r.length} gate={gate} />
              <span aria-hidden>m</span>
            </Positioned>
          );
        })}
    </>
  );
}

interface ModuleLevelProps {
  system: LightSystem;
  catalog: Catalog;
  view: PlanView;
  viewport: Viewport;
  selection: SelectionPath;
  gate: ActionGate;
  onSelect: (s: Selection) => void;
  onOpenOptions: () => void;
}

/** Figures 7–10: plus buttons above rails, distribution options, type switches below modules. */
function ModuleLevelControls(props: ModuleLevelProps) {
  const { t, language } = useI18n();
  return (
    <>
      {railControls(props, t, language)}
      {moduleSwitches(props, t, language)}
    </>
  );
}

type Words = ReturnType<typeof useI18n>['t'];
type Language = ReturnType<typeof useI18n>['language'];

/** Above each rail: its plus button, and the distribution options when the rail (not a module) is selected. */
function railControls({ system, catalog, view, viewport, selection, gate, onSelect }: ModuleLevelProps, t: Words, language: Language): ReactNode[] {
  const out: ReactNode[] = [];
  railPlacements(system, catalog).forEach((r, i) => {
    const rail = system.rails[i];
    const nn = upNormal(view, r.start, r.end);
    const mid = worldToScreen(view, { x: (r.start[0] + r.end[0]) / 2, z: (r.start[1] + r.end[1]) / 2 });
    const plusPos = { sx: mid.sx + nn.nx * NEAR_PX, sy: mid.sy + nn.ny * NEAR_PX };
    // The plus button adds another module like the rail's last one (the catalog's first type on an empty rail).
    const typeId = rail.modules[rail.modules.length - 1]?.type ?? catalog.moduleTypes[0].id;
    const plusType = catalog.moduleTypes.find((m) => m.id === typeId);
    const typeName = plusType ? localName(plusType, language) : typeId;
    if (visible(plusPos, viewport)) {
      out.push(
        <Positioned key={`plus-${rail.id}`} at={plusPos} className="plus-button" testId={`plus-${rail.id}`}>
          <GatedButton gate={gate} action="addModule" params={{ railId: rail.id, type: typeId }} label={t('planner.addModuleToRail', { name: typeName, n: i + 1 })} onRan={() => onSelect({ kind: 'rail', id: rail.id })}>
            +
          </GatedButton>
        </Positioned>,
      );
    }
    const distPos = { sx: mid.sx + nn.nx * FAR_PX, sy: mid.sy + nn.ny * FAR_PX };
    if (selection.railId === rail.id && !selection.moduleId && visible(distPos, viewport)) {
      out.push(
        <Positioned key={`dist-${rail.id}`} at={distPos} className="chip-row" testId={`distribution-${rail.id}`}>
          {/* The pictures read along the rail: its start on the right where the rail runs right to left on screen. */}
          <LazyDistributionButtons
            railId={rail.id}
            current={isFreeRail(rail) ? null : rail.distribution}
            gate={gate}
            compact
            flipped={worldToScreen(view, { x: r.end[0], z: r.end[1] }).sx < worldToScreen(view, { x: r.start[0], z: r.start[1] }).sx - 1}
          />
        </Positioned>,
      );
    }
  });
  return out;
}

/** Below each module: its type switch, which selects it and opens its options. */
function moduleSwitches({ system, catalog, view, viewport, selection, onSelect, onOpenOptions }: ModuleLevelProps, t: Words, language: Language): ReactNode[] {
  const rails = railPlacements(system, catalog);
  const out: ReactNode[] = [];
  for (const m of modulePlacements(system, catalog)) {
    const rail = system.rails.find((r) => r.id === m.railId);
    const module = rail?.modules.find((x) => x.id === m.moduleId);
    const r = rails[system.rails.findIndex((x) => x.id === m.railId)];
    if (!module || !r) continue;
    const nn = upNormal(view, r.start, r.end);
    const c = worldToScreen(view, { x: m.centre[0], z: m.centre[1] });
    const pos = { sx: c.sx - nn.nx * NEAR_PX, sy: c.sy - nn.ny * NEAR_PX };
    if (!visible(pos, viewport)) continue;
    const type = catalog.moduleTypes.find((x) => x.id === module.type);
    const name = type ? localName(type, language) : module.type;
    out.push(
      <Positioned key={`type-${module.id}`} at={pos} className="type-switch" testId={`module-${module.id}`}>
        <ActionButton
          label={t('planner.moduleSettings', { name, cct: String(module.cct) })}
          pressed={selection.moduleId === module.id}
          disabledReason={null}
          onPress={() => {
            onSelect({ kind: 'module', id: module.id });
            onOpenOptions();
          }}
        >
          {typeShortName(name)}
        </ActionButton>
      </Positioned>,
    );
  }
  return out;
}

/**
 * Controls drawn over the plan at positions from worldToScreen, in screen pixels: they keep
 * their size (≥ 44 px targets) while the geometry under them scales. Which controls appear
 * depends on the zoom level, like detail on a map.
 */
export function PlanControls(props: PlanControlsProps) {
  const { config, catalog, view, viewport, level, selection, gate, onSelect, onOpenOptions, drag = null } = props;
  const systems = drawnSystems(config, drag);
  if (level === 'system') {
    const system = systems.find((s) => s.id === selection.systemId);
    return <div className="plan-overlay">{system && <SystemLevelControls key={system.id} system={system} catalog={catalog} view={view} viewport={viewport} gate={gate} />}</div>;
  }
  return (
    <div className="plan-overlay">
      {systems.map((s) => (
        <ModuleLevelControls key={s.id} system={s} catalog={catalog} view={view} viewport={viewport} selection={selection} gate={gate} onSelect={onSelect} onOpenOptions={onOpenOptions} />
      ))}
    </div>
  );
}
