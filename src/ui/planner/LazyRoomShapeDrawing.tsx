import { lazy, Suspense, type ComponentProps } from 'react';

/** The walls, openings and slopes of a drawn room: a chunk fetched only when the room has a shape (the box draws its own rectangle). */
const Drawing = lazy(() => import('./RoomShapeDrawing'));

/** RoomShapeDrawing, loaded on demand (same props). */
export function LazyRoomShapeDrawing(props: ComponentProps<typeof import('./RoomShapeDrawing').default>) {
  return (
    <Suspense fallback={null}>
      <Drawing {...props} />
    </Suspense>
  );
}
