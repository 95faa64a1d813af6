import { memo } from 'react';
import { FURNISHED_PRESETS } from '../../core/catalog/furnishedPresets';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { PresetSpec } from '../../core/model/catalogSchema/presetSchema';
import { createConfiguration, type Configuration } from '../../core/model/configuration/configuration';
import { rectCorners, systemBounds, systemElements } from '../../core/model/rails/geometry';
import { instantiatePreset } from '../../core/model/actions/presets';
import { ActionButton } from './ActionButton';
import type { ActionGate } from './actionGate';
import { useI18n } from '../i18n/useI18n';
import { localDescription, localName } from '../i18n/localName';
import { roomName } from '../i18n/catalogNames';

/** A small drawing of a preset's rails, computed from the model's own geometry (not an image). */
export const PresetThumbnail = memo(function PresetThumbnail({ preset, catalog }: { preset: PresetSpec; catalog: Catalog }) {
  const config = instantiatePreset(createConfiguration(), preset, catalog, { x: 0, z: 0, rotation: 0 }, catalog.suspension.default);
  const system = config.systems[0];
  const b = systemBounds(system, catalog);
  const size = Math.max(b.maxX - b.minX, b.maxZ - b.minZ, 0.5);
  const pad = size * 0.08;
  const polys = systemElements(system, catalog)
    .flat()
    .map((r) => {
      const c = rectCorners({ ...r, halfWidth: Math.max(r.halfWidth, size * 0.025) });
      return [c[0], c[1], c[3], c[2]].map((p) => `${p[0]},${p[1]}`).join(' ');
    });
  return (
    <svg width={48} height={48} viewBox={`${b.minX - pad} ${b.minZ - pad} ${size + 2 * pad} ${size + 2 * pad}`} aria-hidden>
      {polys.map((p, i) => (
        <polygon key={i} points={p} fill="#1f5fbf" />
      ))}
    </svg>
  );
});

export interface PresetPanelProps {
  catalog: Catalog;
  gate: ActionGate;
  /** Runs after a preset was placed (the app selects the new system). */
  onPlaced: () => void;
  /** Opens a furnished room in place of the current configuration (undoable); without it the furnished rooms are not listed. */
  onLoadRoom?: (config: Configuration) => void;
}

/** The configurator paper's right-hand bar: presets placed into the room at a free spot the model finds. */
export function PresetPanel({ catalog, gate, onPlaced, onLoadRoom }: PresetPanelProps) {
  const { t, language } = useI18n();
  return (
    <section className="panel-section" aria-labelledby="presets-title">
      <h2 id="presets-title">{t('planner.presets')}</h2>
      <ul className="preset-list">
        {catalog.presets.map((p) => (
          <li key={p.id}>
            <ActionButton
              label={t('planner.placePreset', { name: localName(p, language) })}
              disabledReason={gate.reason('placePreset', { presetId: p.id })}
              onPress={() => {
                gate.run('placePreset', { presetId: p.id });
                onPlaced();
              }}
              onDisabledPress={gate.explain}
              testId={`preset-${p.id}`}
            >
              <PresetThumbnail preset={p} catalog={catalog} />
              <span>
                <span className="preset-name">{localName(p, language)}</span>
                <span className="preset-detail">{localDescription(p, language)}</span>
              </span>
            </ActionButton>
          </li>
        ))}
      </ul>
      {onLoadRoom && (
        <>
          <h3 id="rooms-title">{t('planner.furnishedRooms')}</h3>
          <ul className="preset-list" aria-labelledby="rooms-title">
            {FURNISHED_PRESETS.map((room) => (
              <li key={room.id}>
                <ActionButton
                  label={t('planner.openFurnishedRoom', { name: roomName(t, room) })}
                  disabledReason={null}
                  onPress={() => {
                    // Built from this catalog's presets through the model's actions; a catalog without them cannot build it.
                    let config: Configuration;
                    try {
                      config = room.build(catalog);
                    } catch (e) {
                      gate.explain(t('planner.furnishedRoomUnbuildable', { name: roomName(t, room), problem: (e as Error).message }));
                      return;
                    }
                    onLoadRoom(config);
                  }}
                  onDisabledPress={gate.explain}
                  testId={`room-${room.id}`}
                >
                  <span>
                    <span className="preset-name">{roomName(t, room)}</span>
                    <span className="preset-detail">{t('planner.furnishedRoomDetail')}</span>
                  </span>
                </ActionButton>
              </li>
            ))}
          </ul>
        </>
      )}
    </section>
  );
}
