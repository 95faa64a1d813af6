import './registerOptionsEnglish';
import type { Room } from '../../core/model/configuration/configuration';
import type { ActionGate } from './actionGate';
import { CommitField } from '../shared/CommitField';
import { OptionsSection } from './OptionsSection';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';

const DIMENSIONS = [
  { key: 'width', titleKey: 'options.roomWidthTitle', labelKey: 'options.roomWidthField' },
  { key: 'depth', titleKey: 'options.roomDepthTitle', labelKey: 'options.roomDepthField' },
  { key: 'height', titleKey: 'options.roomHeightTitle', labelKey: 'options.roomHeightField' },
] as const satisfies readonly { key: string; titleKey: MessageKey; labelKey: MessageKey }[];

/** With nothing selected, the options are the room's: width, depth and height, each one setRoom. */
export function RoomOptions({ room, gate, onClose }: { room: Room; gate: ActionGate; onClose: () => void }) {
  const { t } = useI18n();
  const size = { width: room.width, depth: room.depth, height: room.height };
  return (
    <OptionsSection title={t('options.roomTitle')} onClose={onClose}>
      <div className="setup-fields">
        {DIMENSIONS.map((d) => (
          <div className="field" key={d.key}>
            <h3>{t(d.titleKey)}</h3>
            <CommitField label={t(d.labelKey)} value={size[d.key]} onCommit={(v) => gate.attempt('setRoom', { ...size, [d.key]: v })} onRefused={gate.explain} />
          </div>
        ))}
      </div>
    </OptionsSection>
  );
}
