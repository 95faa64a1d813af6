import { memo, type ReactNode } from 'react';
import { FURNITURE_LIBRARY } from '../../core/model/objects/furniture/furnitureLibrary';
import { ActionButton } from './ActionButton';
import type { ActionGate } from './actionGate';
import { useI18n } from '../i18n/useI18n';
import { ENGLISH } from '../i18n/english';
import type { Format } from '../i18n/createFormat';
import { furnitureName } from '../i18n/catalogNames';
import thumbnailSheet from './furnitureThumbnails.png';

/** The drag-and-drop data type carrying a library item id from the panel onto the plan. */
export const FURNITURE_DRAG_TYPE = 'application/x-luxbox-furniture';

/** Centimetres, as furniture is sized in shops: 1.8 m → "180" (in the locale: 0.455 m → "45,5" in German). */
export function centimetres(metres: number, format: Pick<Format, 'number'> = ENGLISH.format): string {
  return format.number(Math.round(metres * 1000) / 10, { useGrouping: false });
}

/** "180 × 90 × 75 cm" (width × depth × height) for an item at a scale. */
export function itemDimensions(size: { width: number; depth: number; height: number }, scale = 1, format: Pick<Format, 'number'> = ENGLISH.format): string {
  return `${centimetres(size.width * scale, format)} × ${centimetres(size.depth * scale, format)} × ${centimetres(size.height * scale, format)} cm`;
}

/** CSS pixels a side of a library thumbnail (the sheet has twice as many, for high-density screens). */
const THUMBNAIL_CSS_PIXELS = 48;

/**
 * An item's picture: its cell of the sprite sheet drawn from the item's own mesh and default
 * finishes by scripts/furnitureThumbnails.ts (a three-quarter view, flat-shaded), one image for
 * the whole library so the first screen loads one small file and no drawing code. The cells are
 * in FURNITURE_LIBRARY's order; a test checks the committed sheet is what the meshes give.
 */
const ItemThumbnail = memo(function ItemThumbnail({ index }: { index: number }) {
  const s = THUMBNAIL_CSS_PIXELS;
  return <span className="furniture-thumbnail" aria-hidden style={{ width: s, height: s, backgroundImage: `url(${thumbnailSheet})`, backgroundSize: `${s * FURNITURE_LIBRARY.length}px ${s}px`, backgroundPosition: `${-s * index}px 0` }} />;
});

export interface FurniturePanelProps {
  gate: ActionGate;
  /** Adds the item at the middle of the visible plan (wall items: the nearest wall) and selects it. */
  onAdd: (itemId: string) => void;
  /** The import form, shown under the library. */
  children?: ReactNode;
}

/**
 * The furniture library in the side panel: every item with its name and real size. A tap adds
 * it at the middle of the visible plan; on a desktop it can also be dragged onto the plan.
 * Disabled, with the model's reason, where it cannot fit in this room at all.
 */
export function FurniturePanel({ gate, onAdd, children }: FurniturePanelProps) {
  const { t, format } = useI18n();
  return (
    <section className="panel-section" aria-labelledby="furniture-title" data-testid="furniture-panel">
      <h2 id="furniture-title">{t('planner.furniture')}</h2>
      <ul className="furniture-grid">
        {FURNITURE_LIBRARY.map((item, index) => (
          <li
            key={item.id}
            draggable
            onDragStart={(e) => {
              e.dataTransfer.setData(FURNITURE_DRAG_TYPE, item.id);
              e.dataTransfer.effectAllowed = 'copy';
            }}
          >
            <ActionButton
              label={t('planner.addFurniture', { name: furnitureName(t, item), size: itemDimensions(item, 1, format) })}
              disabledReason={gate.reason('addObject', { source: { kind: 'library', item: item.id } })}
              onPress={() => onAdd(item.id)}
              onDisabledPress={gate.explain}
              testId={`furniture-${item.id}`}
            >
              <ItemThumbnail index={index} />
              <span>
                <span className="preset-name">{furnitureName(t, item)}</span>
                <span className="preset-detail">{itemDimensions(item, 1, format)}</span>
              </span>
            </ActionButton>
          </li>
        ))}
      </ul>
      {children}
    </section>
  );
}
