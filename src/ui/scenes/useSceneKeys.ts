import { useEffect } from 'react';
import type { RecallResult, ScenePlayer } from './createScenePlayer';

/** Typing in a field, or a focused control that space would press: the key is theirs. */
function keyBelongsTo(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  if (target.isContentEditable || /^(INPUT|TEXTAREA|SELECT)$/.test(target.tagName)) return true;
  // A focused button other than GO / BACK: space presses it, as everywhere on the web.
  return (target.tagName === 'BUTTON' || target.getAttribute('role') === 'button') && !target.hasAttribute('aria-keyshortcuts');
}

/**
 * Space = GO, Shift+Space = BACK, like a lighting console's GO and BACK keys (not while typing in a
 * field). `play` gets each recall's promise, so GO at the last scene is said, as for the buttons.
 */
export function useSceneKeys(player: ScenePlayer, play: (recall: Promise<RecallResult>) => void): void {
  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      if (e.key !== ' ' || e.ctrlKey || e.metaKey || e.altKey || keyBelongsTo(e.target)) return;
      e.preventDefault();
      play(e.shiftKey ? player.back() : player.go());
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [player, play]);
}
