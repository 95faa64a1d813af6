/** Parameters of a coded message: raw values (numbers, ids, names, line numbers) a UI formats for its locale. */
export type MessageParams = Readonly<Record<string, string | number>>;

/**
 * A sentence as a UI that speaks another language needs it (docs/i18n.md, "Messages from the
 * core"): the English text, its stable code and parameters, and, when the sentence quotes
 * another coded sentence (a file error naming the validation problem it found), that one as
 * `detail`, which the UI words first and passes as the parameter `problem`.
 */
export interface CodedText {
  readonly text: string;
  readonly code?: string;
  readonly params?: MessageParams;
  readonly detail?: CodedText;
}

/** The code, params and quoted detail an error or refusal carries besides its English sentence. */
export interface Coding {
  readonly code: string;
  readonly params?: MessageParams;
  readonly detail?: CodedText;
}

/**
 * Base class of every error caused by bad input (a malformed photometric file,
 * an impossible room, a corrupt scene). The CLI prints `message` as one line and
 * exits non-zero; the UI shows it. Anything that is not an InputError is a bug.
 */
export class InputError extends Error {
  override name = 'InputError';
  /** A stable code and its parameters, for UIs that show the message in another language (docs/i18n.md). */
  readonly code?: string;
  readonly params?: MessageParams;
  /** The coded sentence this message quotes, if any (e.g. the problem a scene file has). */
  readonly detail?: CodedText;
  constructor(message: string, coded?: Coding) {
    super(message);
    if (coded) {
      this.code = coded.code;
      this.params = coded.params;
      if (coded.detail) this.detail = coded.detail;
    }
  }
}

/** An error's or refusal's sentence with its coding, for a UI (absent parts stay absent). */
export function codedText(text: string, coded?: { code?: string; params?: MessageParams; detail?: CodedText }): CodedText {
  if (!coded?.code) return { text };
  return { text, code: coded.code, ...(coded.params ? { params: coded.params } : {}), ...(coded.detail ? { detail: coded.detail } : {}) };
}
