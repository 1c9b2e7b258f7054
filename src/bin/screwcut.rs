//! `screwcut`: plan a lathe threading program from the command line.

use std::io::Read;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use screwcut::diagnostic::Severity;
use screwcut::message::Lang;
use screwcut::num::fmt;
use screwcut::settings::{Kind, Settings};
use screwcut::{Code, Dialect};

#[path = "screwcut/compare.rs"]
mod compare;
#[path = "screwcut/embed.rs"]
mod embed;
#[path = "screwcut/summary.rs"]
mod summary;

#[derive(Parser)]
#[command(name = "screwcut", version, about = "Preview CNC lathe thread-cutting G-code: threads, passes and alarms")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Plan a program and print its threads, passes and diagnostics.
    Plan {
        /// Program file, or '-' for standard input.
        file: String,
        /// Controller dialect: gsk980tdc, fanuc0i, renhe or linuxcnc.
        #[arg(long, short, default_value = "gsk980tdc", value_parser = parse_dialect)]
        dialect: Dialect,
        /// Set a controller parameter or setting, e.g. --set No.058=55 (repeatable).
        #[arg(long = "set", short = 's', value_name = "NAME=VALUE")]
        set: Vec<String>,
        /// Print the plan as JSON.
        #[arg(long)]
        json: bool,
        /// Language of the summary and its diagnostics: en or zh (the JSON's messages stay English).
        #[arg(long, default_value = "en", value_parser = parse_lang)]
        lang: Lang,
    },
    /// List the settings and controller parameters of a dialect with their values.
    Settings {
        /// Controller dialect.
        #[arg(long, short, default_value = "gsk980tdc", value_parser = parse_dialect)]
        dialect: Dialect,
    },
    /// List every diagnostic code with its severity.
    Codes,
    /// Write a program's plan back block by block for a controller: every
    /// pass with its approach, cut, run-out, retract and return.
    Expand {
        /// Program file, or '-' for standard input.
        file: String,
        /// Dialect the program is written in.
        #[arg(long, short, default_value = "gsk980tdc", value_parser = parse_dialect)]
        dialect: Dialect,
        /// Dialect to write (default: the program's own).
        #[arg(long, value_parser = parse_dialect)]
        to: Option<Dialect>,
        /// Set a controller parameter or setting of the source dialect (repeatable).
        #[arg(long = "set", short = 's', value_name = "NAME=VALUE")]
        set: Vec<String>,
        /// Language of the notes: en or zh.
        #[arg(long, default_value = "en", value_parser = parse_lang)]
        lang: Lang,
    },
    /// Plan two programs and list, pass by pass, what differs (X, Z, depth,
    /// lead, start, infeed side, time). Exit 0 when they cut the same
    /// passes, 1 when not, 2 on an error.
    Compare {
        /// The first program, or '-' for standard input.
        a: String,
        /// The second program.
        b: String,
        /// Dialect of the first program.
        #[arg(long, short, default_value = "gsk980tdc", value_parser = parse_dialect)]
        dialect: Dialect,
        /// Dialect of the second program (default: the first's).
        #[arg(long = "dialect-b", value_parser = parse_dialect)]
        dialect_b: Option<Dialect>,
        /// Set a parameter or setting for both programs (repeatable).
        #[arg(long = "set", short = 's', value_name = "NAME=VALUE")]
        set: Vec<String>,
        /// Print the comparison as JSON.
        #[arg(long)]
        json: bool,
    },
    /// Write a threading program: a designation (or --major and --lead), its
    /// length (or --end-z), a controller and a form.
    Generate(GenerateArgs),
    /// Write a program as the HTML of a `<screwcut-preview>` element with its
    /// static drawings and pass table inside (the page shows them until the
    /// reader points at the element, and without JavaScript); alarms and
    /// warnings go to standard error.
    Embed(embed::EmbedArgs),
    /// Draw a program as a standalone SVG: the side section, one thread's
    /// tooth section or its starts.
    Svg {
        /// Program file, or '-' for standard input.
        file: String,
        /// Which drawing: side, tooth or starts.
        #[arg(long, default_value = "side", value_parser = ["side", "tooth", "starts"])]
        view: String,
        /// Controller dialect.
        #[arg(long, short, default_value = "gsk980tdc", value_parser = parse_dialect)]
        dialect: Dialect,
        /// Set a controller parameter or setting (repeatable).
        #[arg(long = "set", short = 's', value_name = "NAME=VALUE")]
        set: Vec<String>,
        /// Thread (1-based) of the tooth and starts drawings.
        #[arg(long, default_value_t = 1)]
        thread: usize,
        /// Start (1-based) of the tooth drawing.
        #[arg(long, default_value_t = 1)]
        start: u32,
        /// Width of the page in px.
        #[arg(long, default_value_t = 800.0)]
        width: f64,
        /// Height of the page in px.
        #[arg(long, default_value_t = 500.0)]
        height: f64,
        /// Stretch the radial scale to fill the height (the app's "Stretch radially").
        #[arg(long)]
        stretch: bool,
        /// Draw the roughing cuts of G71/G72 (the app's "Roughing"; hidden otherwise).
        #[arg(long)]
        roughing: bool,
        /// Language of the labels: en or zh.
        #[arg(long, default_value = "en", value_parser = ["en", "zh"])]
        lang: String,
        /// The view's world → page transform `SX,SY,TX,TY` (page x = TX + SX·z,
        /// page y = TY − SY·r; a view's zoom and pan as the app keeps them);
        /// without it, the drawing and its labels are fitted to the page.
        #[arg(long, value_name = "SX,SY,TX,TY", value_parser = parse_transform)]
        transform: Option<screwcut::draw::Transform>,
    },
}

#[derive(clap::Args)]
struct GenerateArgs {
    /// Thread designation: M30x2-6g, M20x1.5-6H, 1/2-13 UNC-2A, 1/2-14 NPT...
    designation: Option<String>,
    /// Major diameter (mm), without a designation.
    #[arg(long)]
    major: Option<f64>,
    /// Lead (mm), without a designation.
    #[arg(long)]
    lead: Option<f64>,
    /// Thread length (mm), from --start-z towards -Z.
    #[arg(long)]
    length: Option<f64>,
    /// Z where the thread starts.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    start_z: f64,
    /// Z where the thread ends (instead of --length).
    #[arg(long, allow_negative_numbers = true)]
    end_z: Option<f64>,
    /// Internal thread.
    #[arg(long, conflicts_with = "external")]
    internal: bool,
    /// External thread (the default without a designation).
    #[arg(long)]
    external: bool,
    /// Number of starts.
    #[arg(long)]
    starts: Option<u32>,
    /// Nose radius of the threading tool (mm; 0 = sharp).
    #[arg(long, default_value_t = 0.0)]
    nose_radius: f64,
    /// Highest spindle speed (rev/min).
    #[arg(long, default_value_t = 1000.0)]
    max_rpm: f64,
    /// Highest thread feed, lead × speed (mm/min).
    #[arg(long, default_value_t = 3000.0)]
    max_feed: f64,
    /// Target controller.
    #[arg(long, short, default_value = "gsk980tdc", value_parser = parse_dialect)]
    dialect: Dialect,
    /// Form: g32, g92, g76, g78 (GSK), renhe_g33, g33 or linuxcnc_g76 (LinuxCNC).
    #[arg(long, short, default_value = "g32", value_parser = parse_form)]
    form: screwcut::wizard::Form,
    /// Language of the notes and of a refusal: en or zh.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    lang: Lang,
}

fn parse_form(s: &str) -> Result<screwcut::wizard::Form, String> {
    use screwcut::wizard::Form;
    Form::parse(s).ok_or_else(|| {
        format!("unknown form '{s}' ({})", Form::ALL.iter().map(|f| f.name()).collect::<Vec<_>>().join(", "))
    })
}

fn generate(a: GenerateArgs) -> ExitCode {
    let internal = if a.internal {
        Some(true)
    } else if a.external {
        Some(false)
    } else {
        None
    };
    let r = screwcut::wizard::Request {
        designation: a.designation,
        major: a.major,
        lead: a.lead,
        starts: a.starts,
        internal,
        start_z: a.start_z,
        end_z: a.end_z,
        length: a.length,
        nose_radius: a.nose_radius,
        max_rpm: a.max_rpm,
        max_feed: a.max_feed,
        dialect: a.dialect,
        form: a.form,
    };
    match screwcut::wizard::generate(&r) {
        Ok(g) => {
            for n in &g.notes {
                eprintln!("screwcut: note: {}", n.render(a.lang));
            }
            emit(&g.program);
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("screwcut: {}", e.render(a.lang));
            ExitCode::from(2)
        }
    }
}

fn parse_lang(s: &str) -> Result<Lang, String> {
    Lang::parse(s).ok_or_else(|| format!("unknown language '{s}' (en, zh)"))
}

fn parse_dialect(s: &str) -> Result<Dialect, String> {
    Dialect::parse(s).ok_or_else(|| format!("unknown dialect '{s}' ({})", Dialect::names()))
}

/// The transform of `screwcut svg --transform`: four numbers, positive scales.
fn parse_transform(s: &str) -> Result<screwcut::draw::Transform, String> {
    let v: Vec<f64> =
        s.split(',').map(|x| x.trim().parse::<f64>()).collect::<Result<_, _>>().map_err(|e| format!("'{s}': {e}"))?;
    let [sx, sy, tx, ty] = v[..] else { return Err(format!("'{s}' is not four numbers SX,SY,TX,TY")) };
    let t = screwcut::draw::Transform { sx, sy, tx, ty };
    if t.is_valid() { Ok(t) } else { Err(format!("'{s}': the scales must be positive and every number finite")) }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Plan { file, dialect, set, json, lang } => plan(&file, dialect, &set, json, lang),
        Command::Expand { file, dialect, to, set, lang } => expand(&file, dialect, to.unwrap_or(dialect), &set, lang),
        Command::Generate(a) => generate(a),
        Command::Embed(a) => embed::embed(a),
        Command::Compare { a, b, dialect, dialect_b, set, json } => {
            compare_files(&a, &b, dialect, dialect_b.unwrap_or(dialect), &set, json)
        }
        Command::Svg { file, view, dialect, set, thread, start, width, height, stretch, roughing, lang, transform } => {
            let (settings, text) = match input(&file, dialect, &set) {
                Ok(v) => v,
                Err(code) => return code,
            };
            let plan = screwcut::plan(&text, &settings);
            let ti = thread.max(1) - 1;
            let scene = match view.as_str() {
                "tooth" => screwcut::diagram::tooth(&plan, ti, start.max(1)),
                "starts" => screwcut::diagram::starts(&plan, ti),
                _ => Some(screwcut::diagram::side(&plan)),
            };
            let Some(scene) = scene else {
                eprintln!(
                    "screwcut: {file} has no thread {thread} to draw the {view} view of ({} threads)",
                    plan.threads.len()
                );
                return ExitCode::from(2);
            };
            let lang = Lang::parse(&lang).unwrap_or_default();
            let v = screwcut::draw::View {
                width,
                height,
                stretch,
                thread: ti,
                lang,
                transform,
                roughing,
                ..Default::default()
            };
            if let Err(e) = v.validate() {
                eprintln!("screwcut: cannot draw the {view} view: {e}");
                return ExitCode::from(2);
            }
            emit(&screwcut::svg::svg(&scene, &v));
            ExitCode::SUCCESS
        }
        Command::Settings { dialect } => {
            let s = Settings::new(dialect);
            let mut out = String::new();
            for (def, v) in s.entries() {
                let value = match def.kind {
                    Kind::Choice(c) => c.get(v as usize).copied().unwrap_or("?").to_string(),
                    _ => fmt(v),
                };
                out += &format!("{:<24} {:<10} {:<12} {}\n", def.name, value, def.unit, def.help);
            }
            for (def, v) in s.text_entries() {
                out += &format!("{:<24} {:<10} {:<12} {}\n", def.name, format!("'{v}'"), "text", def.help);
            }
            emit(&out);
            ExitCode::SUCCESS
        }
        Command::Codes => {
            let mut out = String::new();
            for c in Code::ALL {
                out += &format!("{:<28} {}\n", c.as_str(), c.severity().name());
            }
            emit(&out);
            ExitCode::SUCCESS
        }
    }
}

/// The settings of `dialect` with `set` applied, and the program text; `Err` is the exit code (2).
fn input(file: &str, dialect: Dialect, set: &[String]) -> Result<(Settings, String), ExitCode> {
    let mut settings = Settings::new(dialect);
    for a in set {
        if let Err(e) = settings.assign(a) {
            eprintln!("screwcut: {e}");
            return Err(ExitCode::from(2));
        }
    }
    let mut bytes = Vec::new();
    let read = if file == "-" {
        std::io::stdin().read_to_end(&mut bytes).map(|_| ())
    } else {
        std::fs::read(file).map(|b| bytes = b)
    };
    if let Err(e) = read {
        eprintln!("screwcut: cannot read {file}: {e}");
        return Err(ExitCode::from(2));
    }
    // Programs from old controllers are not always UTF-8: read them lossily rather than refuse.
    Ok((settings, String::from_utf8_lossy(&bytes).into_owned()))
}

fn expand(file: &str, dialect: Dialect, to: Dialect, set: &[String], lang: Lang) -> ExitCode {
    let (settings, text) = match input(file, dialect, set) {
        Ok(v) => v,
        Err(code) => return code,
    };
    let plan = screwcut::plan(&text, &settings);
    let alarms = plan.diagnostics.iter().filter(|d| d.severity == Severity::Error).count();
    if alarms > 0 {
        eprintln!("screwcut: note: {file} has {alarms} alarm(s): the blocks with an alarm are not in the expansion");
    }
    let e = screwcut::expand::expand(&plan, to);
    for n in &e.notes {
        eprintln!("screwcut: note: {}", n.render(lang));
    }
    emit(&e.program);
    ExitCode::SUCCESS
}

fn compare_files(a: &str, b: &str, da: Dialect, db: Dialect, set: &[String], json: bool) -> ExitCode {
    let read = |file: &str, d: Dialect| input(file, d, set).map(|(s, text)| screwcut::plan(&text, &s));
    let (pa, pb) = match (read(a, da), read(b, db)) {
        (Ok(x), Ok(y)) => (x, y),
        (Err(code), _) | (_, Err(code)) => return code,
    };
    let c = screwcut::compare::compare(&pa, &pb);
    if json {
        let v = serde_json::json!({ "same": c.same(), "a": a, "b": b, "comparison": c });
        emit(&(v.to_string() + "\n"));
    } else {
        emit(&compare::text(&c, a, b));
    }
    if c.same() { ExitCode::SUCCESS } else { ExitCode::from(1) }
}

fn plan(file: &str, dialect: Dialect, set: &[String], json: bool, lang: Lang) -> ExitCode {
    let (settings, text) = match input(file, dialect, set) {
        Ok(v) => v,
        Err(code) => return code,
    };
    let mut plan = screwcut::plan(&text, &settings);
    screwcut::hint::add(&text, &settings, &mut plan, screwcut::hint::MAX_BYTES);
    emit(&if json { plan.to_json() + "\n" } else { summary::summary(&plan, file, lang) });
    if plan.has_alarm() { ExitCode::from(1) } else { ExitCode::SUCCESS }
}

/// Writes to standard output; a closed pipe (`| head`) is not worth a panic.
fn emit(text: &str) {
    let _ = std::io::Write::write_all(&mut std::io::stdout().lock(), text.as_bytes());
}
