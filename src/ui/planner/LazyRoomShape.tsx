import { lazy, Suspense, type ComponentProps } from 'react';
import type { RoomShapeEditorProps } from './RoomShapeEditor';
import { loadRoomShapeSupport } from '../../core/model/actions/loadRoomShapeSupport';

/**
 * The room-shape editor, a chunk of its own: fetched when the shopper opens the room-shape mode,
 * never with the first screen, together with the model's room-shape chunk its actions live in
 * (roomShapeSupport.ts).
 */
const Editor = lazy(() => Promise.all([import('./RoomShapeEditor'), loadRoomShapeSupport()]).then(([editor]) => editor));

/** The walls, openings and slopes of a drawn room: a chunk fetched only when the room has a shape (the box draws its own rectangle). */
const Drawing = lazy(() => import('./RoomShapeDrawing'));

/** RoomShapeEditor, loaded on demand (same props). */
export function LazyRoomShapeEditor(props: RoomShapeEditorProps) {
  return (
    <Suspense fallback={null}>
      <Editor {...props} />
    </Suspense>
  );
}

/** RoomShapeDrawing, loaded on demand (same props). */
export function LazyRoomShapeDrawing(props: ComponentProps<typeof import('./RoomShapeDrawing').default>) {
  return (
    <Suspense fallback={null}>
      <Drawing {...props} />
    </Suspense>
  );
}
