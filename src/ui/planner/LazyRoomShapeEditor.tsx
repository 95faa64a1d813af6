import { lazy, Suspense } from 'react';
import type { RoomShapeEditorProps } from './RoomShapeEditor';

/** The room-shape editor, a chunk of its own: fetched when the shopper opens the room-shape mode, never with the first screen. */
const Editor = lazy(() => import('./RoomShapeEditor'));

/** RoomShapeEditor, loaded on demand (same props). */
export function LazyRoomShapeEditor(props: RoomShapeEditorProps) {
  return (
    <Suspense fallback={null}>
      <Editor {...props} />
    </Suspense>
  );
}
