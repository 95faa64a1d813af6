import type en from './messages/en/index';
import type enLazy from './messages/en/lazy';
import type enOptionsPanel from './messages/en/optionsPanel';
import type enCore from './messages/en/core';
import type enPanelExtras from './messages/en/panelExtras';
import type enGuidance from './messages/en/guidance';
import type enScenes from './messages/en/scenes';
import type enA11y from './messages/en/a11y';
import type enRoomShape from './messages/en/roomShape';
import type enDaylight from './messages/en/daylight';
import type enDaylightPlan from './messages/en/daylightPlan';

/**
 * A message that depends on a count: the CLDR plural category of `params.count` picks the text
 * (Intl.PluralRules); `other` is required because every language has it.
 */
export interface PluralMessage {
  zero?: string;
  one?: string;
  two?: string;
  few?: string;
  many?: string;
  other: string;
}

/**
 * English (the source) defines the keys; the message tree of every language has its shape. Its
 * 3D-only areas (messages/en/lazy.ts) are part of the type but arrive at run time with the 3D chunk,
 * the options panel's (messages/en/optionsPanel.ts) with the options panel's chunk, the share and
 * import-preview parts' (messages/en/panelExtras.ts) with theirs,
 * its core-code areas (messages/en/core.ts) with the first other language loaded, the planner's
 * guidance (messages/en/guidance.ts: first run, remedies) with the guidance chunk, the light scenes'
 * (messages/en/scenes.ts) with the scene panel's and the 3D view's chunks, the screen-reader
 * announcements' (messages/en/a11y.ts) with theirs, the room-shape editor's (messages/en/roomShape.ts) with its chunk, the daylight panel's
 * (messages/en/daylight.ts) with its chunk, the plan's daylight-factor overlay's (messages/en/daylightPlan.ts) with its.
 */
export type SourceMessages = typeof en &
  typeof enLazy &
  typeof enOptionsPanel &
  typeof enCore &
  typeof enPanelExtras & { guidance: typeof enGuidance; scenes: typeof enScenes; a11y: typeof enA11y; roomShape: typeof enRoomShape; daylight: typeof enDaylight; daylightPlan: typeof enDaylightPlan };

export type Area = keyof SourceMessages & string;

/** What one area of a translation must provide: every English key, a string for a string and a plural for a plural. */
export type AreaMessages<T> = { [K in keyof T]: T[K] extends string ? string : PluralMessage };

/** A whole language: every area of the English tree. */
export type MessageTree = { [A in Area]: AreaMessages<SourceMessages[A]> };

/** 'area.key' for every key English defines; a wrong key is a type error. */
export type MessageKey = { [A in Area]: `${A}.${keyof SourceMessages[A] & string}` }[Area];

/** Values for `{name}` placeholders; numbers are formatted for the locale, `count` also picks the plural. */
export type MessageParams = Record<string, string | number>;

export type Translate = (key: MessageKey, params?: Readonly<MessageParams>) => string;
