//! Issue #44.3: the forms LDmicro's own reader accepts for the elements
//! docs/ldmicro.md lists, as LDmicro 4.x writes them, run as LDmicro runs
//! them; a form LDmicro itself refuses stays refused.

use engine::formats::ldmicro::{parse, to_ladder};
use engine::plc::Plc;
use engine::SimTime;

use crate::run::{get, load, program, set};

/// Runs to `ms` milliseconds.
fn run_to(plc: &mut dyn Plc, ms: u64) {
    plc.run_until(SimTime::from_millis(ms));
}

/// `TIME2COUNT name delay adjust`, as LDmicro 4.x saves it (its timer
/// line, adjust last): read, the adjust ignored as LDmicro's reader
/// ignores it; the count is the delay's cycles.
#[test]
fn time2count_with_its_adjust_field_runs() {
    let text =
        program("RUNG\n    TIME2COUNT n 100000 0\nEND\nRUNG\n    TIME2COUNT m 50000 -1\nEND\n");
    let mut plc = load(&text);
    run_to(plc.as_mut(), 25);
    assert_eq!(get(plc.as_ref(), "n"), 10, "100 ms of 10 ms cycles");
    assert_eq!(get(plc.as_ref(), "m"), 5, "the adjust read and ignored");
    // A field that is no number, or a fourth, is no form LDmicro writes.
    for bad in ["TIME2COUNT n 100000 x", "TIME2COUNT n 100000 0 0"] {
        let e = parse(&program(&format!("RUNG\n    {bad}\nEND\n"))).expect_err(bad);
        assert_eq!(
            e[0].error.to_string(),
            "TIME2COUNT takes name delay [adjust]"
        );
    }
}

/// `PERSIST` in a parallel group beside boxes passes power through, as in
/// LDmicro: the branch is a wire, the ADD beside it still runs on the
/// rung's power, and the coil after the group follows the contact.
#[test]
fn persist_in_a_branch_beside_boxes_passes_power() {
    let text = program(
        "RUNG\n    CONTACTS Xa 0\n    PARALLEL\n        PERSIST saved\n        ADD saved saved 1\n    END\n    COIL Yq 0 0 0\nEND\n",
    );
    let mut plc = load(&text);
    run_to(plc.as_mut(), 25);
    assert_eq!(get(plc.as_ref(), "Yq"), 0);
    assert_eq!(get(plc.as_ref(), "saved"), 0);
    set(plc.as_mut(), "Xa", 1);
    run_to(plc.as_mut(), 55);
    assert_eq!(
        get(plc.as_ref(), "Yq"),
        1,
        "power passes the PERSIST branch"
    );
    assert_eq!(get(plc.as_ref(), "saved"), 3, "the ADD ran each scan");
    // Written back, it reads again as the same ladder, `saved` kept.
    let ladder = to_ladder(&parse(&text).expect("read")).expect("a ladder");
    let out = engine::formats::ldmicro::export(&ladder, 10_000).expect("written");
    let again = to_ladder(&parse(&out).expect("read again")).expect("a ladder again");
    assert_eq!(again.rungs, ladder.rungs, "{out}");
    assert!(again
        .variables
        .iter()
        .any(|v| v.name == "saved" && v.retain));
    // And in series between a contact and a coil.
    let text = program("RUNG\n    CONTACTS Xa 0\n    PERSIST saved\n    COIL Yq 0 0 0\nEND\n");
    let mut plc = load(&text);
    set(plc.as_mut(), "Xa", 1);
    run_to(plc.as_mut(), 15);
    assert_eq!(get(plc.as_ref(), "Yq"), 1);
}

/// Numbers as LDmicro's `IsNumber` and `hobatoi` read them: one sign,
/// hexadecimal wrapping in 32 bits, a leading 0 octal, digits up to the
/// first that is none; `--5` is a name (LDmicro's `IsNumber` says so).
#[test]
fn numbers_read_as_ldmicro_reads_them() {
    let moves = [
        ("a", "+7", 7),
        ("b", "0xFFFFFFFF", -1),
        ("c", "-0x10", -16),
        ("d", "010", 8),
        ("e", "12abc", 12),
        ("f", "0x80000000", i64::from(i32::MIN)),
        ("g", "'A'", 65),
    ];
    let mut body = String::new();
    for (dest, src, _) in moves {
        body.push_str(&format!("RUNG\n    MOVE {dest} {src}\nEND\n"));
    }
    // Into 4-byte variables, so that no width wraps them.
    let vars: String = moves
        .iter()
        .map(|(d, _, _)| format!("    4 bytes {d}\n"))
        .collect();
    let text = program(&body).replace("PROGRAM\n", &format!("VAR LIST\n{vars}END\n\nPROGRAM\n"));
    let mut plc = load(&text);
    run_to(plc.as_mut(), 15);
    for (dest, src, want) in moves {
        assert_eq!(get(plc.as_ref(), dest), want, "MOVE {dest} {src}");
    }
    // `--5` is a variable's name in LDmicro, not 5.
    let text = program("RUNG\n    MOVE x --5\nEND\n");
    let file = parse(&text).expect("read");
    let ladder = to_ladder(&file).expect("a ladder");
    assert!(
        ladder
            .variables
            .iter()
            .any(|v| v.comment.contains("LDmicro name: --5")),
        "{:?}",
        ladder.variables
    );
    // Quotes around two characters: LDmicro's compiler refuses them.
    let text = program("RUNG\n    MOVE x 'AB'\nEND\n");
    let file = parse(&text).expect("read");
    assert!(to_ladder(&file).is_err());
}

/// A table's entries are numbers as `hobatoi` reads them (`0x10`, `'A'`,
/// `7abc` is 7); an entry that is no number at all (`abc`, which
/// LDmicro's `hobatoi` would silently read as 0) is refused at its line.
#[test]
fn table_entries_read_as_hobatoi_and_a_word_is_refused() {
    let file = parse(&program(
        "RUNG\n    LOOK_UP_TABLE d i 3 0 0x10 'A' 7abc\nEND\n",
    ))
    .expect("read");
    let values = file.elements().find_map(|(e, _)| match e {
        engine::formats::ldmicro::Element::LookUpTable { values, .. } => Some(values.clone()),
        _ => None,
    });
    assert_eq!(values, Some(vec![16, 65, 7]));
    let e = parse(&program("RUNG\n    LOOK_UP_TABLE d i 2 0 5 abc\nEND\n")).expect_err("a word");
    assert_eq!(
        e[0].error.to_string(),
        "LOOK_UP_TABLE: \"abc\" is not a number"
    );
}
