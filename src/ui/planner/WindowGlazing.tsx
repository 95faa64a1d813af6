import './registerRoomShapeEnglish';
import { GLAZING_PRESETS, type GlazingPreset } from '../../core/daylight/glazing';
import type { TransmittanceValue } from '../../core/model/configuration/daylightSettings';
import { DEFAULT_TRANSMITTANCE } from '../../core/model/lightingScene/parseDaylight';
import type { ActionGate } from './actionGate';
import { CommitField } from '../shared/CommitField';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';

const PRESET_KEYS = { single: 'roomShape.glazingSingle', double: 'roomShape.glazingDouble', triple: 'roomShape.glazingTriple' } as const satisfies Record<GlazingPreset, MessageKey>;
const PRESETS = Object.keys(GLAZING_PRESETS) as GlazingPreset[];

/**
 * A window's glazing in the room-shape sheet (issue 30, docs/daylight.md "Glazing"): single,
 * double or triple clear glazing, or the normal-incidence transmittance as a number (1 = an open
 * window). Each choice is one setWindowGlazing through the gate.
 */
export function WindowGlazing({ opening, value, gate }: { opening: number; value: TransmittanceValue | undefined; gate: ActionGate }) {
  const { t, format } = useI18n();
  const current = value ?? DEFAULT_TRANSMITTANCE;
  const tau = (p: GlazingPreset) => format.number(GLAZING_PRESETS[p].normalTransmittance, { minimumFractionDigits: 2 });
  return (
    <div className="room-shape-glazing" data-testid="room-window-glazing">
      <label className="room-shape-field">
        <span>{t('roomShape.glazing')}</span>
        <select
          value={typeof current === 'number' ? 'number' : current}
          data-testid="room-glazing-select"
          onChange={(e) => {
            const choice = e.currentTarget.value;
            // "A number" starts from what the glazing transmits now.
            const next = choice === 'number' ? (typeof current === 'number' ? current : GLAZING_PRESETS[current].normalTransmittance) : (choice as GlazingPreset);
            const refused = gate.attempt('setWindowGlazing', { opening, transmittance: next });
            if (refused) gate.explain(refused);
          }}
        >
          {PRESETS.map((p) => (
            <option key={p} value={p}>
              {t(PRESET_KEYS[p], { tau: tau(p) })}
            </option>
          ))}
          <option value="number">{t('roomShape.glazingNumber')}</option>
        </select>
      </label>
      {typeof current === 'number' && (
        <label className="room-shape-field">
          <span>{t('roomShape.transmittance')}</span>
          <CommitField label={t('roomShape.transmittance')} value={current} decimals={2} onCommit={(v) => gate.attempt('setWindowGlazing', { opening, transmittance: v })} onRefused={gate.explain} testId="room-glazing-transmittance" />
        </label>
      )}
    </div>
  );
}
