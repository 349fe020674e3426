//! Issue #43, round 3: LDmicro files. Each test failed on the main branch
//! before the fix it names.

use std::process::Command;

use engine::runtime::ldmicro::printf::{Printf, PrintfError};

use crate::common::Temp;

/// Every format of the grid below, each value given to C as the type its
/// length modifier names, printed by this machine's C library: one line
/// `format TAB value TAB output` each.
const C_GRID: &str = r##"
#include <stdio.h>
#include <string.h>
int main(void) {
    static const int values[] = {0, 1, 7, 8, -1, -7, 255, 256, 300, -300, 32767,
        32768, 65535, 65536, 70000, -70000, 2147483647, -2147483647 - 1};
    static const char *flags[] = {"", "-", "+", " ", "0", "#", "#0", "-#", "+0",
        " 0", "#-", "+#", "0#+ -"};
    static const char *widths[] = {"", "1", "6"};
    static const char *precisions[] = {"", ".", ".0", ".1", ".4"};
    static const char *lengths[] = {"", "h", "hh", "l", "ll"};
    static const char convs[] = "diuxXoc";
    char f[64], out[256];
    for (unsigned a = 0; a < sizeof flags / sizeof *flags; a++)
    for (unsigned b = 0; b < sizeof widths / sizeof *widths; b++)
    for (unsigned c = 0; c < sizeof precisions / sizeof *precisions; c++)
    for (unsigned d = 0; d < sizeof lengths / sizeof *lengths; d++)
    for (unsigned e = 0; convs[e]; e++) {
        if (convs[e] == 'c' && d != 0) continue;
        snprintf(f, sizeof f, "<%%%s%s%s%s%c>", flags[a], widths[b], precisions[c],
                 lengths[d], convs[e]);
        for (unsigned v = 0; v < sizeof values / sizeof *values; v++) {
            int x = values[v];
            if (convs[e] == 'c' && x == 0) continue;
            if (!strcmp(lengths[d], "l")) snprintf(out, sizeof out, f, (long)x);
            else if (!strcmp(lengths[d], "ll")) snprintf(out, sizeof out, f, (long long)x);
            else snprintf(out, sizeof out, f, x);
            printf("%s\t%d\t%s\n", f, x, out);
        }
    }
    return 0;
}
"##;

/// Issue 43.6: STRING's text is C's printf, so every form docs/ldmicro.md
/// accepts prints what C prints: `#` with `%o` makes the first digit a 0
/// after the precision (`%#.5o` of 8 is `00010`, `%#.0o` of 0 is `0`);
/// `h` and `hh` convert the value to a short and a char first (`%hd` of
/// 70000 is 4464, `%hhu` of -1 is 255); `l` and `ll` print it as a long
/// and long long (`%lu` of -1). Checked against this machine's C library
/// where a C compiler is installed.
#[test]
fn string_printf_prints_what_c_prints_for_every_accepted_form() {
    let temp = Temp::new("r3-printf");
    let source = temp.file("grid.c", C_GRID);
    let binary = source.replace("grid.c", "grid");
    let built = Command::new("cc")
        .args(["-w", "-O0", "-o", &binary, &source])
        .status();
    if !matches!(built, Ok(s) if s.success()) {
        eprintln!("no C compiler: the printf grid is not compared");
        return;
    }
    let run = Command::new(&binary).output().expect("the grid runs");
    // A STRING holds one-byte characters, shown as Latin-1: C's bytes
    // are read so (`%c` of 255 is `ÿ`).
    let grid: String = run.stdout.iter().map(|&b| char::from(b)).collect();
    let mut wrong = Vec::new();
    let mut compared = 0;
    for line in grid.lines() {
        let mut parts = line.splitn(3, '\t');
        let (Some(format), Some(value), Some(c)) = (parts.next(), parts.next(), parts.next())
        else {
            continue;
        };
        let value: i64 = value.parse().expect("a value");
        let ours = Printf::parse(format)
            .map(|p| p.print(value))
            .unwrap_or_else(|e| format!("refused: {e}"));
        compared += 1;
        if ours != c {
            wrong.push(format!("{format} of {value}: C {c:?}, Hashigo {ours:?}"));
        }
    }
    assert!(compared > 50_000, "the grid ran ({compared} lines)");
    assert!(
        wrong.is_empty(),
        "{} of {compared} differ, e.g.\n{}",
        wrong.len(),
        wrong[..wrong.len().min(20)].join("\n")
    );
}

/// Issue 43.6: the same forms without a C compiler, as glibc prints them.
#[test]
fn octal_alternate_form_and_short_lengths_print_as_c() {
    let print = |f: &str, v: i64| Printf::parse(f).expect(f).print(v);
    assert_eq!(print("%#.5o", 8), "00010");
    assert_eq!(print("%#.0o", 0), "0");
    assert_eq!(print("%#.3o", 1), "001");
    assert_eq!(print("%#-6o|", 8), "010   |");
    assert_eq!(print("%hd", 70000), "4464");
    assert_eq!(print("%hhd", 300), "44");
    assert_eq!(print("%hhu", -1), "255");
    assert_eq!(print("%hx", -1), "ffff");
    assert_eq!(print("%#hho", 256), "0");
    assert_eq!(print("%.0hd", 65536), "");
    assert_eq!(print("%lu", -1), "18446744073709551615");
    assert_eq!(print("%llx", -2), "fffffffffffffffe");
}

/// Issue 43.6: a length C has no meaning for is refused, not printed as
/// a guess: `%hc`, `%lc` (a wide character), `%hhhd`, `%lld` is fine.
#[test]
fn lengths_c_does_not_define_are_refused() {
    for f in [
        "%hc", "%hhc", "%lc", "%llc", "%hhhd", "%lllx", "%hld", "%lhd",
    ] {
        assert!(
            matches!(Printf::parse(f), Err(PrintfError::Length(_))),
            "{f}: {:?}",
            Printf::parse(f)
        );
    }
    assert!(Printf::parse("%lld").is_ok());
}

/// An LDmicro file of `cycle` (its `CYCLE=` line, line 2) and a timer at
/// line 6.
fn cycle_file(cycle: &str) -> String {
    format!(
        "LDmicro0.2\nCYCLE={cycle}\nPROGRAM\nRUNG\n    CONTACTS Xa 0\n    TON Ton 100000\n    COIL Yb 0 0 0\nEND\n"
    )
}

/// Issue 43.13: a `CYCLE=` that is not a number, is 0, negative or huge
/// was read as 0 (`scan=0ms`, the timer blamed): it is refused at its
/// own line, saying what the line holds; the timer is not blamed.
#[test]
fn a_cycle_that_is_no_scan_period_is_refused_at_its_line() {
    for (cycle, says) in [
        ("abc", "CYCLE= holds \"abc\": not a number"),
        ("-5000", "CYCLE= holds \"-5000\": no scan period"),
        ("0", "CYCLE= holds \"0\": LDmicro's untimed cycle"),
        (
            "99999999999999999999999",
            "CYCLE= holds \"99999999999999999999999\": no scan period",
        ),
        ("10000001", "CYCLE= holds \"10000001\": no scan period"),
    ] {
        let errors = engine::formats::ldmicro::parse(&cycle_file(cycle)).expect_err(cycle);
        assert_eq!(errors.len(), 1, "{cycle}: {errors:?}");
        assert_eq!(errors[0].line, 2, "{cycle}");
        let text = errors[0].error.to_string();
        assert!(text.starts_with(says), "{cycle}: {text}");
    }
    // LDmicro's own forms still read: the number, then its tail.
    for (cycle, us) in [
        ("10000", 10_000),
        (" 2500", 2_500),
        ("+1000", 1_000),
        ("10000000", 10_000_000),
        (
            "5000 us at Timer1, YPlcCycleDuty:0, ConfigurationWord(s):0x0",
            5_000,
        ),
    ] {
        let file = engine::formats::ldmicro::parse(&cycle_file(cycle)).expect(cycle);
        assert_eq!(file.cycle_us, us, "{cycle}");
    }
}

/// Issue 43.13 through the CLI: `error: FILE:2: CYCLE= holds …`, and the
/// timer at line 6 is not blamed.
#[test]
fn hashigo_names_the_cycle_line_not_the_timer() {
    let temp = Temp::new("r3-cycle");
    let path = temp.file("cycle.ld", &cycle_file("abc"));
    let out = crate::common::hashigo(&["run", "--program", &path, "--until", "50ms"], "");
    let err = crate::common::text(&out.stderr);
    assert!(!out.status.success());
    assert!(
        err.contains("cycle.ld:2: CYCLE= holds \"abc\": not a number"),
        "{err}"
    );
    assert!(!err.contains(":6:"), "{err}");
}

/// A file whose names are used as two things: `msg` a STRING's text
/// (line 5), compared as a number (line 9) and read as a bit (line 13);
/// `Xa` a bit (line 4) added to as a number (line 14).
const CLASHES: &str = "LDmicro0.2\nPROGRAM\nRUNG\n  CONTACTS Xa 0\n  STRING msg n \"n=%d\"\nEND\n\
RUNG\n  CONTACTS Xa 0\n  EQU msg 3\n  COIL Yb 0 0 0\nEND\n\
RUNG\n  CONTACTS msg 0\n  ADD Xa Xa 1\nEND\n";

/// Issue 43.12: errors found after lowering said "rung R, row r, column
/// c" with internal names (`LD_STRING's D is a STRING`), and only the
/// first: every one is now at its own line in LDmicro's terms.
#[test]
fn names_used_as_two_things_are_said_at_each_line_in_ldmicros_terms() {
    let file = engine::formats::ldmicro::parse(CLASHES).expect("reads");
    let errors = engine::formats::ldmicro::to_ladder(&file).expect_err("clashes");
    let said: Vec<(usize, String)> = errors
        .iter()
        .map(|e| (e.line, e.error.to_string()))
        .collect();
    assert_eq!(
        said,
        vec![
            (
                9,
                "\"msg\" is a number for EQU here, but a STRING's text for STRING at line 5: one name cannot be both".to_string()
            ),
            (
                13,
                "\"msg\" is a bit for CONTACTS here, but a STRING's text for STRING at line 5: one name cannot be both".to_string()
            ),
            (
                14,
                "\"Xa\" is a number for ADD here, but a bit for CONTACTS at line 4: one name cannot be both".to_string()
            ),
        ]
    );
    let temp = Temp::new("r3-clash");
    let path = temp.file("clash.ld", CLASHES);
    let out = crate::common::hashigo(&["compile", "--program", &path], "");
    let err = crate::common::text(&out.stderr);
    assert!(!out.status.success());
    for line in [9, 13, 14] {
        assert!(err.contains(&format!("error: {path}:{line}: ")), "{err}");
    }
    assert!(!err.contains("rung") && !err.contains("LD_"), "{err}");
}

/// Issue 43.12: a variable named as the lowering names a timer's
/// instance (`T1_ld` beside `TON T1`) was "declared twice (first on line
/// 5)" — a line of the compiled IL: the instance now takes another name
/// and the file runs.
#[test]
fn a_name_like_an_instance_no_longer_clashes_with_it() {
    let text = "LDmicro0.2\nPROGRAM\nRUNG\n  CONTACTS Xa 0\n  TON T1 100000\nEND\n\
        RUNG\n  MOVE T1_ld 4\nEND\n";
    let file = engine::formats::ldmicro::parse(text).expect("reads");
    let ladder = engine::formats::ldmicro::to_ladder(&file).expect("a ladder");
    let il = engine::ladder::compile::compile(
        &ladder,
        engine::MachineId::SoftPlc,
        engine::ladder::compile::Options::default(),
    );
    assert!(il.is_ok(), "{il:?}");
}

/// Issue 43.12: what only the soft PLC finds (a file naming a BOOL the
/// lowering makes, `_ld0`) is said at the LDmicro line of the rung it
/// came from, `error: FILE:LINE:`, never at a rung and cell.
#[test]
fn what_the_soft_plc_refuses_is_said_at_the_ldmicro_line() {
    let text = "LDmicro0.2\nPROGRAM\nRUNG\n  CONTACTS Xa 0\n  PARALLEL\n    COIL Yb 0 0 0\n    SERIES\n      CONTACTS Xc 0\n      COIL Yd 0 0 0\n    END\n  END\n  ADD x x 1\nEND\n\
        RUNG\n  CONTACTS Xa 0\n  MOVE _ld0 7\nEND\n";
    let temp = Temp::new("r3-held");
    let path = temp.file("held.ld", text);
    let out = crate::common::hashigo(&["compile", "--program", &path], "");
    let err = crate::common::text(&out.stderr);
    assert!(!out.status.success());
    assert!(
        err.starts_with(&format!("error: {path}:16: the soft PLC cannot run this: ")),
        "{err}"
    );
    assert!(!err.contains("rung"), "{err}");
}

/// Issue 43.12: a number LDmicro refuses in an operand is said as its
/// element's, not as an internal "operand".
#[test]
fn a_bad_operand_is_said_as_its_elements() {
    let text = "LDmicro0.2\nPROGRAM\nRUNG\n  CONTACTS Xa 0\n  MOVE x 'AB'\nEND\n";
    let file = engine::formats::ldmicro::parse(text).expect("reads");
    let errors = engine::formats::ldmicro::to_ladder(&file).expect_err("refused");
    assert_eq!(errors[0].line, 5);
    assert_eq!(
        errors[0].error.to_string(),
        "MOVE: \"'AB'\" is not a number"
    );
}

/// A soft PLC project of an LDmicro file that counts scans in `n` and
/// prints it into the STRING `msg` (`n=%04d;`), with one case of
/// `expect`.
fn string_project(expect: &[&str]) -> String {
    let text = "LDmicro0.2\nCYCLE=10000\nPROGRAM\nRUNG\n  ADD n n 1\nEND\n\
        RUNG\n  STRING msg n 7 110 61 37 48 52 100 59\nEND\n";
    let file = engine::formats::ldmicro::parse(text).expect("reads");
    let ladder = engine::formats::ldmicro::to_ladder(&file).expect("a ladder");
    let mut project = engine::formats::Project::new(engine::MachineId::SoftPlc, ladder);
    project.tests.push(engine::cases::TestCase {
        name: "count".into(),
        events: String::new(),
        expect: expect.iter().map(|e| e.to_string()).collect(),
        hint: String::new(),
    });
    project.to_json()
}

/// Issue 43.15: a STRING is checked in a ladder test: `msg = 'n=0004;'
/// at 40ms`, `<>`, a text with spaces and `$` escapes; a wrong text fails
/// saying what the STRING held, quoted.
#[test]
fn a_ladder_test_checks_a_string_by_its_text() {
    let temp = Temp::new("r3-text-test");
    let path = temp.file(
        "count.json",
        &string_project(&[
            "msg = 'n=0004;' at 40ms",
            "msg <> 'n=0003;' at 40ms",
            "msg != '' at 40ms",
            "n = 4 at 40ms",
        ]),
    );
    let out = crate::common::hashigo(&["test", "--program", &path], "");
    let said = crate::common::text(&out.stdout);
    assert!(
        out.status.success(),
        "{said}{}",
        crate::common::text(&out.stderr)
    );
    assert!(said.contains("pass count"), "{said}");

    let path = temp.file("wrong.json", &string_project(&["msg = 'n=0003;' at 40ms"]));
    let out = crate::common::hashigo(&["test", "--program", &path], "");
    let said = crate::common::text(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{said}");
    assert!(
        said.contains("fail count: msg = 'n=0003;' at 40ms: msg was 'n=0004;' at 40ms"),
        "{said}"
    );
}

/// Issue 43.15: a text with spaces and escapes is one value; a text met
/// where a number is wanted (or the other way) fails saying so; a text
/// compared by order, or without its closing quote, is refused.
#[test]
fn text_expectations_read_as_iec_texts_and_refuse_what_they_cannot_mean() {
    use engine::cases::{ExpectError, Expectation, Want};
    let e = Expectation::parse("msg = 'a b$'c$$' at 1s").expect("reads");
    assert_eq!(
        e,
        Expectation::At {
            device: "msg".into(),
            op: engine::cases::Compare::Eq,
            value: Want::Text("a b'c$".into()),
            time: engine::SimTime::from_secs(1),
        }
    );
    assert_eq!(e.to_string(), "msg = 'a b$'c$$' at 1000ms");
    assert!(matches!(
        Expectation::parse("msg stays 'x y' from 0s to 1s"),
        Ok(Expectation::Stays { value: Want::Text(t), .. }) if t == "x y"
    ));
    assert_eq!(
        Expectation::parse("msg < 'a' at 1s"),
        Err(ExpectError::TextOrder("<"))
    );
    assert!(matches!(
        Expectation::parse("msg = 'abc at 1s"),
        Err(ExpectError::Text(_))
    ));
    assert!(matches!(
        Expectation::parse("msg = 'a$' at 1s"),
        Err(ExpectError::Text(_))
    ));

    // Kinds that do not meet: said, not a bare "was".
    let temp = Temp::new("r3-text-kind");
    let path = temp.file(
        "kind.json",
        &string_project(&["msg = 4 at 40ms", "n = 'n' at 40ms"]),
    );
    let out = crate::common::hashigo(&["test", "--program", &path], "");
    let said = crate::common::text(&out.stdout);
    assert!(
        said.contains("msg is a text ('n=0004;'): compare it with a text in quotes"),
        "{said}"
    );
}

/// Issue 43.12: every error at once — two refused elements in one rung,
/// one in another, and a name used as two things — each at its line, in
/// line order, and no error caused by another.
#[test]
fn every_error_of_a_file_is_said_at_once() {
    let text = "LDmicro0.2\nPROGRAM\nRUNG\n  CONTACTS Xa 0\n  PARALLEL\n    TIME2DELAY d 100\n    ADD x x 1\n  END\n  MOVE y 'AB'\nEND\n\
        RUNG\n  CONTACTS x 0\n  RANDOM r\nEND\n";
    let file = engine::formats::ldmicro::parse(text).expect("reads");
    let errors = engine::formats::ldmicro::to_ladder(&file).expect_err("refused");
    let lines: Vec<usize> = errors.iter().map(|e| e.line).collect();
    assert_eq!(lines, vec![6, 9, 12, 13], "{errors:?}");
    assert!(errors[0].error.to_string().starts_with("TIME2DELAY"));
    assert!(errors[1].error.to_string().starts_with("MOVE"));
    assert!(errors[2].error.to_string().starts_with("\"x\" is a bit"));
    assert!(errors[3].error.to_string().starts_with("RANDOM"));
}
