// Type declarations of <screwcut-preview> (the package's README documents
// each attribute, property and event).

/** A controller dialect the element reads programs as. */
export type ScrewcutDialect = 'gsk980tdc' | 'fanuc0i' | 'renhe' | 'linuxcnc';

/** A drawing or list the element shows (`view` takes them separated by spaces or commas). */
export type ScrewcutView = 'side' | 'tooth' | 'starts' | 'table';

/** The attributes, as written in HTML. */
export interface ScrewcutPreviewAttributes {
  /** `gsk980tdc` (default), `fanuc0i`, `renhe` or `linuxcnc`. */
  dialect?: ScrewcutDialect | string;
  /** Any of `side`, `tooth`, `starts`, `table`, separated by spaces or commas (default `side`). */
  view?: string;
  /** Height of each drawing in CSS px, 120–1200 (default 320). */
  height?: string | number;
  /** The thread (1-based) the tooth, starts and table views show. */
  thread?: string | number;
  /** Controller parameters and previewer settings, `NAME=VALUE` separated by `;`. */
  settings?: string;
  /** URL of the program (http(s) or relative), instead of the text content. */
  src?: string;
  /** A plain text editor under the drawings (a flag). */
  editable?: boolean | '';
  /** Without `editable`: leave the program's listing out (a flag). */
  'hide-code'?: boolean | '';
  /** With static `<svg>` drawings inside: plan when scrolled near, not only when the reader points at it or focuses it (a flag). */
  live?: boolean | '';
  /** The app the "Open in editor" link opens (http(s) or relative). */
  app?: string;
  /** The labels' language: `en` (default) or `zh`. */
  lang?: 'en' | 'zh' | string;
}

/** A diagnostic of the program, with its place in the text. */
export interface ScrewcutDiagnostic {
  severity: 'error' | 'warning' | 'info';
  /** Stable code, as `screwcut codes` lists it. */
  code: string;
  /** The message in the element's language. */
  message: string;
  /** 1-based line and column (characters) of the start, and of the end (exclusive). */
  line: number;
  column: number;
  end_line: number;
  end_column: number;
  /** UTF-16 offsets of the span in the program. */
  from: number;
  to: number;
  /** Inside a subprogram or macro: the lines of the calls that led here, innermost first. */
  via?: number[];
  /** How many times the program raised it here after these calls (a loop run again), when more than once. */
  repeats?: number;
}

/** One pass of the chosen thread (X as a diameter). */
export interface ScrewcutPass {
  /** The start (1-based) the pass cuts. */
  start: number;
  /** The pass's number within its start. */
  index: number;
  /** Where the cut starts and ends: [X, Z]. */
  from: [number, number];
  to: [number, number];
  /** Depth below the crest (radius) and the infeed since the previous pass. */
  depth: number;
  infeed: number;
  /** Chip area (mm² or in²) and that of an even-area schedule; null: not known. */
  area: number | null;
  evenArea: number | null;
  /** Time of the pass, s; null without a spindle speed. */
  time: number | null;
  role: 'rough' | 'finish' | 'spring';
  /** The program lines that cut the pass, and the call lines that led there. */
  lines: number[];
  via: number[];
  /** Axial shift of the pass from the first (flank infeed) and the infeed angle, degrees. */
  shift: number;
  angle: number;
}

/** A thread of the program, without its passes. */
export interface ScrewcutThread {
  line: number;
  end_line: number;
  lead: number;
  pitch: number;
  starts: number;
  internal: boolean;
  infeed: string;
  tool_angle: number;
  crest: number;
  height: number;
  taper: number;
  /** Number of passes. */
  passes: number;
  [figure: string]: unknown;
}

/** The planner's last answer. */
export interface ScrewcutResult {
  dialect: ScrewcutDialect;
  alarms: number;
  warnings: number;
  notes: number;
  /** Motions planned. */
  moves: number;
  /** Threading time, s; null without a spindle speed. */
  timeS: number | null;
  /** The plan draws something and has no alarm. */
  good: boolean;
  diagnostics: ScrewcutDiagnostic[];
  threads: ScrewcutThread[];
  /** The chosen thread's passes. */
  passes: ScrewcutPass[];
  /** `settings` entries the planner refused. */
  settingErrors: { setting: string; message: string }[];
  [more: string]: unknown;
}

/** Something the element could not use. */
export interface ScrewcutProblem {
  attribute: 'dialect' | 'settings' | 'app' | string;
  message: string;
}

/** `detail` of `screwcut-plan`. */
export interface ScrewcutPlanDetail {
  threads: number;
  passes: number;
  alarms: number;
  warnings: number;
  notes: number;
}

/** `detail` of `screwcut-error`. */
export interface ScrewcutErrorDetail {
  message: string;
}

export interface ScrewcutPreviewEventMap extends HTMLElementEventMap {
  'screwcut-plan': CustomEvent<ScrewcutPlanDetail>;
  'screwcut-error': CustomEvent<ScrewcutErrorDetail>;
}

/** `<screwcut-preview>`: a live diagram of a lathe threading program. */
export declare class ScrewcutPreview extends HTMLElement {
  static readonly observedAttributes: string[];
  /** The G-code shown: the text content (without a static `<svg>` inside), or what `src` loaded; set it to change the drawing. */
  program: string;
  /** The planner's last answer, or null before the first plan. */
  readonly result: ScrewcutResult | null;
  /** What the element could not use (also listed under the drawing). */
  readonly problems: ScrewcutProblem[];
  /** Plans now, without waiting to be scrolled into view or pointed at. */
  start(): void;
  addEventListener<K extends keyof ScrewcutPreviewEventMap>(
    type: K,
    listener: (this: ScrewcutPreview, ev: ScrewcutPreviewEventMap[K]) => unknown,
    options?: boolean | AddEventListenerOptions,
  ): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void;
  removeEventListener<K extends keyof ScrewcutPreviewEventMap>(
    type: K,
    listener: (this: ScrewcutPreview, ev: ScrewcutPreviewEventMap[K]) => unknown,
    options?: boolean | EventListenerOptions,
  ): void;
  removeEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | EventListenerOptions): void;
}

declare global {
  interface HTMLElementTagNameMap {
    'screwcut-preview': ScrewcutPreview;
  }
}
