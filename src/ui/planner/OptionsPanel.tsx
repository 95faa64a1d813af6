import { useSyncExternalStore } from 'react';
import type { Catalog } from '../../core/model/catalogSchema';
import type { Configuration } from '../../core/model/configuration';
import { ActionButton } from './ActionButton';
import { CommitField } from './CommitField';
import { DistributionButtons } from './DistributionButtons';
import type { FootprintSource } from './footprintSource';
import { modulePhotometryPath } from './moduleFootprint';
import { PhotometryWarnings } from '../shared/PhotometryWarnings';
import { RailLengthField } from './RailLengthField';
import type { ActionGate } from './actionGate';
import type { SelectionPath } from './selection';

export interface OptionsPanelProps {
  config: Configuration;
  catalog: Catalog;
  path: SelectionPath;
  gate: ActionGate;
  onClose: () => void;
  /** The plan's photometry loader: a selected module's file warnings are shown from it. */
  footprints?: FootprintSource;
}

/** Dimming levels offered as touch-sized choices (the 3D view relights instantly on a change). */
export const DIMMING_STEPS = [0.25, 0.5, 0.75, 1] as const;

function Chips({ title, children }: { title: string; children: React.ReactNode }) {
  return (
    <div className="field" role="group" aria-label={title}>
      <h3>{title}</h3>
      <div className="chip-row" style={{ flexWrap: 'wrap' }}>
        {children}
      </div>
    </div>
  );
}

/** The warnings of a module's photometric file, once the plan has loaded it (re-renders when it arrives). */
function ModulePhotometryNote({ source, path }: { source: FootprintSource; path: string }) {
  useSyncExternalStore(source.subscribe, source.version, source.version);
  return <PhotometryWarnings notes={[{ file: path, warnings: source.warnings(path) }]} testId="module-photometry-warnings" />;
}

/**
 * Settings of the selected part (configurator paper, fig. 10, 11): module type, beam and colour
 * temperature; rail length, distribution and modules; system suspension, rotation and rails;
 * with nothing selected, the room. Every choice is an ActionButton gated by the model.
 */
export function OptionsPanel({ config, catalog, path, gate, onClose, footprints }: OptionsPanelProps) {
  const system = config.systems.find((s) => s.id === path.systemId);
  const rail = system?.rails.find((r) => r.id === path.railId);
  const railIndex = system && rail ? system.rails.indexOf(rail) : -1;
  const module = rail?.modules.find((m) => m.id === path.moduleId);

  let body: React.ReactNode;
  let title: string;
  if (module) {
    const type = catalog.moduleTypes.find((t) => t.id === module.type);
    title = `Module: ${type?.name ?? module.type}`;
    const photometryPath = modulePhotometryPath(module, catalog);
    body = (
      <>
        <Chips title="Module type">
          {catalog.moduleTypes.map((t) => (
            <ActionButton
              key={t.id}
              label={t.name}
              pressed={t.id === module.type}
              disabledReason={t.id === module.type ? null : gate.reason('setModuleType', { moduleId: module.id, type: t.id })}
              onPress={() => t.id !== module.type && gate.run('setModuleType', { moduleId: module.id, type: t.id })}
              onDisabledPress={gate.explain}
              testId={`type-${t.id}`}
            />
          ))}
        </Chips>
        {type && type.beams.length > 0 && (
          <Chips title="Beam">
            {type.beams.map((b) => (
              <ActionButton
                key={b.id}
                label={b.label}
                pressed={b.id === module.beam}
                disabledReason={b.id === module.beam ? null : gate.reason('setModuleBeam', { moduleId: module.id, beam: b.id })}
                onPress={() => b.id !== module.beam && gate.run('setModuleBeam', { moduleId: module.id, beam: b.id })}
                onDisabledPress={gate.explain}
                testId={`beam-${b.id}`}
              />
            ))}
          </Chips>
        )}
        {footprints && photometryPath && <ModulePhotometryNote source={footprints} path={photometryPath} />}
        {type && (
          <Chips title="Colour temperature">
            {type.ccts.map((k) => (
              <ActionButton
                key={k}
                label={`${k} K`}
                pressed={k === module.cct}
                disabledReason={k === module.cct ? null : gate.reason('setModuleCct', { moduleId: module.id, cct: k })}
                onPress={() => k !== module.cct && gate.run('setModuleCct', { moduleId: module.id, cct: k })}
                onDisabledPress={gate.explain}
                testId={`cct-${k}`}
              />
            ))}
          </Chips>
        )}
        <Chips title="Dimming">
          {DIMMING_STEPS.map((d) => (
            <ActionButton
              key={d}
              label={`${Math.round(d * 100)} %`}
              pressed={Math.abs(module.dimming - d) < 1e-9}
              disabledReason={gate.reason('setModuleDimming', { moduleId: module.id, dimming: d })}
              onPress={() => Math.abs(module.dimming - d) >= 1e-9 && gate.run('setModuleDimming', { moduleId: module.id, dimming: d })}
              onDisabledPress={gate.explain}
              testId={`dimming-${Math.round(d * 100)}`}
            />
          ))}
        </Chips>
        <ActionButton
          label="Remove module"
          disabledReason={gate.reason('removeModule', { moduleId: module.id })}
          onPress={() => gate.run('removeModule', { moduleId: module.id })}
          onDisabledPress={gate.explain}
        />
      </>
    );
  } else if (rail && system) {
    title = `Rail ${railIndex + 1}`;
    const last = railIndex === system.rails.length - 1;
    body = (
      <>
        <div className="field">
          <h3>Length (m)</h3>
          <RailLengthField railId={rail.id} railNumber={railIndex + 1} length={rail.length} gate={gate} />
          <span className="empty-note">
            {catalog.rail.minLength}–{catalog.rail.maxLength} m in steps of {catalog.rail.step} m
          </span>
        </div>
        <Chips title="Module distribution">
          <DistributionButtons railId={rail.id} current={rail.distribution} gate={gate} />
        </Chips>
        <Chips title="Add a module">
          {catalog.moduleTypes.map((t) => (
            <ActionButton
              key={t.id}
              label={`Add ${t.name}`}
              disabledReason={gate.reason('addModule', { railId: rail.id, type: t.id })}
              onPress={() => gate.run('addModule', { railId: rail.id, type: t.id })}
              onDisabledPress={gate.explain}
            >
              + {t.name}
            </ActionButton>
          ))}
        </Chips>
        {last && system.rails.length > 1 && (
          <ActionButton
            label="Remove this rail"
            disabledReason={gate.reason('removeRail', { railId: rail.id })}
            onPress={() => gate.run('removeRail', { railId: rail.id })}
            onDisabledPress={gate.explain}
          />
        )}
      </>
    );
  } else if (system) {
    title = 'Lighting system';
    const turns = catalog.connectors.flatMap((c) => (c.angle === 0 ? [{ c, turn: 0, label: `Add rail straight (${c.name})` }] : [
      { c, turn: c.angle, label: `Add rail turning left ${c.angle}°` },
      { c, turn: -c.angle, label: `Add rail turning right ${c.angle}°` },
    ]));
    body = (
      <>
        <div className="field">
          <h3>Suspension: ceiling to light (m)</h3>
          <CommitField
            label="Suspension (m)"
            value={system.suspension}
            onCommit={(suspension) => {
              const r = gate.reason('setSuspension', { systemId: system.id, suspension });
              if (!r) gate.run('setSuspension', { systemId: system.id, suspension });
              return r;
            }}
            onRefused={gate.explain}
          />
          <span className="empty-note">
            {catalog.suspension.min}–{catalog.suspension.max} m; lights stay {catalog.suspension.minHeightAboveFloor} m above the floor
          </span>
        </div>
        <Chips title="Rotate">
          {[-90, -15, 15, 90].map((by) => (
            <ActionButton
              key={by}
              label={`Rotate ${by > 0 ? 'left' : 'right'} ${Math.abs(by)}°`}
              disabledReason={gate.reason('rotateSystem', { systemId: system.id, by })}
              onPress={() => gate.run('rotateSystem', { systemId: system.id, by })}
              onDisabledPress={gate.explain}
            >
              {by > 0 ? '⟲' : '⟳'} {Math.abs(by)}°
            </ActionButton>
          ))}
        </Chips>
        <Chips title="Extend the chain">
          {turns.map(({ c, turn, label }) => (
            <ActionButton
              key={`${c.id}${turn}`}
              label={label}
              disabledReason={gate.reason('addRail', { systemId: system.id, connector: c.id, turn })}
              onPress={() => gate.run('addRail', { systemId: system.id, connector: c.id, turn })}
              onDisabledPress={gate.explain}
            >
              {turn === 0 ? '→' : turn > 0 ? '↰' : '↱'} rail
            </ActionButton>
          ))}
        </Chips>
        <ActionButton
          label="Delete system"
          disabledReason={gate.reason('deleteSystem', { systemId: system.id })}
          onPress={() => gate.run('deleteSystem', { systemId: system.id })}
          onDisabledPress={gate.explain}
        />
      </>
    );
  } else {
    title = 'Room';
    const { width, depth, height } = config.room;
    const setRoom = (p: { width: number; depth: number; height: number }) => {
      const r = gate.reason('setRoom', p);
      if (!r) gate.run('setRoom', p);
      return r;
    };
    body = (
      <div className="setup-fields">
        <div className="field">
          <h3>Width (m)</h3>
          <CommitField label="Room width (m)" value={width} onCommit={(w) => setRoom({ width: w, depth, height })} onRefused={gate.explain} />
        </div>
        <div className="field">
          <h3>Depth (m)</h3>
          <CommitField label="Room depth (m)" value={depth} onCommit={(d) => setRoom({ width, depth: d, height })} onRefused={gate.explain} />
        </div>
        <div className="field">
          <h3>Height (m)</h3>
          <CommitField label="Room height (m)" value={height} onCommit={(h) => setRoom({ width, depth, height: h })} onRefused={gate.explain} />
        </div>
      </div>
    );
  }

  return (
    <section className="panel-section options-panel" aria-label="Options" data-testid="options-panel">
      <div style={{ display: 'flex', alignItems: 'center', gap: 8 }}>
        <h2 style={{ flex: 1, margin: 0 }}>{title}</h2>
        <button type="button" className="btn" onClick={onClose} aria-label="Close options">
          ✕
        </button>
      </div>
      {body}
    </section>
  );
}
