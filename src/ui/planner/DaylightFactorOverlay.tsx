import './registerDaylightPlanEnglish';
import './daylightFactorOverlay.css';
import { useEffect, useLayoutEffect, useMemo, useRef, useSyncExternalStore } from 'react';
import { DAYLIGHT_FACTOR_SKY_ILLUMINANCE, daylightFactorLuxLevels } from '../../core/daylight/daylightFactor';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';
import type { DaylightFactorValues } from '../viewer/useDaylightFactorView';
import { LuxLegend } from '../viewer/LuxLegend';
import { daylightFactorImage, type DaylightFactorGrid } from './daylightFactorGrid';
import { daylightFactorOverlayOf } from './daylightFactorOverlay';

function useOverlay(store: ConfiguratorStore) {
  const overlay = daylightFactorOverlayOf(store);
  const snapshot = useSyncExternalStore(overlay.subscribe, overlay.snapshot);
  return { overlay, snapshot };
}

/** The grid as a PNG data URL, one pixel a point (drawn scaled up with crisp pixels: each is a 0.25 m cell of the plane). */
function gridPicture(grid: DaylightFactorGrid) {
  const image = daylightFactorImage(grid);
  const canvas = document.createElement('canvas');
  canvas.width = image.columns;
  canvas.height = image.rows;
  const context = canvas.getContext('2d');
  if (!context) return null;
  context.putImageData(new ImageData(image.rgba, image.columns, image.rows), 0, 0);
  const half = grid.spacing / 2;
  return { href: canvas.toDataURL('image/png'), x: image.x0 - half, y: image.z0 - half, width: image.columns * grid.spacing, height: image.rows * grid.spacing };
}

/**
 * The false-colour layer inside the plan's SVG (metres, under the room outline, windows, rails and
 * modules): the work plane's DF at each grid point in the 3D view's daylight-factor colours; faded
 * while a new grid is being computed.
 */
export function DaylightFactorLayer({ store }: { store: ConfiguratorStore }) {
  const { snapshot } = useOverlay(store);
  const grid = snapshot.on ? snapshot.grid : null;
  const picture = useMemo(() => (grid ? gridPicture(grid) : null), [grid]);
  if (!picture) return null;
  return (
    <image
      href={picture.href}
      x={picture.x}
      y={picture.y}
      width={picture.width}
      height={picture.height}
      preserveAspectRatio="none"
      opacity={snapshot.phase === 'ready' ? 1 : 0.4}
      className="df-plan-layer"
      pointerEvents="none"
      data-testid="df-plan-layer"
      data-x={picture.x}
      data-y={picture.y}
      data-width={picture.width}
      data-height={picture.height}
    />
  );
}

/** The figures: mean, lowest, U₀ and EN 17037's share at DF ≥ 2 % (the 3D view's table's rows and words, two a line so the card stays small on a phone). */
const FIGURES: { key: 'mean' | 'min' | 'u0' | 'shareAbove2'; messageKey: MessageKey }[] = [
  { key: 'mean', messageKey: 'view3d.statsAverage' },
  { key: 'min', messageKey: 'view3d.statsMin' },
  { key: 'u0', messageKey: 'view3d.statsUniformity' },
  { key: 'shareAbove2', messageKey: 'view3d.dfShareAbove2' },
];

function DaylightFactorFigures({ values }: { values: DaylightFactorValues | null }) {
  const { t, format } = useI18n();
  const value = (key: (typeof FIGURES)[number]['key']) => {
    if (!values) return '–';
    if (key === 'shareAbove2') return format.number(100 * values.shareAbove2, { maximumFractionDigits: 0 }) + ' %';
    return format.number(values[key], { minimumFractionDigits: 2, maximumFractionDigits: 2 });
  };
  return (
    <figure className="df-plan-figures" data-testid="df-stats">
      <figcaption>{t('view3d.dfCaption')}</figcaption>
      <dl>
        {FIGURES.map((f) => (
          <div key={f.key}>
            {/* A number and its unit stay on one line ("300 lx", "2 %") when a label wraps on a phone. */}
            <dt>{t(f.messageKey).replace(/(\d) (lx|%)/g, '$1\u00a0$2')}</dt>
            <dd data-testid={`df-${f.key}`}>{value(f.key)}</dd>
          </div>
        ))}
      </dl>
    </figure>
  );
}

/**
 * Tells the planner how much of the plan's top the open card covers, so the room is fitted below
 * it (as under the room-shape editor's bar); nothing while hidden (the editor's insets apply then).
 */
function useCardInsets(on: boolean, hidden: boolean, onInsets?: (top: number, bottom: number) => void) {
  const rootRef = useRef<HTMLDivElement>(null);
  useLayoutEffect(() => {
    const root = rootRef.current;
    if (!root || hidden || !on || !onInsets) return;
    const measure = () => onInsets(root.offsetTop + root.offsetHeight, 0);
    measure();
    const ro = new ResizeObserver(measure);
    ro.observe(root);
    return () => {
      ro.disconnect();
      onInsets(0, 0);
    };
  }, [on, hidden, onInsets]);
  return rootRef;
}

/**
 * The overlay's controls on the plan: the toggle and, when on, the legend in % (the 3D view's
 * LuxLegend at DAYLIGHT_FACTOR_LEVELS), the figures (the report's function, as the 3D view's
 * table) and what is being done. Mounted while the plan is shown: the overlay asks the bake
 * service for the daylight factor only then.
 */
export function DaylightFactorControls({ store, hidden = false, onInsets }: { store: ConfiguratorStore; hidden?: boolean; onInsets?: (top: number, bottom: number) => void }) {
  const { t } = useI18n();
  const { overlay, snapshot } = useOverlay(store);
  useEffect(() => overlay.attach(), [overlay]);
  const { on, phase, grid } = snapshot;
  const rootRef = useCardInsets(on, hidden, onInsets);
  const note = phase === 'computing' ? t('daylightPlan.computing') : phase === 'no-sky' ? t('daylightPlan.noSky') : phase === 'unavailable' ? t('daylightPlan.unavailable') : null;
  return (
    <div className="df-plan" ref={rootRef} data-plan-control data-testid="df-plan" data-phase={phase} hidden={hidden}>
      <button type="button" className="action-button df-plan-toggle" aria-pressed={on} title={t('daylightPlan.hint')} onClick={() => overlay.setOn(!on)} data-testid="df-plan-toggle">
        {t('daylightPlan.toggle')}
      </button>
      {on && (
        <div className="df-plan-card" data-testid="df-plan-card">
          <p className="df-plan-note" role="status" data-testid="df-plan-note">
            {note}
          </p>
          <LuxLegend levels={daylightFactorLuxLevels()} percentOf={DAYLIGHT_FACTOR_SKY_ILLUMINANCE} />
          {phase !== 'no-sky' && phase !== 'unavailable' && <DaylightFactorFigures values={grid?.statistics ?? null} />}
          <p className="df-plan-band">{t('daylightPlan.band')}</p>
        </div>
      )}
    </div>
  );
}

/** Which part the plan draws where (LazyDaylightFactor.tsx): one lazy component for both keeps the first screen small. */
export type DaylightFactorPartProps = { store: ConfiguratorStore } & ({ part: 'layer' } | { part: 'controls'; hidden: boolean; onInsets: (top: number, bottom: number) => void });

export default function DaylightFactorPart(props: DaylightFactorPartProps) {
  return props.part === 'layer' ? <DaylightFactorLayer store={props.store} /> : <DaylightFactorControls store={props.store} hidden={props.hidden} onInsets={props.onInsets} />;
}
