//! Diagnostic codes: every alarm, warning and note screwcut gives, with
//! its fixed severity and stable string form.

use serde::Serialize;

/// How serious a diagnostic is. `Error` is an alarm: the controller would
/// stop, and the CLI exits with status 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// Advice or a note on how something was read.
    Info,
    /// Probably not what was meant; the plan is still drawn.
    Warning,
    /// An alarm: the controller would refuse this block.
    Error,
}

impl Severity {
    /// Its name as the JSON writes it: `error`, `warning` or `info`.
    pub fn name(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info => "info",
        }
    }
}

macro_rules! codes {
    ($( $(#[$doc:meta])* $name:ident = $text:literal, $sev:ident; )*) => {
        /// Every diagnostic screwcut emits. The string form is stable and is
        /// what the JSON, the CLI and the web app show; codes of the
        /// controllers themselves (such as Renhe `E18-03`) are kept verbatim.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Code {
            $( $(#[$doc])* $name, )*
        }

        impl Code {
            /// All codes, for documentation and coverage tests.
            pub const ALL: &'static [Code] = &[ $( Code::$name, )* ];

            /// The stable string form.
            pub fn as_str(self) -> &'static str {
                match self { $( Code::$name => $text, )* }
            }

            /// The severity this code always carries.
            pub fn severity(self) -> Severity {
                match self { $( Code::$name => Severity::$sev, )* }
            }
        }
    };
}

codes! {
    // ---- lexical ----
    /// Full-width or look-alike characters were read as their ASCII twins.
    FullWidth = "full-width", Info;
    /// A number with misplaced signs or points (`X1.2.3`, `Z--4`).
    MalformedNumber = "malformed-number", Error;
    /// A word letter with no number after it.
    MissingValue = "missing-value", Error;
    /// A letter this dialect does not use as an address.
    UnknownAddress = "unknown-address", Error;
    /// A character that cannot start a word.
    UnexpectedCharacter = "unexpected-character", Error;
    /// The same address twice in one block.
    RepeatedWord = "repeated-word", Error;
    /// A block longer than the `limits.block_chars` setting.
    BlockTooLong = "block-too-long", Error;
    /// More digits than the controller accepts (`limits.digits`).
    TooManyDigits = "too-many-digits", Error;
    /// `(` without a closing `)` on the same line.
    UnclosedComment = "unclosed-comment", Error;
    /// `)` without an opening `(`.
    UnmatchedParen = "unmatched-paren", Error;
    /// `(` inside a comment: comments do not nest.
    NestedComment = "nested-comment", Warning;
    /// G-code after `;`, which ends the block: it is not executed.
    CodeAfterSemicolon = "code-after-semicolon", Warning;
    /// Macro variables and expressions (`#`, `[`) are not interpreted.
    UnsupportedMacro = "unsupported-macro", Error;
    /// `O` not followed by a program number.
    MalformedProgramNumber = "malformed-program-number", Error;
    /// The program is larger than `limits.program_bytes`.
    ProgramTooLarge = "program-too-large", Error;
    /// The program reads without alarm as another controller's (its name is the argument `dialect`).
    DialectHint = "dialect-hint", Info;
    // ---- interpreter ----
    /// A length written finer than the controller's least input increment.
    FinerThanIncrement = "finer-than-increment", Info;
    /// A G code the dialect does not have.
    UnsupportedGCode = "unsupported-g-code", Error;
    /// A G code the controller has but the previewer does not draw.
    NotSimulated = "not-simulated", Warning;
    /// Two G codes of the same modal group in one block.
    ConflictingGCodes = "conflicting-g-codes", Error;
    /// An absolute and an incremental word for the same axis (`X` with `U`).
    AxisConflict = "axis-conflict", Error;
    /// A Fanuc length without a decimal point read in least input increments.
    NoDecimalPoint = "no-decimal-point", Warning;
    /// A feed move before any feed rate was given.
    MissingFeed = "missing-feed", Warning;
    /// An arc whose radius is shorter than half its chord.
    ArcRadiusTooSmall = "arc-radius-too-small", Error;
    /// An arc whose I/K centre is not equidistant from its ends.
    ArcRadiusMismatch = "arc-radius-mismatch", Error;
    /// An arc without R or I/K.
    ArcMissingCenter = "arc-missing-center", Error;
    /// A word that this block's command does not take.
    UnexpectedWord = "unexpected-word", Error;
    /// A value outside the range the manual gives for the word.
    ValueOutOfRange = "value-out-of-range", Error;
    /// Blocks after M30/M02 are never executed.
    AfterEnd = "after-end", Info;
    /// G20/G21 changed after motion: coordinates mix units.
    UnitsChanged = "units-changed", Warning;
    /// A command that needs a word it did not get (G04 without time, G50 without axes...).
    MissingWord = "missing-word", Error;
    /// A word that must not carry a decimal point (Fanuc G32 Q, G76 P/Q).
    DecimalPointNotAllowed = "decimal-point-not-allowed", Error;
    /// An incremental move before any absolute position: the start was assumed.
    StartAssumed = "start-assumed", Info;
    /// The plan would hold more motions than `limits.moves`.
    MoveLimit = "move-limit", Error;
    // ---- program flow: subprograms, macros, o-words ----
    /// A macro line the controller cannot read (`#1=`, `IF[…]`, `o100 call`).
    MacroSyntax = "macro-syntax", Error;
    /// A value a macro cannot compute: division by zero, a function outside its domain, a variable number that is not whole.
    MacroValue = "macro-value", Error;
    /// A variable the controller does not have, cannot write, or a named parameter not yet defined.
    MacroVariable = "macro-variable", Error;
    /// A jump or call whose target is not in the text: program, sequence number, subroutine, loop end.
    JumpTarget = "jump-target", Error;
    /// Calls nested deeper than the controller (or `limits.call_depth`) allows.
    CallDepth = "call-depth", Error;
    /// More blocks run again by loops, jumps and calls than `limits.blocks`.
    BlockLimit = "block-limit", Error;
    /// The program raised its own alarm (`#3000 = n`).
    MacroAlarm = "macro-alarm", Error;
    /// M99 in the main program repeats it forever; the preview runs it `program.main_repeats` times.
    MainRepeats = "main-repeats", Info;
    /// A subprogram or subroutine ran to its end without M99/endsub.
    SubprogramEnd = "subprogram-end", Warning;
    // ---- thread cutting (G32 and shared) ----
    /// A thread block with no lead: no F/I in it or before it.
    MissingLead = "missing-lead", Error;
    /// Fanuc: a thread block without F takes the lead from a feed rate's F (one shared register).
    LeadFromFeed = "lead-from-feed", Warning;
    /// A thread block that does not move.
    ZeroLengthThread = "zero-length-thread", Error;
    /// The run-out length K is longer than the thread itself.
    RunoutTooLong = "runout-too-long", Error;
    /// Q on a later block of a continuous thread is ignored.
    QIgnored = "q-ignored", Warning;
    /// Run-out drawn by parameter No.107's speed rule.
    RunoutSpeed = "runout-speed", Info;
    /// More starts than the controller allows.
    TooManyStarts = "too-many-starts", Error;
    // ---- cycles ----
    /// G76/G78 without the thread height P(k).
    MissingThreadHeight = "missing-thread-height", Error;
    /// G76/G78 without the first depth Q(Δd).
    MissingFirstDepth = "missing-first-depth", Error;
    /// A threading cycle asked for a face thread (or a cut mostly along X).
    FaceThreadNotAllowed = "face-thread-not-allowed", Error;
    /// A cycle whose depth schedule needs more passes than `limits.passes_per_start`.
    PassLimit = "pass-limit", Error;
    /// A decimal point that does not change the unit (NO182.7 = 0 increments).
    DecimalPointIgnored = "decimal-point-ignored", Warning;
    /// The cycle's start point is not outside the thread.
    StartInsideThread = "start-inside-thread", Warning;
    /// A taper R(i) of the opposite sign to U that is larger than |U/2|: the cut would start beyond the start point.
    TaperBeyondStart = "taper-beyond-start", Error;
    /// A G71/G72 contour its cycle cannot rough: it goes back along the cut,
    /// or has pockets where the controller roughs type I only.
    ContourNotMonotone = "contour-not-monotone", Error;
    // ---- Renhe ----
    /// Renhe: absolute X or Z in a G32/G33 thread block.
    E18_03 = "E18-03", Error;
    /// Renhe: |W| must exceed |U| and 4 mm.
    E18_04 = "E18-04", Error;
    /// Renhe: no X feed (G00/G01) before the thread to set the run-out direction.
    E18_05 = "E18-05", Error;
    /// Spindle speed above the controller's advice for the pitch (Renhe n ≤ 2300/t − 60).
    SpindleSpeed = "spindle-speed", Warning;
    /// A pass on the same surface as others cuts another helix (lead, start angle or axial start).
    CrossThread = "cross-thread", Warning;
    // ---- LinuxCNC ----
    /// LinuxCNC: G33 or G76 while the spindle is not turning (no M3/M4, or after M5).
    SpindleNotTurning = "spindle-not-turning", Error;
    /// LinuxCNC: G76 or a G71/G72 profile cycle with cutter radius compensation (G41/G42, G41.1/G42.1) on.
    CutterCompActive = "cutter-comp-active", Error;
    /// LinuxCNC: the program ends without M2/M30 or a closing `%`.
    NoProgramEnd = "no-program-end", Error;
    /// LinuxCNC reads a value as another one: Q−1 as no Q, R below 1 as 1, E below 0 as 0, L as a bit mask, E without L.
    ValueReadAs = "value-read-as", Warning;
    /// LinuxCNC: a G33 K or G76 P that is zero or negative, passed on as the spindle sync ratio.
    OddPitch = "odd-pitch", Warning;
    /// LinuxCNC: G76 with a negative H drops the full-depth pass: the thread is never cut to K.
    FullDepthSkipped = "full-depth-skipped", Warning;
    /// LinuxCNC: G76 tapers E longer than half the drive line: the cut between them runs backwards.
    BackwardCut = "backward-cut", Warning;
    /// LinuxCNC: G33 or G76 outside the XZ plane G18 (accepted by the interpreter, not by the manual).
    PlaneNotXz = "plane-not-xz", Warning;
    /// LinuxCNC: a G70–G72 profile cycle outside the XZ plane G18, which the interpreter refuses.
    CycleNeedsXz = "cycle-needs-xz", Error;
    /// LinuxCNC: the profile of a G71/G72 that the interpreter refuses (it turns back along the
    /// cut, offset lines that do not meet) or roughs without end.
    ProfileRefused = "profile-refused", Error;
    /// LinuxCNC: G76 with an X or Y word: the passes still use the drive line; the word only moves the tool at the end.
    DriveLineKept = "drive-line-kept", Warning;
    /// LinuxCNC: a G76 whose degression and depths need many passes.
    ManyPasses = "many-passes", Warning;
    /// LinuxCNC: |I| + n·J rounds below |I| + K in floating point, so the full depth is cut twice.
    FloatExtraPass = "float-extra-pass", Info;
    /// LinuxCNC: G33 K is the advance along the move; on a taper the axial lead is less.
    LeadAlongPath = "lead-along-path", Info;
    // ---- shop floor ----
    /// Thread feed lead × n above the machine's limit (`machine.max_thread_feed`).
    ThreadFeedLimit = "thread-feed-limit", Warning;
    /// Spindle speed above the machine's (`machine.max_rpm`).
    SpindleLimit = "spindle-limit", Warning;
    /// A thread cut under G96: the speed changes with X.
    ThreadCss = "thread-css", Warning;
    /// The insert (`tool.insert`) is for the other side (internal/external).
    InsertSide = "insert-side", Warning;
    /// A full-profile insert made for another pitch.
    InsertPitch = "insert-pitch", Warning;
    /// A partial-profile insert whose range does not hold the pitch.
    InsertRange = "insert-range", Warning;
    /// A pass of a thread cut at another spindle speed than its first pass.
    SpeedBetweenPasses = "speed-between-passes", Warning;
    /// The tool's leading flank cuts into a shoulder at the end of a pass.
    ToolShoulder = "tool-shoulder", Warning;
    /// A pass starts inside the turned part: its infeed plunges into it in rapid.
    ApproachIntoPart = "approach-into-part", Warning;
    /// The helix asks for another shim than the holder's standard 1°.
    Shim = "shim", Info;
    /// The standard shim leaves the insert leaning off the helix by more than the makers' window: a flank rubs.
    ShimRub = "shim-rub", Warning;
    /// Lead-in δ1 shorter than n·L/500 (`machine.delta1_divisor`).
    Delta1Speed = "delta1-speed", Warning;
    /// Run-out δ2 shorter than n·L/1800 (`machine.delta2_divisor`).
    Delta2Speed = "delta2-speed", Warning;
    /// A first pass heavier than a constant-area share allows, or a pass over `tool.max_chip_area`.
    ChipHeavyFirst = "chip-heavy-first", Warning;
    /// A pass that deepens the thread by less than `chip.min_infeed`.
    ChipThin = "chip-thin", Info;
    /// A pass (not a spring pass) that removes nothing.
    ChipNone = "chip-none", Warning;
    /// The thread check: the pitch diameter cut is within the designation's limits.
    GaugeOk = "gauge-ok", Info;
    /// The thread check: the thread will not gauge (with the fix).
    GaugeFail = "gauge-fail", Warning;
    /// `thread.designation` (or the designation found) cannot be read or has no limits.
    BadDesignation = "bad-designation", Warning;
    // ---- textbook advice ----
    /// The crest diameter was not turned in the program and was assumed.
    CrestAssumed = "crest-assumed", Info;
    /// Total programmed depth differs from the 1.3·P rule.
    DepthVsStandard = "depth-vs-standard", Warning;
    /// More diagnostics than `limits.diagnostics`: the rest are counted, not listed.
    MoreDiagnostics = "more-diagnostics", Info;
    /// Programmed infeeds compared with table 4-3.
    InfeedGuidance = "infeed-guidance", Info;
    /// A pass infeed larger than table 4-3's largest for the pitch.
    InfeedTooLarge = "infeed-too-large", Warning;
    /// Lead-in δ1 or run-out δ2 shorter than the textbook advises.
    Clearance = "clearance", Warning;
}

impl Serialize for Code {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

impl std::fmt::Display for Code {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}
