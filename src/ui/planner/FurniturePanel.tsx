import { memo, type ReactNode } from 'react';
import { FURNITURE_LIBRARY, type FurnitureItem } from '../../core/model/objects/furniture/furnitureLibrary';
import { ActionButton } from './ActionButton';
import type { ActionGate } from './actionGate';
import { libraryItemOutline } from './objectShapes';
import { useI18n } from '../i18n/useI18n';
import { ENGLISH } from '../i18n/english';
import type { Format } from '../i18n/createFormat';
import { furnitureName } from '../i18n/catalogNames';

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

/**
 * A small drawing of an item from the model's own geometry (not an image): its outline seen
 * from above, or for a wall item its front (width × height), as it is seen on the wall.
 */
const ItemThumbnail = memo(function ItemThumbnail({ item }: { item: FurnitureItem }) {
  const polygons =
    item.mount === 'wall'
      ? [
          [
            { x: -item.width / 2, z: -item.height / 2 },
            { x: item.width / 2, z: -item.height / 2 },
            { x: item.width / 2, z: item.height / 2 },
            { x: -item.width / 2, z: item.height / 2 },
          ],
        ]
      : libraryItemOutline(item.id);
  const size = Math.max(item.width, item.mount === 'wall' ? item.height : item.depth);
  const pad = size * 0.08;
  const d = polygons.map((p) => `M${p.map((q) => `${q.x},${q.z}`).join('L')}Z`).join('');
  return (
    <svg width={40} height={40} viewBox={`${-size / 2 - pad} ${-size / 2 - pad} ${size + 2 * pad} ${size + 2 * pad}`} aria-hidden>
      <path d={d} fillRule="evenodd" fill="#8a6d4b" fillOpacity={0.35} stroke="#4a5160" strokeWidth={size / 40} />
    </svg>
  );
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
        {FURNITURE_LIBRARY.map((item) => (
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
              <ItemThumbnail item={item} />
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
