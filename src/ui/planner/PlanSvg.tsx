import { memo, useId, useSyncExternalStore } from 'react';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration, LightSystem } from '../../core/model/configuration/configuration';
import { modulePlacements, rectCorners, systemElementTree, type PlanRect } from '../../core/model/rails/geometry';
import { chainCoordinates, chainPoint, feedCoordinate } from '../../core/model/rails/chainCoordinates';
import { moduleHeight, suspensionPoints } from '../../core/model/rails/suspensionPoints';
import { moduleFootprint, modulePhotometryPath } from './moduleFootprint';
import type { FootprintSource } from './footprintSource';
import { useColourFilterSpectra } from './useColourFilterSpectra';
import { configurationFilterIds } from '../../core/model/modules/moduleFilter';
import { moduleTint } from './moduleTint';
import { modelSymbolPoints } from './modelSymbol';
import { floorTint } from './finishColour';
import { defaultSurfaceFinishes } from '../../core/catalog/surfaceFinishes';
import { gridStep } from './detailLevel';
import type { PlanPoint, PlanView } from './viewTransform';
import { sourceName } from '../../core/model/objects/objectGeometry';
import { objectFillColour } from './objectColour';
import { objectPolygons } from './objectShapes';
import { hitStrip, moduleSymbol } from './planHitTest';
import type { DragPreview } from './dragPreview';
import type { SelectionPath } from './selection';
import { useI18n } from '../i18n/useI18n';
import { LazyRoomShapeDrawing } from './LazyRoomShape';
import { LazyDaylightFactor } from './LazyDaylightFactor';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';

export interface PlanSvgProps {
  config: Configuration;
  catalog: Catalog;
  view: PlanView;
  selection: SelectionPath;
  /** A system or object being dragged is drawn offset by this much (metres) until it is dropped; faded where it may not be dropped. */
  drag: DragPreview | null;
  /** Measured floor footprints per photometric file. */
  footprints: FootprintSource;
  /** Each module's level shown during a light-scene crossfade (scene player; off = 0); absent: the configuration's. */
  levels?: ReadonlyMap<string, number> | null;
  /** The configurator whose daylight-factor overlay is drawn under the plan (issue 30); absent: none. */
  daylightFactorOf?: ConfiguratorStore | null;
}

/** A module's shown level: the fade's, else its own (0 when switched off). */
const shownLevel = (levels: ReadonlyMap<string, number> | null | undefined, m: { id: string; on?: boolean; dimming: number }) => levels?.get(m.id) ?? (m.on === false ? 0 : m.dimming);
/** Module symbols fade with their level (docs/light-scenes.md), never below a quarter so an off module stays visible. */
const levelOpacity = (level: number) => 0.25 + 0.75 * level;

const points = (r: PlanRect) => {
  // rectCorners returns the corners in (−,−), (−,+), (+,−), (+,+) order; reorder to a loop.
  const c = rectCorners(r);
  return [c[0], c[1], c[3], c[2]].map((p) => `${p[0]},${p[1]}`).join(' ');
};

function SystemShape({
  system,
  catalog,
  scale,
  selected,
  selectedRailId,
  selectedModuleId,
  levels,
  outline,
}: {
  system: LightSystem;
  catalog: Catalog;
  scale: number;
  selected: boolean;
  selectedRailId?: string;
  selectedModuleId?: string;
  levels?: ReadonlyMap<string, number> | null;
  /** A catalog `model`'s plan outline, when loaded (footprintSource). */
  outline?: (path: string) => readonly [number, number][] | null | undefined;
}) {
  const { elements, kinds } = systemElementTree(system, catalog);
  const modules = modulePlacements(system, catalog);
  const railIds = system.rails.map((r) => r.id);
  return (
    <g data-system-id={system.id} className="plan-system" style={{ cursor: 'move' }}>
      {elements.map((rects, i) => rects.map((r, k) => <polygon key={`hit-${i}-${k}`} points={points(hitStrip(r, scale))} data-rail-id={railIds[kinds[i].rail]} fill="transparent" />))}
      {elements.map((rects, i) => {
        // A rail, or the connector node at a rail's end (a T or X: its incoming arm and one arm per branch); a node selects the rail it ends.
        const isRail = kinds[i].kind === 'rail';
        const railId = railIds[kinds[i].rail];
        return rects.map((r, k) => (
          <polygon
            key={`${i}-${k}`}
            points={points(r)}
            data-rail-id={railId}
            data-connector-of={isRail ? undefined : railId}
            fill={isRail ? (railId === selectedRailId ? '#3b7be0' : '#1f5fbf') : railId === selectedRailId ? '#9ca3af' : '#6b7280'}
            stroke={selected ? '#c0392b' : '#0f2f5f'}
            strokeWidth={selected ? 3 : 1}
            vectorEffect="non-scaling-stroke"
          />
        ));
      })}
      {modules.map((m) => {
        const module = system.rails.flatMap((r) => r.modules).find((x) => x.id === m.moduleId);
        const rect = moduleSymbol(m.footprint);
        // A type with an L3D body: its outline from above (docs/gldf.md "L3D in the plan"); the rectangle until it loads.
        const model = module ? catalog.moduleTypes.find((t) => t.id === module.type)?.model : undefined;
        const hull = model ? outline?.(model) : undefined;
        return (
          <polygon
            key={m.moduleId}
            points={
              hull && hull.length >= 3
                ? modelSymbolPoints(hull, m.centre, m.heading)
                    .map((p) => `${p[0]},${p[1]}`)
                    .join(' ')
                : points(rect)
            }
            data-module-id={m.moduleId}
            data-module-outline={hull && hull.length >= 3 ? 'model' : undefined}
            data-level={module ? shownLevel(levels, module).toFixed(3) : undefined}
            fill={module ? moduleTint(module) : '#fff'}
            fillOpacity={module ? levelOpacity(shownLevel(levels, module)) : 1}
            stroke={m.moduleId === selectedModuleId ? '#c0392b' : '#1d2330'}
            strokeWidth={m.moduleId === selectedModuleId ? 3 : 1}
            vectorEffect="non-scaling-stroke"
          />
        );
      })}
      <FixingsAndFeeds system={system} catalog={catalog} scale={scale} />
    </g>
  );
}

/**
 * The derived ceiling fixings (suspension points, or surface clips as hollow dots) as small dots
 * 3 px in radius, and each power feed as a 5 px square marked with its number, on the rail line.
 */
function FixingsAndFeeds({ system, catalog, scale }: { system: LightSystem; catalog: Catalog; scale: number }) {
  const r = 3 / scale;
  const surface = system.mounting === 'surface';
  const chain = chainCoordinates(system, catalog);
  return (
    <g pointerEvents="none">
      {suspensionPoints(system, catalog).map((p, i) => (
        <circle key={`fix-${i}`} cx={p.plan[0]} cy={p.plan[1]} r={r} fill={surface ? '#ffffff' : '#1d2330'} stroke="#1d2330" strokeWidth={1} vectorEffect="non-scaling-stroke" data-fixing={surface ? 'clip' : 'suspension'} />
      ))}
      {system.feeds.map((f, i) => {
        const [x, z] = chainPoint(system, catalog, feedCoordinate(f.at, chain));
        const h = 5 / scale;
        return (
          <g key={f.id} data-feed-id={f.id}>
            <rect x={x - h} y={z - h} width={2 * h} height={2 * h} fill="#f2c200" stroke="#1d2330" strokeWidth={1} vectorEffect="non-scaling-stroke" />
            <text x={x} y={z + h * 0.55} fontSize={h * 1.5} textAnchor="middle" fill="#1d2330">
              {i + 1}
            </text>
          </g>
        );
      })}
    </g>
  );
}

/** SVG path data for outline polygons (holes come out by the even-odd rule). */
function outlinePath(polygons: readonly (readonly PlanPoint[])[]): string {
  return polygons.map((poly) => `M${poly.map((p) => `${p.x},${p.z}`).join('L')}Z`).join('');
}

/**
 * Furniture and imported models: each object's real outline seen from above, filled with its
 * main finish at low opacity, drawn under the footprints and rails (the lights hang from the
 * ceiling). Memoised on the configuration: a drag only moves the dragged object's group.
 */
const ObjectShapes = memo(function ObjectShapes({ config, selectedId, drag }: { config: Configuration; selectedId?: string; drag: DragPreview | null }) {
  return (
    <g data-testid="plan-objects">
      {config.objects.map((o) => {
        const dragged = drag && 'objectId' in drag && drag.objectId === o.id ? drag : null;
        const selected = o.id === selectedId;
        const fill = objectFillColour(config, o.id);
        return (
          <g
            key={o.id}
            data-object-id={o.id}
            transform={dragged ? `translate(${dragged.delta.x} ${dragged.delta.z})` : undefined}
            opacity={dragged?.invalid ? 0.4 : 1}
            data-drop-refused={dragged?.invalid || undefined}
            data-selected={selected || undefined}
          >
            <title>{sourceName(config, o.source)}</title>
            <path
              d={outlinePath(objectPolygons(config, o.id))}
              fillRule="evenodd"
              fill={fill}
              fillOpacity={selected ? 0.55 : 0.35}
              stroke={selected ? '#c0392b' : '#4a5160'}
              strokeWidth={selected ? 2.5 : 1}
              vectorEffect="non-scaling-stroke"
            />
          </g>
        );
      })}
    </g>
  );
});

/** A system dragged as a whole: its offset, and whether it may be dropped there. */
type SystemDrag = Extract<DragPreview, { systemId: string }> | null;
/** A module or fixing point dragged: its system as the drag would leave it. */
type MovedSystem = Extract<DragPreview, { preview: LightSystem }> | null;
type Levels = ReadonlyMap<string, number> | null | undefined;

/** Each module's floor footprint (measured polygon or ellipse), tinted with its light and faded with its level, clipped to the room. */
function footprintLayer(systems: readonly LightSystem[], systemDrag: SystemDrag, catalog: Catalog, levels: Levels, config: Configuration, footprints: FootprintSource, clipId: string) {
  return (
    <g clipPath={`url(#${clipId})`} pointerEvents="none">
      {systems.map((s) => {
        const d = systemDrag?.systemId === s.id ? systemDrag.delta : { x: 0, z: 0 };
        // Where the modules really are: the suspension, or the surface mount's drop below the ceiling.
        const h = moduleHeight(s, { height: config.room.height }, catalog);
        return (
          <g key={s.id} transform={`translate(${d.x} ${d.z})`}>
            {modulePlacements(s, catalog).map((m) => {
              const module = s.rails.flatMap((r) => r.modules).find((x) => x.id === m.moduleId);
              if (!module) return null;
              const path = modulePhotometryPath(module, catalog);
              const f = moduleFootprint(m, module, catalog, h, path ? footprints.get(path) : null, config.room);
              if (!f) return null;
              const paint = {
                fill: moduleTint(module),
                fillOpacity: 0.2 * shownLevel(levels, module),
                stroke: '#c98a1c',
                strokeOpacity: 0.7,
                strokeWidth: 1,
                vectorEffect: 'non-scaling-stroke' as const,
                'data-footprint-for': m.moduleId,
              };
              if (f.kind === 'polygon') return <polygon key={m.moduleId} points={f.points.map((p) => `${p.x},${p.z}`).join(' ')} {...paint} />;
              const e = f.ellipse;
              return <ellipse key={m.moduleId} cx={e.center.x} cy={e.center.z} rx={Math.max(e.rx, 1e-3)} ry={Math.max(e.ry, 1e-3)} transform={`rotate(${e.rotationDeg} ${e.center.x} ${e.center.z})`} {...paint} />;
            })}
          </g>
        );
      })}
    </g>
  );
}

/** The systems' rails, connectors, module symbols, fixings and feeds, each system offset by its drag and faded where it may not be dropped. */
function systemLayer(systems: readonly LightSystem[], systemDrag: SystemDrag, catalog: Catalog, levels: Levels, moved: MovedSystem, view: PlanView, selection: SelectionPath, footprints: FootprintSource) {
  return systems.map((s) => {
    const d = systemDrag?.systemId === s.id ? systemDrag.delta : { x: 0, z: 0 };
    const refused = systemDrag?.systemId === s.id && systemDrag.invalid;
    const moduleRefused = moved?.preview.id === s.id && moved.invalid;
    const own = selection.systemId === s.id;
    return (
      <g key={s.id} transform={`translate(${d.x} ${d.z})`} opacity={refused ? 0.4 : 1} data-drop-refused={refused || undefined} data-module-drag-refused={moduleRefused || undefined}>
        <SystemShape system={s} catalog={catalog} scale={view.scale} selected={own} selectedRailId={own ? selection.railId : undefined} selectedModuleId={own ? selection.moduleId : undefined} levels={levels} outline={footprints.outline} />
      </g>
    );
  });
}

/**
 * The room drawn from above as SVG (plan x = world x, plan y = world z). Geometry is drawn in
 * metres inside one group whose transform is the view, with non-scaling strokes, so lines keep
 * their on-screen width at every zoom; the constant-size controls live in PlanControls. It
 * only draws: what a pointer hits is found from the same shapes by planHitTest, and input goes
 * to the PlannerController. Its objects, footprints and systems are drawn by ObjectShapes, footprintLayer and systemLayer.
 */
export const PlanSvg = memo(function PlanSvg({ config, catalog, view, selection, drag, footprints, levels, daylightFactorOf }: PlanSvgProps) {
  const clipId = useId();
  const { t } = useI18n();
  // Re-render when a photometric file arrives.
  useSyncExternalStore(footprints.subscribe, footprints.version);
  // ... and when the colour-filter spectra do: filtered modules are tinted with their light's colour.
  useColourFilterSpectra(configurationFilterIds(config).length > 0);
  // Every optic in use has its measured footprint (or failed to load): tests wait for this.
  const footprintsReady = config.systems.every((s) =>
    s.rails.every((r) =>
      r.modules.every((m) => {
        const p = modulePhotometryPath(m, catalog);
        return p === null || footprints.get(p) !== undefined;
      }),
    ),
  );
  const systemDrag = drag && 'systemId' in drag ? drag : null;
  // A module dragged along its rail: its system is drawn as it would be with the module there.
  // A dragged module or fixing point: its system drawn as the drag would leave it.
  const moved = drag && 'preview' in drag ? drag : null;
  const systems = moved ? config.systems.map((s) => (s.id === moved.preview.id ? moved.preview : s)) : config.systems;
  const { width, depth, height, shape } = config.room;
  // A drawn room (issue 29): its outline is the floor and the clip; absent, the box.
  const floorShape = shape ? <path d={`M${shape.outline.join('L')}Z`} /> : <rect x={0} y={0} width={width} height={depth} />;
  const step = gridStep(view.scale);
  const gridLines: { x1: number; z1: number; x2: number; z2: number; major: boolean }[] = [];
  for (let i = 1; i * step < width - 1e-9; i++) gridLines.push({ x1: i * step, z1: 0, x2: i * step, z2: depth, major: Math.abs(i * step - Math.round(i * step)) < 1e-9 });
  for (let i = 1; i * step < depth - 1e-9; i++) gridLines.push({ x1: 0, z1: i * step, x2: width, z2: i * step, major: Math.abs(i * step - Math.round(i * step)) < 1e-9 });

  return (
    <svg
      className="plan-svg"
      role="img"
      aria-label={t('planner.planLabel', { width, depth, systems: t('planner.systemCount', { count: config.systems.length }), objects: t('planner.objectCount', { count: config.objects.length }) })}
      data-testid="plan-svg"
      data-footprints={footprintsReady ? 'ready' : 'loading'}
    >
      <defs>
        <clipPath id={clipId}>{floorShape}</clipPath>
      </defs>
      <g transform={`matrix(${view.scale} 0 0 ${view.scale} ${view.offsetX} ${view.offsetY})`}>
        <g fill={floorTint(config.room.reflectance.floor, defaultSurfaceFinishes)} data-testid="plan-floor">
          {floorShape}
        </g>
        <g clipPath={shape && `url(#${clipId})`}>
          {gridLines.map((l, i) => (
            <line key={i} x1={l.x1} y1={l.z1} x2={l.x2} y2={l.z2} stroke={l.major ? '#d3d8e0' : '#eceff3'} strokeWidth={1} vectorEffect="non-scaling-stroke" />
          ))}
        </g>
        {daylightFactorOf && <LazyDaylightFactor part="layer" store={daylightFactorOf} />}
        <ObjectShapes config={config} selectedId={selection.objectId} drag={drag} />
        {footprintLayer(systems, systemDrag, catalog, levels, config, footprints, clipId)}
        {shape ? (
          <LazyRoomShapeDrawing shape={shape} height={height} clipId={clipId} hatchId={`${clipId}h`} />
        ) : (
          <rect x={0} y={0} width={width} height={depth} fill="none" stroke="#1d2330" strokeWidth={3} vectorEffect="non-scaling-stroke" />
        )}
        {systemLayer(systems, systemDrag, catalog, levels, moved, view, selection, footprints)}
      </g>
    </svg>
  );
});
