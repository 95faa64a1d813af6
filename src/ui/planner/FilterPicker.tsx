import './registerOptionsEnglish';
import { useMemo, useState } from 'react';
import { FILTER_KINDS } from '../../core/colour/colourFilterLibrary';
import { swatchCss } from '../../core/colour/displaySwatch';
import type { FilteredColour } from '../../core/colour/filteredColour';
import { moduleColour } from '../../core/colour/moduleColour';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { ModuleInstance } from '../../core/model/configuration/configuration';
import { catalogFilters, filterLabel, filterMatches } from '../../core/model/modules/moduleFilter';
import { useI18n } from '../i18n/useI18n';
import { useColourFilterSpectra } from './useColourFilterSpectra';
import type { ActionGate } from './actionGate';
import { GatedButton } from './GatedButton';
import { OptionChips } from './OptionChips';

export interface FilterPickerProps {
  module: ModuleInstance;
  catalog: Catalog;
  gate: ActionGate;
}

const swatchStyle = (colour: FilteredColour, size: string) => ({
  display: 'inline-block',
  width: size,
  height: size,
  borderRadius: '50%',
  border: '1px solid #1d2330',
  background: swatchCss(colour.linearRgb),
  verticalAlign: 'middle',
  marginRight: '0.4em',
  flex: 'none',
});

/**
 * The colour filter (gel) of a module whose type has a holder (docs/colour-filters.md): what the
 * light is now (swatch, name, transmission; CIE x,y and CCT/Duv behind Expert details), a search by name or
 * number, and the catalog's filters grouped by kind, each with the swatch of the light it gives
 * this module. Choosing one is setModuleFilter: a relight in 3D, never a rebake.
 */
export function FilterPicker(props: FilterPickerProps) {
  const { t } = useI18n();
  // The swatches need the spectra (loaded on first need, docs/colour-filters.md "Two files").
  if (!useColourFilterSpectra(true)) {
    return (
      <div className="field" role="group" aria-label={t('filters.title')} aria-busy="true" data-testid="filter-picker">
        <h3>{t('filters.title')}</h3>
        <p>{t('filters.loading')}</p>
      </div>
    );
  }
  return <LoadedFilterPicker {...props} />;
}

function LoadedFilterPicker({ module, catalog, gate }: FilterPickerProps) {
  const { t, format } = useI18n();
  const [query, setQuery] = useState('');
  const moduleId = module.id;
  // Every filter's colour for this module's CCT: 43 small spectral sums, redone only when the CCT changes.
  const all = useMemo(() => catalogFilters(catalog).map((item) => ({ ...item, colour: moduleColour(module.cct, item.filter.id) })), [catalog, module.cct]);
  const current = module.filter === undefined ? null : (all.find((f) => f.filter.id === module.filter) ?? null);
  const colour = current?.colour ?? moduleColour(module.cct, undefined);
  const shown = all.filter(({ filter }) => filterMatches(filter, query));
  const xy = (v: number) => format.number(v, { minimumFractionDigits: 4, maximumFractionDigits: 4 });
  const percent = (v: number) => format.percent(v, { maximumFractionDigits: 1 });
  return (
    <div className="field" role="group" aria-label={t('filters.title')} data-testid="filter-picker">
      <h3>{t('filters.title')}</h3>
      <div data-testid="filter-readout" style={{ display: 'flex', alignItems: 'flex-start', gap: '0.25em' }}>
        <span role="img" aria-label={t('filters.swatch')} data-testid="filter-swatch" data-colour={swatchCss(colour.linearRgb)} style={swatchStyle(colour, '2em')} />
        <span>
          <strong>{current ? filterLabel(current.filter) : t('filters.unfiltered', { cct: String(module.cct) })}</strong>
          <br />
          {t('filters.transmission', { percent: percent(colour.transmission) })}
          {/* The colorimetry (CIE 1931 x, y; CCT and Duv) is for experts: one tap away, closed by default. */}
          <details className="expert-details" data-testid="filter-expert-details">
            <summary>{t('filters.expertDetails')}</summary>
            {t('filters.chromaticity', { x: xy(colour.x), y: xy(colour.y) })}
            <br />
            {colour.white ? t('filters.white', { cct: format.number(Math.round(colour.white.cct)), duv: format.number(colour.white.duv, { minimumFractionDigits: 4, maximumFractionDigits: 4 }) }) : t('filters.notWhite')}
          </details>
        </span>
      </div>
      <input type="search" value={query} onChange={(e) => setQuery(e.target.value)} placeholder={t('filters.searchPlaceholder')} aria-label={t('filters.search')} data-testid="filter-search" style={{ width: '100%', margin: '0.4em 0' }} />
      <div className="chip-row">
        <GatedButton gate={gate} action="setModuleFilter" params={{ moduleId, filter: null }} label={t('filters.none')} current={module.filter === undefined} testId="filter-none" />
      </div>
      {FILTER_KINDS.map((kind) => {
        const group = shown.filter((f) => f.filter.kind === kind);
        if (group.length === 0) return null;
        return (
          <OptionChips key={kind} title={t(`filters.kind_${kind}`)}>
            {group.map(({ filter, colour: c }) => (
              <GatedButton
                key={filter.id}
                gate={gate}
                action="setModuleFilter"
                params={{ moduleId, filter: filter.id }}
                label={t('filters.choose', { name: filterLabel(filter), percent: percent(c.transmission) })}
                current={module.filter === filter.id}
                testId={`filter-${filter.id}`}
              >
                <span aria-hidden="true" style={swatchStyle(c, '0.9em')} />
                {filterLabel(filter)}
              </GatedButton>
            ))}
          </OptionChips>
        );
      })}
      {shown.length === 0 && <p data-testid="filter-no-match">{t('filters.noMatch', { query })}</p>}
    </div>
  );
}
