//! LDmicro's `STRING dest var text` on the soft PLC (issue #32): while
//! its rung has power, `dest` takes the text with `var` printed in it as
//! C's `sprintf` prints it; the text is kept while it has none; `dest` is
//! a STRING the watch, the CLI and time travel show; the element goes
//! back out as `.ld`; a text C would read another argument for is
//! refused at its line.

use engine::formats::ldmicro::{parse, to_ladder};
use engine::plc::{Plc, Value};
use engine::SimTime;

use crate::common::{hashigo, text, Temp};
use crate::run::{load, program, set};

/// `Xa` powers a STRING printing `n` into `msg` ("n=%04d;" as the
/// codes 110 61 37 48 52 100 59); `n` counts the scans.
const COUNT: &str = "RUNG 1\n  ADD n n 1\nEND\n\
    RUNG 2\n  CONTACTS Xa 0\n  STRING msg n 7 110 61 37 48 52 100 59\nEND\n\
    RUNG 3\n  STRING hi (none) 8 72 105 32 49 48 48 37 37\nEND\n";

fn read_text(plc: &dyn Plc, name: &str) -> Value {
    plc.read(plc.device(name).expect(name))
}

fn string(text: &str) -> Value {
    Value::Text(std::sync::Arc::new(text.to_string()))
}

#[test]
fn a_string_prints_its_variable_while_powered_and_keeps_its_text_after() {
    let mut plc = load(&program(COUNT));
    plc.run_until(SimTime::from_millis(25));
    // Unpowered from the start: nothing printed yet; the constant text
    // of a rung always powered is there from the first scan.
    assert_eq!(read_text(plc.as_ref(), "msg"), string(""));
    assert_eq!(read_text(plc.as_ref(), "hi"), string("Hi 100%"));
    set(plc.as_mut(), "Xa", 1);
    plc.run_until(SimTime::from_millis(35));
    let shown = read_text(plc.as_ref(), "msg");
    let n = plc.read(plc.device("n").expect("n")).as_i64();
    assert_eq!(shown, string(&format!("n={n:04};")));
    set(plc.as_mut(), "Xa", 0);
    plc.run_until(SimTime::from_millis(85));
    assert_eq!(
        read_text(plc.as_ref(), "msg"),
        shown,
        "kept while the rung is off, as the variable keeps it"
    );
    assert!(plc.read(plc.device("n").expect("n")).as_i64() > n);
}

#[test]
fn a_recording_gives_back_each_scans_text() {
    let mut plc = load(&program(COUNT));
    set(plc.as_mut(), "Xa", 1);
    let msg = plc.device("msg").expect("msg");
    let mut images = Vec::new();
    for scan in 1..=3u64 {
        plc.run_until(SimTime::from_millis(10 * scan + 5));
        let mut image = Vec::new();
        plc.image_into(&mut image);
        images.push((image, plc.read(msg)));
    }
    assert_ne!(images[0].1, images[2].1, "the text changes each scan");
    for (image, shown) in &images {
        assert_eq!(plc.read_image(image, msg).as_ref(), Some(shown));
    }
}

#[test]
fn the_cli_watches_a_string_and_quotes_it_where_csv_needs() {
    let tmp = Temp::new("ldstring");
    let ld = tmp.file(
        "count.ld",
        &program("RUNG 1\n  STRING msg (none) 8 97 44 32 34 98 34 32 99\nEND\n"),
    );
    let out = hashigo(
        &["run", "--program", &ld, "--until", "20ms", "--watch", "msg"],
        "",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    // Empty before the first scan; then `a, "b" c`, which holds a comma
    // and quotes: one quoted CSV field.
    assert_eq!(
        text(&out.stdout),
        "time_ms,msg\n0,\n20,\"a, \"\"b\"\" c\"\n"
    );
}

#[test]
fn a_string_goes_back_out_as_the_line_it_was() {
    let text = program(COUNT);
    let ladder = to_ladder(&parse(&text).expect("reads")).expect("lowers");
    let out = engine::formats::ldmicro::export(&ladder, 10_000).expect("exports");
    assert!(
        out.contains("STRING msg n 7 110 61 37 48 52 100 59\n"),
        "{out}"
    );
    assert!(
        out.contains("STRING hi (none) 8 72 105 32 49 48 48 37 37\n"),
        "{out}"
    );
    let back = to_ladder(&parse(&out).expect("reads")).expect("lowers");
    assert_eq!(back.rungs, ladder.rungs);
    let msg = back
        .variables
        .iter()
        .find(|v| v.name == "msg")
        .expect("declared");
    assert_eq!(msg.data_type, "STRING");
}

#[test]
fn a_text_c_would_read_another_argument_for_is_refused_at_its_line() {
    for (body, says) in [
        // "%s": a string argument.
        ("  STRING s v 2 37 115", "STRING: `%s` prints no integer"),
        // "%d %d": two.
        (
            "  STRING s v 5 37 100 32 37 100",
            "STRING: a second %: STRING prints one variable",
        ),
        // "%d" with no variable.
        (
            "  STRING s (none) 2 37 100",
            "STRING: the text prints a value (%…) but no variable is named",
        ),
    ] {
        let text = format!("LDmicro0.2\nCYCLE=10000\n\nPROGRAM\nRUNG 1\n{body}\nEND\n");
        let errors = to_ladder(&parse(&text).expect("reads")).expect_err("refused");
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert_eq!(errors[0].line, 6);
        let said = errors[0].error.to_string();
        assert!(said.starts_with(says), "{said}");
    }
}

#[test]
fn a_string_ladder_reads_back_from_its_il_and_its_plcopen_file() {
    use engine::ladder::compile::{compile, Options};
    use engine::machines::{decompile, Source};
    use engine::MachineId;
    // A coil after the box: the IL read-back needs a rung to end in one
    // (docs/ldmicro.md).
    let coiled =
        "RUNG 1\n  CONTACTS Xa 0\n  STRING msg n 7 110 61 37 48 52 100 59\n  COIL Yq 0 0 0\nEND\n";
    let ladder = to_ladder(&parse(&program(coiled)).expect("reads")).expect("lowers");
    let il = compile(&ladder, MachineId::SoftPlc, Options::default()).expect("compiles");
    let loaded = engine::softplc::Program::load(&il).expect("loads");
    let back = decompile(Source::Soft(&loaded)).expect("decompiles");
    let again = compile(&back, MachineId::SoftPlc, Options::default()).expect("recompiles");
    assert_eq!(again, il);
    let xml = engine::formats::plcopen::export(&ladder, "strings").expect("exports");
    assert!(
        xml.contains("<variable name=\"msg\"><type><string/></type>"),
        "{xml}"
    );
    // A rung whose box stands on a wire from the rail goes out too, its
    // input on the rail (LDmicro's rungs often start with one).
    let plain = to_ladder(&parse(&program(COUNT)).expect("reads")).expect("lowers");
    let xml_plain = engine::formats::plcopen::export(&plain, "count").expect("exports");
    let mut counted = engine::machines::new_plc(MachineId::SoftPlc);
    let il_plain = engine::formats::plcopen::Document::read(&xml_plain)
        .and_then(|document| document.soft_program(None))
        .expect("imports");
    counted.load_text(&il_plain.text).expect("runs");
    counted.run_until(SimTime::from_millis(35));
    assert_eq!(read_text(counted.as_ref(), "hi"), string("Hi 100%"));
    assert_eq!(counted.read(counted.device("n").expect("n")).as_i64(), 3);
    // Opened as a ladder, the box keeps its text.
    let opened = engine::formats::plcopen::Document::read(&xml)
        .and_then(|document| document.import(Some(MachineId::SoftPlc), None, None))
        .map(|i| i.ladder)
        .expect("opens");
    let il_again = compile(&opened, MachineId::SoftPlc, Options::default()).expect("compiles");
    assert!(il_again.contains("FMT := 'n=%04d;'"), "{il_again}");
    let from_xml = engine::formats::plcopen::Document::read(&xml)
        .and_then(|document| document.soft_program(None))
        .expect("imports");
    let mut plc = engine::machines::new_plc(MachineId::SoftPlc);
    plc.load_text(&from_xml.text).expect("runs");
    set(plc.as_mut(), "Xa", 1);
    plc.run_until(SimTime::from_millis(15));
    assert_eq!(read_text(plc.as_ref(), "msg"), string("n=0000;"));
}

#[test]
fn a_string_ladder_travels_in_a_share_link_and_a_project_file() {
    use engine::formats::project::Project;
    use engine::formats::share;
    let ladder = to_ladder(&parse(&program(COUNT)).expect("reads")).expect("lowers");
    let project = Project::new(engine::MachineId::SoftPlc, ladder);
    let link = share::encode(&project).expect("encodes");
    assert_eq!(share::decode(&link), Ok(project.clone()));
    let again = Project::from_json(&project.to_json()).expect("reads back");
    assert_eq!(again.ladder, project.ladder);
}
