/**
 * The error Strata throws for bad input: a broken or hostile file, a nonsense setting, a model that
 * does not fit. The CLI prints its message on one line, without a stack trace.
 */
export type ErrorCode =
  | 'BAD_MESH'
  | 'BAD_FILE'
  | 'UNSUPPORTED_FORMAT'
  | 'BAD_SETTING'
  | 'UNKNOWN_SETTING'
  | 'UNKNOWN_PRESET'
  | 'DOES_NOT_FIT'
  | 'OVERLAPPING_OBJECTS'
  | 'EMPTY_MODEL'
  | 'BAD_SHADER'
  | 'BAD_IMAGE'
  | 'LIMIT_EXCEEDED'
  | 'WRITE_FAILED'
  | 'CANCELLED';

export class StrataError extends Error {
  readonly code: ErrorCode;
  constructor(code: ErrorCode, message: string, options?: { cause?: unknown }) {
    super(message, options);
    this.name = 'StrataError';
    this.code = code;
  }
}

/** The error of a slice stopped by its AbortSignal; `cause` is the signal's reason. */
export function cancelled(signal?: AbortSignal): StrataError {
  return new StrataError('CANCELLED', 'slicing was cancelled', signal ? { cause: signal.reason } : undefined);
}
