/**
 * Three's own programs compiled without freezing the page (issue 34, docs/viewer.md "Compiles that
 * never freeze"). Before a frame whose materials are not the ones last compiled (the first frame
 * of a scene, a new object's material, a material whose `needsUpdate` was set), the view is not
 * drawn: `renderer.compileAsync` starts the compile, which with KHR_parallel_shader_compile polls
 * COMPLETION_STATUS_KHR every 10 ms instead of blocking on LINK_STATUS (three 0.187,
 * WebGLRenderer.compileAsync), and the frame is drawn once it has resolved. Meanwhile the page
 * keeps answering: no draw call waits for the driver. What the key does not see (a program
 * variant three chooses at draw time for another reason) is compiled at draw time, as before.
 */
export interface CompileCounters {
  /** compileAsync calls started, and those that resolved. */
  started: number;
  finished: number;
  /** Frames not drawn because a compile was under way. */
  heldFrames: number;
  /** Compiles that had resolved when the first frame was drawn (null: none drawn yet). */
  finishedAtFirstFrame: number | null;
}

export interface CompileGate {
  /**
   * Whether the view can be drawn now: its materials key is the last compiled one. Otherwise a
   * compile of that key is started (unless one is under way) and the frame is held; `onReady` runs
   * when it resolves (the caller asks for a frame then).
   */
  ready(): boolean;
  /** Note a drawn frame (for `finishedAtFirstFrame`). */
  drawn(): void;
  readonly counters: CompileCounters;
  /** No more `onReady` after this (the view is going). */
  dispose(): void;
}

export interface CompileGateSource {
  /** A key of the materials the next frame draws (roomView.ts materialsKey): equal keys need no compile. */
  key(): string;
  /** Compile them without blocking (renderer.compileAsync over the view's scene). */
  compile(): Promise<unknown>;
  onReady(): void;
}

export function createCompileGate(source: CompileGateSource): CompileGate {
  const counters: CompileCounters = { started: 0, finished: 0, heldFrames: 0, finishedAtFirstFrame: null };
  let compiledKey: string | null = null;
  let compilingKey: string | null = null;
  let disposed = false;
  const settle = (key: string) => {
    counters.finished++;
    // A compile overtaken by a newer key is not the one the next frame needs: that one settles later.
    if (compilingKey !== key) return;
    compilingKey = null;
    compiledKey = key;
    if (!disposed) source.onReady();
  };
  return {
    ready() {
      const key = source.key();
      if (key === compiledKey) return true;
      counters.heldFrames++;
      if (compilingKey !== key) {
        compilingKey = key;
        counters.started++;
        // A failed compile shows as three's own error at draw time: the frame is drawn then, not held forever.
        source.compile().then(
          () => settle(key),
          () => settle(key),
        );
      }
      return false;
    },
    drawn() {
      counters.finishedAtFirstFrame ??= counters.finished;
    },
    counters,
    dispose() {
      disposed = true;
    },
  };
}
