import './registerOptionsEnglish';
import { useState, useSyncExternalStore } from 'react';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { ModuleInstance } from '../../core/model/configuration/configuration';
import { PhotometryWarnings } from '../shared/PhotometryWarnings';
import type { ActionGate } from './actionGate';
import type { FootprintSource } from './footprintSource';
import { GatedButton } from './GatedButton';
import { beamChangeNote, type ModuleBeamState } from './beamChangeNote';
import { modulePhotometryPath } from './moduleFootprint';
import { OptionChips } from './OptionChips';
import { OptionsSection } from './OptionsSection';
import { AimOptions } from './AimOptions';
import type { AimAtMode } from '../shared/aimAtMode';
import { FilterPicker } from './FilterPicker';
import { useI18n } from '../i18n/useI18n';
import { localLabel, localName } from '../i18n/localName';

/** Dimming levels offered as touch-sized choices (the 3D view relights instantly on a change). */
export const DIMMING_STEPS = [0.25, 0.5, 0.75, 1] as const;

/** The warnings of a module's photometric file, once the plan has loaded it (re-renders when it arrives). */
function ModulePhotometryNote({ source, path }: { source: FootprintSource; path: string }) {
  useSyncExternalStore(source.subscribe, source.version, source.version);
  return <PhotometryWarnings notes={[{ file: path, warnings: source.warnings(path) }]} testId="module-photometry-warnings" />;
}

/**
 * After a type change that could not keep the module's beam (the new type has no beam of that id,
 * beamForType took the nearest angle), says which beam was set instead; cleared by the next change
 * or another module (state adjusted while rendering, React's pattern for a prop change).
 */
function useBeamChangeNote(module: ModuleInstance, catalog: Catalog): string | null {
  const { t, language } = useI18n();
  const [last, setLast] = useState<ModuleBeamState>({ id: module.id, type: module.type, beam: module.beam });
  const [note, setNote] = useState<string | null>(null);
  if (last.id !== module.id || last.type !== module.type || last.beam !== module.beam) {
    setLast({ id: module.id, type: module.type, beam: module.beam });
    setNote(beamChangeNote(last, module, catalog, t, language));
  }
  return note;
}

export interface ModuleOptionsProps {
  module: ModuleInstance;
  catalog: Catalog;
  gate: ActionGate;
  onClose: () => void;
  /** The plan's photometry loader: the module's file warnings are shown from it. */
  footprints?: FootprintSource;
  /** Aim-at mode shared with the 3D view; absent: no aim options (docs/aiming.md). */
  aimMode?: AimAtMode;
}

/** A selected module's settings (configurator paper, fig. 10, 11): type, beam, photometry notes, colour temperature, dimming, remove. */
export function ModuleOptions({ module, catalog, gate, onClose, footprints, aimMode }: ModuleOptionsProps) {
  const { t, format, language } = useI18n();
  const type = catalog.moduleTypes.find((m) => m.id === module.type);
  const photometryPath = modulePhotometryPath(module, catalog);
  const moduleId = module.id;
  const beamNote = useBeamChangeNote(module, catalog);
  return (
    <OptionsSection title={t('options.moduleTitle', { name: type ? localName(type, language) : module.type })} onClose={onClose}>
      <OptionChips title={t('options.moduleType')}>
        {catalog.moduleTypes.map((m) => (
          <GatedButton key={m.id} gate={gate} action="setModuleType" params={{ moduleId, type: m.id }} label={localName(m, language)} current={m.id === module.type} testId={`type-${m.id}`} />
        ))}
      </OptionChips>
      {type && type.beams.length > 0 && (
        <OptionChips title={t('options.beam')}>
          {type.beams.map((b) => (
            <GatedButton key={b.id} gate={gate} action="setModuleBeam" params={{ moduleId, beam: b.id }} label={localLabel(b, language)} current={b.id === module.beam} testId={`beam-${b.id}`} />
          ))}
        </OptionChips>
      )}
      {beamNote && (
        <p className="empty-note" role="status" data-testid="beam-changed">
          {beamNote}
        </p>
      )}
      {footprints && photometryPath && <ModulePhotometryNote source={footprints} path={photometryPath} />}
      {type && (
        <OptionChips title={t('options.colourTemperature')}>
          {type.ccts.map((k) => (
            <GatedButton key={k} gate={gate} action="setModuleCct" params={{ moduleId, cct: k }} label={t('options.kelvin', { k: String(k) })} current={k === module.cct} testId={`cct-${k}`} />
          ))}
        </OptionChips>
      )}
      <OptionChips title={t('options.dimming')}>
        {DIMMING_STEPS.map((d) => {
          const percent = Math.round(d * 100);
          return <GatedButton key={d} gate={gate} action="setModuleDimming" params={{ moduleId, dimming: d }} label={format.percent(d)} current={Math.abs(module.dimming - d) < 1e-9} testId={`dimming-${percent}`} />;
        })}
      </OptionChips>
      {type?.filterHolder && <FilterPicker module={module} catalog={catalog} gate={gate} />}
      {aimMode && <AimOptions module={module} catalog={catalog} gate={gate} aimMode={aimMode} />}
      <GatedButton gate={gate} action="removeModule" params={{ moduleId }} label={t('options.removeModule')} />
    </OptionsSection>
  );
}
