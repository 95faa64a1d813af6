import { useEffect, useMemo, useState } from 'react';
import { recallLooks } from '../../core/model/cues/lightScenes';
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { ViewerController } from '../../engines/view/createViewerController';
import { useI18n } from '../i18n/useI18n';
import { fromScene, lightsOf } from '../../engines/view/sceneLights';
import type { BakeFeed } from './startBakeFeed';

/** The A/B compare's choice: on or off, the two light scenes by id, the wipe (0…1 of the width shows A from the left). */
export interface CompareChoice {
  on: boolean;
  a: string | null;
  b: string | null;
  split: number;
}

export const COMPARE_OFF: CompareChoice = { on: false, a: null, b: null, split: 0.5 };

/**
 * The A/B compare of two recorded light scenes in the 3D view (docs/viewer.md, "A/B compare"): the
 * lit configuration with each scene's looks (dimming and colour: relights of the same bases), A left
 * of the wipe and B right of it, at one exposure. Handed to the controller whenever the choice, the
 * wipe or the resolved configuration changes.
 */
export function useCompare(feed: BakeFeed | null, controller: { readonly current: ViewerController | null }, controllerVersion: number): [CompareChoice, (patch: Partial<CompareChoice>) => void, { id: string; name: string }[]] {
  const [choice, setChoice] = useState<CompareChoice>(COMPARE_OFF);
  // Each resolved configuration re-renders; the feed hands back the same object until the next one.
  const [, setResolved] = useState(0);
  useEffect(() => feed?.subscribe(() => setResolved((n) => n + 1)), [feed]);
  const latest = feed?.latest() ?? null;
  const scenes = useMemo(() => (latest?.config.lightScenes ?? []).map((s) => ({ id: s.id, name: s.name })), [latest]);
  const sides = useMemo((): [BakeScene, BakeScene] | null => {
    if (!choice.on || !latest) return null;
    const sceneOf = (id: string | null): BakeScene | null => {
      const scene = latest.config.lightScenes?.find((s) => s.id === id);
      if (!scene) return null;
      try {
        return fromScene(latest.bake, latest.ids, lightsOf(recallLooks(latest.config, scene, latest.catalog), latest.catalog));
      } catch {
        // A look the lighting scene cannot take now (a filter's spectra not loaded): no compare.
        return null;
      }
    };
    const a = sceneOf(choice.a);
    const b = sceneOf(choice.b);
    return a && b ? [a, b] : null;
  }, [choice.on, choice.a, choice.b, latest]);
  useEffect(() => {
    controller.current?.setCompare(sides ? { a: sides[0], b: sides[1], split: choice.split } : null);
  }, [controller, sides, choice.split, controllerVersion]);
  const update = (patch: Partial<CompareChoice>) =>
    setChoice((c) => {
      const next = { ...c, ...patch };
      // Turned on: the first two scenes unless chosen.
      if (next.on && (!next.a || !scenes.some((s) => s.id === next.a))) next.a = scenes[0]?.id ?? null;
      if (next.on && (!next.b || !scenes.some((s) => s.id === next.b))) next.b = scenes.find((s) => s.id !== next.a)?.id ?? null;
      return next;
    });
  return [choice, update, scenes];
}

/** The panel's A/B group: the toggle and the two scene choices; nothing with fewer than two light scenes. */
export function CompareControl({ choice, update, scenes }: { choice: CompareChoice; update: (patch: Partial<CompareChoice>) => void; scenes: { id: string; name: string }[] }) {
  const { t } = useI18n();
  if (scenes.length < 2) return null;
  const select = (side: 'a' | 'b') => (
    <label className="viewer3d-compare-side">
      {t(side === 'a' ? 'view3d.compareA' : 'view3d.compareB')}{' '}
      <select value={choice[side] ?? ''} onChange={(e) => update({ [side]: e.target.value })} data-testid={`compare-${side}`}>
        {scenes.map((s) => (
          <option key={s.id} value={s.id}>
            {s.name}
          </option>
        ))}
      </select>
    </label>
  );
  return (
    <div className="viewer3d-group" role="group" aria-label={t('view3d.compare')}>
      <button type="button" className={`btn${choice.on ? ' btn-primary' : ''}`} aria-pressed={choice.on} onClick={() => update({ on: !choice.on })} data-testid="compare-toggle" title={t('view3d.compare')}>
        {t('view3d.compareToggle')}
      </button>
      {choice.on && select('a')}
      {choice.on && select('b')}
    </div>
  );
}

/** Over the canvas: the wipe line, the two scenes' names and the wipe slider. */
export function CompareWipe({ choice, update, scenes }: { choice: CompareChoice; update: (patch: Partial<CompareChoice>) => void; scenes: { id: string; name: string }[] }) {
  const { t } = useI18n();
  if (!choice.on || scenes.length < 2) return null;
  const name = (id: string | null) => scenes.find((s) => s.id === id)?.name ?? '';
  return (
    <div className="viewer3d-compare" data-testid="compare-wipe-overlay">
      <div className="viewer3d-compare-line" style={{ left: `${choice.split * 100}%` }} />
      <span className="viewer3d-compare-label viewer3d-compare-label-a">{`${t('view3d.compareA')} · ${name(choice.a)}`}</span>
      <span className="viewer3d-compare-label viewer3d-compare-label-b">{`${t('view3d.compareB')} · ${name(choice.b)}`}</span>
      <input
        type="range"
        className="viewer3d-compare-slider"
        min={0}
        max={1}
        step={0.01}
        value={choice.split}
        onInput={(e) => update({ split: Number((e.target as HTMLInputElement).value) })}
        onChange={(e) => update({ split: Number(e.target.value) })}
        aria-label={t('view3d.compareWipe')}
        data-testid="compare-wipe"
      />
    </div>
  );
}
