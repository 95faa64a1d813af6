import { CAMERA_PRESETS, type CameraPresetName } from '../../engines/view/cameraPresets';
import type { MessageKey } from '../i18n/messageTypes';
import { useI18n } from '../i18n/useI18n';
import { presetPressed, type CameraMode } from './cameraMode';

const PRESET_LABEL: Record<CameraPresetName, MessageKey> = { eye: 'view3d.cameraEye', top: 'view3d.cameraTop', corner: 'view3d.cameraCorner' };

/** The camera presets (eye, top, corner); the one the camera is at is pressed. */
export function CameraPresetButtons({ camera, onPreset }: { camera: CameraMode; onPreset: (name: CameraPresetName) => void }) {
  const { t } = useI18n();
  return (
    <div className="viewer3d-group" role="group" aria-label={t('view3d.camera')}>
      {CAMERA_PRESETS.map((p) => (
        <button key={p} type="button" className={`btn${presetPressed(camera, p) ? ' btn-primary' : ''}`} aria-pressed={presetPressed(camera, p)} onClick={() => onPreset(p)} data-testid={`camera-${p}`}>
          {t(PRESET_LABEL[p])}
        </button>
      ))}
    </div>
  );
}
