import './registerGuidanceEnglish';
import { useMemo } from 'react';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Room } from '../../core/model/configuration/configuration';
import { suggestedPresets } from '../../core/model/guidance/suggestedPresets';
import { ActionButton } from './ActionButton';
import type { ActionGate } from './actionGate';
import { PresetThumbnail } from './PresetPanel';
import { useI18n } from '../i18n/useI18n';
import { localName } from '../i18n/localName';
import type { UiStore } from '../../core/store/uiStore';

/** What the shop chose for the first run (docs/embedding.md, `firstRun`): its own preset ids, none (false), or the best for the room (undefined). */
export interface FirstRunOptions {
  presets?: readonly string[] | false;
}

export interface FirstRunHintProps {
  room: Pick<Room, 'width' | 'depth' | 'height'>;
  catalog: Catalog;
  gate: ActionGate;
  options?: FirstRunOptions;
  /** After a suggestion was placed (the planner selects it). */
  onPlaced: () => void;
  /** "All layouts" opens the side panel's full preset list (the drawer on a phone). */
  ui: UiStore;
}

/**
 * The empty plan's first step (issue 27, docs/planner.md "First run"): one sentence, the two or
 * three presets that fit this room best (core suggestedPresets), each placed with one tap, and the
 * way to all presets. Shown on the plan while it holds no system.
 */
export function FirstRunHint({ room, catalog, gate, options, onPlaced, ui }: FirstRunHintProps) {
  const { t, language } = useI18n();
  const only = options?.presets;
  // A shop's list is compared by its content: a new array with the same ids is the same choice.
  const key = only === false ? false : only === undefined ? undefined : only.join('\n');
  const { width, depth, height } = room;
  const suggestions = useMemo(() => (key === false ? [] : suggestedPresets({ width, depth, height }, catalog, 3, key === undefined ? undefined : key.split('\n'))), [width, depth, height, catalog, key]);
  return (
    // The area below the zoom buttons, the card centred in it (app.css).
    <div className="first-run-area">
      <div className="first-run" data-plan-control data-testid="first-run" role="group" aria-labelledby="first-run-title">
        <p id="first-run-title" className="first-run-title">
          {t('guidance.firstRunTitle')}
        </p>
        <p className="first-run-hint">{t('guidance.firstRunHint')}</p>
        {suggestions.length > 0 && (
          <ul className="first-run-list">
            {suggestions.map(({ presetId }) => {
              const preset = catalog.presets.find((p) => p.id === presetId)!;
              const name = localName(preset, language);
              return (
                <li key={presetId}>
                  <ActionButton
                    label={t('guidance.firstRunPlace', { name })}
                    disabledReason={gate.reason('placePreset', { presetId })}
                    onPress={() => {
                      gate.run('placePreset', { presetId });
                      onPlaced();
                    }}
                    onDisabledPress={gate.explain}
                    testId={`first-run-${presetId}`}
                  >
                    <PresetThumbnail preset={preset} catalog={catalog} />
                    <span className="preset-name">{name}</span>
                  </ActionButton>
                </li>
              );
            })}
          </ul>
        )}
        <button
          type="button"
          className="btn btn-link"
          onClick={() => {
            ui.setState({ panelOpen: true });
            document.getElementById('presets-title')?.scrollIntoView({ block: 'start' });
          }}
          data-testid="first-run-all"
        >
          {t('guidance.firstRunAll')}
        </button>
      </div>
    </div>
  );
}
