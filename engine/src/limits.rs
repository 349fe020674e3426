//! Hard limits on what the engine accepts from outside (docs/limits.md).
//!
//! Programs, projects, share links and PLCopen files come from other
//! people, and the same code runs in the page, where a stack overflow or an
//! allocation failure kills the tab. Each limit is checked before the work
//! it guards starts and is reported as an ordinary located error.

/// The largest text file any reader takes (program, project, PLCopen
/// file, events): 16 MiB.
pub const MAX_INPUT_BYTES: usize = 16 << 20;

/// Steps (edges and points visited) lowering a PLCopen file's boolean
/// blocks may take in all: a real file takes a few thousand; a hostile one
/// with thousands of blocks is refused instead of taking minutes.
pub const MAX_GATE_WORK: usize = 10_000_000;

/// BOOLs (`_h0` …) the PLCopen reader may add on the soft PLC to hold a
/// network's power where a gate's input is needed twice (the bit
/// machines take spare relays there): far more than a real file needs.
pub const MAX_SOFT_HELPERS: usize = 1024;

/// How many PLCopen connectors one wire may pass through, each
/// continuation feeding the next connector (followed recursively): real
/// files pass one or two.
pub const MAX_CONNECTOR_CHAIN: usize = 64;

/// How deeply PLCopen XML elements may nest. Real files nest about 12 deep.
pub const MAX_XML_DEPTH: usize = 256;

/// Attributes on one XML element. PLCopen elements carry at most a
/// handful (the real projects six); the limit keeps a hostile element
/// from being built before it is refused.
pub const MAX_XML_ATTRIBUTES: usize = 256;

/// Entries of one LDmicro table (a look-up table's values, a
/// piecewise-linear table's points, a string's characters, a shift
/// register's stages): LDmicro's own editor takes a few dozen.
pub const MAX_LD_TABLE: usize = 1024;

/// Rungs in one ladder.
pub const MAX_RUNGS: usize = 10_000;

/// Test cases in one project.
pub const MAX_TEST_CASES: usize = 1_000;

/// Samples a project's test cases may take in all, counted before any
/// runs: every instant the machine runs to plus every look at an
/// expectation (a window looks every millisecond). One hour of a window
/// is 7 200 000; the work runs at tens of millions a second.
pub const MAX_TEST_WORK: u64 = 100_000_000;

/// Expectation lines in one test case.
pub const MAX_EXPECTATIONS: usize = 10_000;

/// Entries in one of a project's tables of names (its settings, its device
/// comments): a machine has at most a few thousand devices.
pub const MAX_MAP_ENTRIES: usize = 100_000;

/// Cells a rung's grid may span: rows × columns of its bounding box. A
/// single row of 20 000 contacts fits; a 6 000 × 6 000 layout does not.
pub const MAX_RUNG_CELLS: usize = 1 << 20;

/// How deeply series and parallel blocks may nest inside one rung. Every
/// walk over a rung's logic is bounded by this; hand-drawn rungs nest a
/// handful of levels.
pub const MAX_NESTING: usize = 100;

/// Lines of one program text (the machines hold at most a few thousand
/// instructions; the rest is comments).
pub const MAX_PROGRAM_LINES: usize = 100_000;

/// Parentheses, `LOW(`/`HIGH(` and unary minus nested in one AVR
/// assembler expression.
pub const MAX_EXPRESSION_DEPTH: usize = 64;

/// Lines of one events file.
pub const MAX_EVENTS: usize = 1_000_000;

/// Values one `hashigo run` prints: rows × watched devices.
pub const MAX_CSV_VALUES: u64 = 50_000_000;

/// The longest simulated time a run, a step or a setting may reach, in
/// seconds: 10 000 000 s (about 116 days), far below the clock's 584-year
/// range, so sums of simulated times never overflow
/// ([`crate::time::MAX_SIM_TIME`] is the same as a time).
pub const MAX_SIM_SECONDS: u64 = 10_000_000;

/// The longest share link fragment the decoder takes: 64 KiB.
pub const MAX_SHARE_FRAGMENT: usize = 64 << 10;

/// How much of a user's token an error message repeats.
pub const MAX_ECHO_CHARS: usize = 40;

/// Checks a program text's line count against [`MAX_PROGRAM_LINES`]
/// before any line is parsed: `Err((first line past the limit, lines))`.
pub fn check_program_lines(text: &str) -> Result<(), (usize, usize)> {
    let lines = text.lines().count();
    if lines > MAX_PROGRAM_LINES {
        return Err((MAX_PROGRAM_LINES + 1, lines));
    }
    Ok(())
}
