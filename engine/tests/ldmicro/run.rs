//! LDmicro files run on the soft PLC (issue #32): how many of the
//! workplace's real files run and why the others do not, and several by
//! behaviour against what LDmicro's manual says they do — a cyclic timer
//! pair, a 7-segment display, a retentive timer, a counter, arithmetic,
//! the master relay, a shift register and a look-up table.

use engine::events::InputValue;
use engine::formats::ldmicro::{decode, parse, to_ladder};
use engine::ladder::compile::{compile, Options};
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::{MachineId, SimTime};

use crate::common::{hashigo, text, Temp};

pub(crate) const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/fixtures/ldmicro");

/// An `.ld` text loaded on a soft PLC scanning at the file's cycle.
pub(crate) fn load(text: &str) -> Box<dyn Plc> {
    let file = parse(text).unwrap_or_else(|e| panic!("{e:?}"));
    let ladder = to_ladder(&file).unwrap_or_else(|e| panic!("{e:?}"));
    let il = compile(&ladder, MachineId::SoftPlc, Options::default())
        .unwrap_or_else(|e| panic!("{e:?}"));
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.apply(Command::Setting {
        name: "scan".into(),
        value: format!("{}us", file.cycle_us),
    })
    .expect("scan");
    plc.load_text(&il).unwrap_or_else(|e| panic!("{e}\n{il}"));
    plc
}

pub(crate) fn real(name: &str) -> Option<String> {
    std::fs::read(format!("{REAL}/{name}"))
        .ok()
        .map(|b| decode(&b).into_owned())
}

pub(crate) fn set(plc: &mut dyn Plc, name: &str, v: i64) {
    let d = plc.device(name).expect(name);
    plc.apply(Command::SetInput(d, InputValue::Int(v)))
        .expect(name);
}

pub(crate) fn get(plc: &dyn Plc, name: &str) -> i64 {
    plc.read(plc.device(name).expect(name)).as_i64()
}

/// The files that do not run, and what each is told (at a line): the
/// five that drive hardware Hashigo does not simulate.
const NOT_RUN: [(&str, &str); 5] = [
    ("Tests__test-i2c-1.ld", "I2C_WR drives hardware"),
    ("Tests__test-i2c-2.ld", "I2C_RD drives hardware"),
    ("Tests__test-i2c-lcd16x2.ld", "I2C_WR drives hardware"),
    ("Tests__test-spi.ld", "SPI_WR drives hardware"),
    // Its 7SEGMENTS runs; the BUS after it maps bits to pins.
    ("sample__swatch2.ld", "BUS drives hardware"),
];

#[test]
fn all_27_real_files_without_i2c_spi_or_bus_run_and_the_others_name_their_element() {
    let Some(names) = crate::common::fixture_names(REAL, ".ld") else {
        return;
    };
    assert_eq!(names.len(), 32);
    let mut ran = Vec::new();
    for name in &names {
        let text = real(name).expect("readable");
        let file = parse(&text).unwrap_or_else(|e| panic!("{name}: {e:?}"));
        match to_ladder(&file) {
            Ok(_) => {
                let mut plc = load(&text);
                plc.run_until(SimTime::from_secs(2));
                let expected = 2_000_000 / file.cycle_us;
                assert!(plc.scans() + 1 >= expected, "{name} scans {}", plc.scans());
                ran.push(name.clone());
            }
            Err(errors) => {
                let (_, why) = NOT_RUN
                    .iter()
                    .find(|(n, _)| n == name)
                    .unwrap_or_else(|| panic!("{name}: {errors:?}"));
                let said = errors[0].error.to_string();
                assert!(said.contains(why), "{name}: {said}");
                let line = text.lines().nth(errors[0].line - 1).unwrap_or_default();
                let keyword = why.split(' ').next().unwrap_or_default();
                assert!(
                    line.contains(keyword),
                    "{name}: line {} is {line}",
                    errors[0].line
                );
            }
        }
    }
    assert_eq!(ran.len(), 27, "{ran:?}");
}

/// `device`'s on and off stretches (ms) over `ms`, sampled every scan.
fn stretches(plc: &mut dyn Plc, device: &str, scan_ms: u64, ms: u64) -> Vec<(i64, u64)> {
    let mut out: Vec<(i64, u64)> = Vec::new();
    for t in (scan_ms..=ms).step_by(scan_ms as usize) {
        plc.run_until(SimTime::from_millis(t));
        let v = get(plc, device);
        match out.last_mut() {
            Some((last, n)) if *last == v => *n += scan_ms,
            _ => out.push((v, scan_ms)),
        }
    }
    out
}

#[test]
fn blink_oscillates_100_ms_on_and_1_s_off_as_its_timers_say() {
    // TON 100 ms then TOF 1 s on Rslow's own contact, in a 0.1 file at a
    // 10 ms cycle: the TON counts 9 cycles, the TOF 99 ((delay - cycle) /
    // cycle, LDmicro 2.x's period), and each holds one cycle more.
    let Some(text) = real("sample__blink.ld") else {
        return;
    };
    let mut plc = load(&text);
    set(plc.as_mut(), "Xbutton", 0);
    let got = stretches(plc.as_mut(), "Rslow", 10, 4500);
    // After the first stretch (from power-up), each is its full length.
    let steady: Vec<(i64, u64)> = got[1..got.len() - 1].to_vec();
    assert!(steady.len() >= 4, "{got:?}");
    for (v, ms) in steady {
        assert_eq!(ms, if v == 1 { 100 } else { 1000 }, "{got:?}");
    }
    // The button released once: Cwhich is 1, and the LED blinks slowly.
    assert_eq!(get(plc.as_ref(), "Cwhich"), 1);
}

#[test]
fn the_7_segment_sample_multiplexes_three_digits() {
    let Some(text) = real("sample__7seg-display.ld") else {
        return;
    };
    // The program shows 1, 8 and 5 (its last rung: MOVE digit0 1 …).
    let mut plc = load(&text);
    let segments = |plc: &dyn Plc| -> String {
        "abcdefg"
            .chars()
            .filter(|s| get(plc, &format!("Yseg_{s}")) == 1)
            .collect()
    };
    let mut seen = std::collections::BTreeMap::new();
    for t in (5..=300).step_by(5) {
        plc.run_until(SimTime::from_millis(t));
        let on: Vec<i64> = (0..3)
            .map(|k| get(plc.as_ref(), &format!("Ycom_digit{k}")))
            .collect();
        assert_eq!(on.iter().sum::<i64>(), 1, "one digit at a time: {on:?}");
        let k = on.iter().position(|&v| v == 1).unwrap_or(0);
        seen.insert(k, segments(plc.as_ref()));
    }
    // 1 lights b and c; 8 all seven; 5 a, c, d, f and g.
    assert_eq!(seen.get(&0).map(String::as_str), Some("bc"));
    assert_eq!(seen.get(&1).map(String::as_str), Some("abcdefg"));
    assert_eq!(seen.get(&2).map(String::as_str), Some("acdfg"));
}

/// A 0.2 file at a 10 ms cycle with `body` as its rungs.
pub(crate) fn program(body: &str) -> String {
    format!("LDmicro0.2\nCYCLE=10000 us at Timer1, YPlcCycleDuty:0\nCRYSTAL=16000000 Hz\n\nIO LIST\n    Xa at 1\n    Xr at 2\n    Yq at 3\nEND\n\nPROGRAM\n{body}")
}

/// Runs scans with `Xa` as `pattern` gives it, returning `Yq` after each.
fn run_pattern(plc: &mut dyn Plc, pattern: &[i64], from_scan: u64) -> Vec<i64> {
    pattern
        .iter()
        .enumerate()
        .map(|(k, &v)| {
            set(plc, "Xa", v);
            plc.run_until(SimTime::from_millis(10 * (from_scan + k as u64) + 15));
            get(plc, "Yq")
        })
        .collect()
}

#[test]
fn a_retentive_timer_keeps_its_time_while_off_until_reset() {
    let text = program(
        "RUNG 1\n  CONTACTS Xa 0\n  RTO Tr 50000\n  COIL Yq 0 0 0\nEND\nRUNG 2\n  CONTACTS Xr 0\n  RES Tr\nEND\n",
    );
    let mut plc = load(&text);
    // 50 ms at 10 ms: 5 cycles counted, in two stretches of 3 and 2.
    let got = run_pattern(plc.as_mut(), &[1, 1, 1, 0, 0, 1, 1, 1], 0);
    assert_eq!(got, vec![0, 0, 0, 0, 0, 0, 0, 1]);
    assert_eq!(get(plc.as_ref(), "Tr"), 5);
    // RES in the rung below: the coil sees it from the next scan on, as
    // in LDmicro, which runs the rungs in the same order.
    set(plc.as_mut(), "Xr", 1);
    let got = run_pattern(plc.as_mut(), &[0, 0], 8);
    assert_eq!(
        (got, get(plc.as_ref(), "Tr")),
        (vec![1, 0], 0),
        "RES clears it"
    );
}

#[test]
fn a_counter_counts_rises_to_its_limit_and_resets() {
    let text = program(
        "RUNG 1\n  CONTACTS Xa 0\n  CTU Cc 3\n  COIL Yq 0 0 0\nEND\nRUNG 2\n  CONTACTS Xr 0\n  RES Cc\nEND\n",
    );
    let mut plc = load(&text);
    let got = run_pattern(plc.as_mut(), &[1, 0, 1, 1, 0, 1, 0, 1], 0);
    assert_eq!(got, vec![0, 0, 0, 0, 0, 1, 1, 1]);
    assert_eq!(get(plc.as_ref(), "Cc"), 3, "it stops at its limit");
    set(plc.as_mut(), "Xr", 1);
    run_pattern(plc.as_mut(), &[0], 8);
    assert_eq!(get(plc.as_ref(), "Cc"), 0);
}

#[test]
fn arithmetic_runs_while_its_rung_has_power() {
    let text = program(
        "RUNG 1\n  CONTACTS Xa 0\n  ADD sum a 7\n  MUL prod sum 3\n  SUB diff prod 0x10\n  DIV quot diff 2\n  MOD rest diff 4\nEND\nRUNG 2\n  GEQ quot 10\n  COIL Yq 0 0 0\nEND\n",
    );
    let mut plc = load(&text);
    set(plc.as_mut(), "a", 5);
    run_pattern(plc.as_mut(), &[0], 0);
    assert_eq!(get(plc.as_ref(), "sum"), 0, "no power: nothing computed");
    let got = run_pattern(plc.as_mut(), &[1], 1);
    // (5 + 7) * 3 = 36; 36 - 16 = 20; 20 / 2 = 10; 20 mod 4 = 0.
    let values: Vec<i64> = ["sum", "prod", "diff", "quot", "rest"]
        .iter()
        .map(|n| get(plc.as_ref(), n))
        .collect();
    assert_eq!(values, vec![12, 36, 20, 10, 0]);
    assert_eq!(got, vec![1], "GEQ quot 10");
}

#[test]
fn hashigo_runs_an_ld_file_without_a_machine_and_refuses_hardware_at_its_line() {
    let tmp = Temp::new("ldmicro");
    let ld = tmp.file(
        "counter.ld",
        &program("RUNG 1\n  CONTACTS Xa 0\n  CTU Cc 2\n  COIL Yq 0 0 0\nEND\n"),
    );
    let events = tmp.file("ev.csv", "0,Xa,1\n50ms,Xa,0\n100ms,Xa,1\n");
    let out = hashigo(
        &[
            "run",
            "--program",
            &ld,
            "--input",
            &events,
            "--until",
            "200ms",
            "--watch",
            "Yq,Cc",
        ],
        "",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).ends_with("200,1,2\n"),
        "{}",
        text(&out.stdout)
    );
    // Standard input with --format ld; compile prints the soft PLC's IL.
    let out = hashigo(
        &["compile", "--program", "-", "--format", "ld"],
        &program("RUNG 1\n  CONTACTS Xa 0\n  TON Tw 30000\n  COIL Yq 0 0 0\nEND\n"),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let il = text(&out.stdout);
    assert!(
        il.contains("Tw_ld : LD_TON;") && il.contains("P := DINT#3"),
        "{il}"
    );
    // Hardware the page does not simulate: refused at its line.
    let spi = tmp.file(
        "spi.ld",
        &program("RUNG 1\n  CONTACTS Xa 0\n  SPI_WR SPI1 x y 0 0 8 MSB 1000\nEND\n"),
    );
    let out = hashigo(&["compile", "--program", &spi], "");
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert!(err.contains("spi.ld:14: SPI_WR drives hardware"), "{err}");
    // Another machine is refused: LDmicro files run on the soft PLC.
    let out = hashigo(
        &[
            "run",
            "--machine",
            "io86a",
            "--program",
            &ld,
            "--until",
            "1s",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("run on the soft PLC"));
}

#[test]
fn deep_and_long_files_are_read_or_refused_at_a_line_never_slowly() {
    let started = std::time::Instant::now();
    // 5 000 rungs of a contact, a timer and a coil.
    let mut body = String::new();
    for k in 0..5_000 {
        body.push_str(&format!(
            "RUNG\n  CONTACTS Xa 0\n  TON T{k} 50000\n  COIL Y{k} 0 0 0\nEND\n"
        ));
    }
    let file = parse(&program(&body)).expect("reads");
    let ladder = to_ladder(&file).expect("draws");
    assert_eq!(ladder.rungs.len(), 5_000);
    // Groups nested 90 deep: drawn or refused at a line, never a panic.
    let deep = format!(
        "RUNG\n{}  CONTACTS Xa 0\n  COIL Yq 0 0 0\n{}END\n",
        "PARALLEL\nSERIES\n".repeat(45),
        "END\nEND\n".repeat(45)
    );
    let file = parse(&program(&deep)).expect("reads");
    if let Err(errors) = to_ladder(&file) {
        assert!(errors.iter().all(|e| e.line > 0), "{errors:?}");
    }
    // Not a speed test: a search of the ladder per rung would take minutes.
    assert!(started.elapsed().as_secs() < 60);
}

#[test]
fn every_real_file_that_runs_goes_back_out_as_ld_and_reads_as_the_same_ladder() {
    let Some(names) = crate::common::fixture_names(REAL, ".ld") else {
        return;
    };
    let mut round = 0;
    for name in &names {
        let file = parse(&real(name).expect("readable")).expect("reads");
        let Ok(ladder) = to_ladder(&file) else {
            continue;
        };
        let text = engine::formats::ldmicro::export(&ladder, file.cycle_us)
            .unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let again = parse(&text).unwrap_or_else(|e| panic!("{name}: {e:?}\n{text}"));
        assert_eq!(again.cycle_us, file.cycle_us);
        let back = to_ladder(&again).unwrap_or_else(|e| panic!("{name}: {e:?}\n{text}"));
        assert_eq!(back.rungs, ladder.rungs, "{name}\n{text}");
        let typed = |l: &engine::ladder::Ladder| -> Vec<(String, String, String, bool)> {
            let mut v: Vec<_> = l
                .variables
                .iter()
                .map(|v| {
                    (
                        v.name.clone(),
                        v.data_type.clone(),
                        v.address.clone(),
                        v.retain,
                    )
                })
                .collect();
            v.sort();
            v
        };
        assert_eq!(typed(&back), typed(&ladder), "{name}");
        round += 1;
    }
    assert!(round >= 17 || names.is_empty(), "{round}");
}

#[test]
fn an_element_ldmicro_has_no_form_for_is_refused_at_its_cell() {
    let file = parse(&program("RUNG 1\n  CONTACTS Xa 0\n  COIL Yq 0 0 0\nEND\n")).expect("reads");
    let mut ladder = to_ladder(&file).expect("draws");
    // A rising contact: LDmicro writes a contact and an OSR instead.
    if let Some(Some(engine::ladder::Element::Contact { kind, .. })) =
        ladder.rungs[0].cells[0].get_mut(0)
    {
        *kind = engine::ladder::ContactKind::Rising;
    }
    let errors = engine::formats::ldmicro::export(&ladder, 10_000).expect_err("refused");
    assert_eq!((errors[0].rung, errors[0].pos.map(|p| p.col)), (1, Some(0)));
    assert!(errors[0].message.contains("OSR"), "{}", errors[0].message);
}

#[test]
fn a_rung_of_a_coil_alone_is_always_on_and_writes_back_as_it_was() {
    let text = program("RUNG 1\n  COIL Yq 0 0 0\nEND\n");
    let mut plc = load(&text);
    plc.run_until(SimTime::from_millis(25));
    assert_eq!(get(plc.as_ref(), "Yq"), 1);
    let file = parse(&text).expect("reads");
    let ladder = to_ladder(&file).expect("draws");
    let out = engine::formats::ldmicro::export(&ladder, file.cycle_us).expect("writes");
    assert!(
        out.contains("RUNG 1\n    SHORT\n    COIL Yq 0 0 0 0\nEND"),
        "{out}"
    );
    let back = to_ladder(&parse(&out).expect("reads")).expect("draws");
    assert_eq!(back.rungs, ladder.rungs);
}

#[test]
fn the_master_relay_turns_the_rungs_between_a_pair_off() {
    // LDmicro's sample: countA counts while Xswitch is on, countB while it
    // is off, `between` always.
    let Some(text) = real("sample__MasterRelay-Test.ld") else {
        return;
    };
    let mut plc = load(&text);
    let cycle = parse(&text).expect("reads").cycle_us / 1000;
    let counts = |plc: &dyn Plc| -> Vec<i64> {
        ["countA", "between", "countB"]
            .iter()
            .map(|n| get(plc, n))
            .collect()
    };
    plc.run_until(SimTime::from_millis(20 * cycle + cycle / 2));
    let off = counts(plc.as_ref());
    assert_eq!(off[0], 0, "{off:?}");
    assert!(off[1] >= 19 && off[2] >= 19, "{off:?}");
    set(plc.as_mut(), "Xswitch", 1);
    plc.run_until(SimTime::from_millis(40 * cycle + cycle / 2));
    let on = counts(plc.as_ref());
    assert!(on[0] >= 18, "{on:?}");
    assert!(on[2] - off[2] <= 2, "countB stops: {off:?} {on:?}");
    assert!(on[1] - off[1] >= 19, "between goes on: {off:?} {on:?}");
}

#[test]
fn a_shift_register_shifts_at_each_rise_and_a_table_looks_up() {
    let text = program(
        "RUNG 1\n  CONTACTS Xa 0\n  SHIFT_REGISTER reg 3\nEND\nRUNG 2\n  CONTACTS Xr 0\n  LOOK_UP_TABLE out i 4 0 10 20 30 40\nEND\n",
    );
    let mut plc = load(&text);
    set(plc.as_mut(), "reg0", 7);
    run_pattern(plc.as_mut(), &[1, 1, 0], 0);
    assert_eq!(
        (get(plc.as_ref(), "reg1"), get(plc.as_ref(), "reg2")),
        (7, 0),
        "one rise, one shift"
    );
    set(plc.as_mut(), "reg0", 8);
    run_pattern(plc.as_mut(), &[1], 3);
    let regs: Vec<i64> = ["reg0", "reg1", "reg2"]
        .iter()
        .map(|n| get(plc.as_ref(), n))
        .collect();
    assert_eq!(regs, vec![8, 8, 7]);
    set(plc.as_mut(), "i", 2);
    set(plc.as_mut(), "Xr", 1);
    run_pattern(plc.as_mut(), &[0], 4);
    assert_eq!(get(plc.as_ref(), "out"), 30);
}

#[test]
fn a_share_link_and_a_project_keep_an_ldmicro_ladder() {
    use engine::formats::{share, Project};
    let text = program(
        "RUNG 1\n  CONTACTS Xa 0\n  TON Tw 30000\n  CTC Cc 4 0 \\\n  COIL Yq 0 0 1 0\nEND\nRUNG 2\n  OSR\n  MOVE n 0x10\nEND\n\
         RUNG 3\n  FORMATTED_STRING n 17 105 116 39 115 44 32 40 42 36 41 32 92 51 92 114 92 110\n  \
         UART_RECV ch\n  UART_SEND ch\nEND\n",
    );
    let ladder = to_ladder(&parse(&text).expect("reads")).expect("draws");
    let project = Project::new(MachineId::SoftPlc, ladder.clone());
    let link = share::encode(&project).expect("encodes");
    assert_eq!(share::decode(&link).expect("decodes").ladder, ladder);
    let json = project.to_json();
    assert_eq!(Project::from_json(&json).expect("reads").ladder, ladder);
}

#[test]
fn ldmicros_word_operations_work_in_the_width_the_var_list_gives() {
    // A 0.2 file whose VAR LIST makes `b` one byte, `w` two.
    let text = "LDmicro0.2\nCYCLE=10000 us at Timer1, YPlcCycleDuty:0\n\nVAR LIST\n    1 bytes b \n    2 bytes w \nEND\n\nIO LIST\n    Xa at 1\n    Yq at 3\nEND\n\nPROGRAM\nRUNG 1\n  CONTACTS Xa 0\n  BIN2BCD bcd n\n  BCD2BIN back bcd\n  SR0 w m 4\n  OPPOSITE b one\n  SET_BIT s 3\nEND\nRUNG 2\n  IF_BIT_SET s 3\n  COIL Yq 0 0 0 0\nEND\n";
    let mut plc = load(text);
    set(plc.as_mut(), "n", 1234);
    set(plc.as_mut(), "m", -1);
    set(plc.as_mut(), "one", 1);
    run_pattern(plc.as_mut(), &[1], 0);
    assert_eq!(get(plc.as_ref(), "bcd"), 0x1234, "BIN2BCD");
    assert_eq!(get(plc.as_ref(), "back"), 1234, "BCD2BIN");
    assert_eq!(
        get(plc.as_ref(), "w"),
        0x0FFF,
        "SR0 fills a 16-bit word with zeros"
    );
    assert_eq!(
        get(plc.as_ref(), "b"),
        -128,
        "OPPOSITE in one byte: bit 0 to bit 7"
    );
    assert_eq!(get(plc.as_ref(), "s"), 8, "SET_BIT");
    let got = run_pattern(plc.as_mut(), &[0], 1);
    assert_eq!(got, vec![1], "IF_BIT_SET passes power while bit 3 is set");
    // Written back as the same elements.
    let file = parse(text).expect("reads");
    let ladder = to_ladder(&file).expect("draws");
    let out = engine::formats::ldmicro::export(&ladder, file.cycle_us).expect("writes");
    for line in [
        "BIN2BCD bcd n",
        "BCD2BIN back bcd",
        "SR0 w m 4",
        "OPPOSITE b one",
        "SET_BIT s 3",
        "IF_BIT_SET s 3",
    ] {
        assert!(out.contains(line), "{line}\n{out}");
    }
    let back = to_ladder(&parse(&out).expect("reads")).expect("draws");
    // The widths come from the VAR LIST, which LDmicro writes again
    // from its own list: the element lines are the same.
    assert_eq!(back.rungs.len(), ladder.rungs.len());
}

#[test]
fn a_piecewise_linear_table_interpolates_and_time2count_counts_cycles() {
    let text = program(
        "RUNG 1\n  CONTACTS Xa 0\n  PIECEWISE_LINEAR y x 3 0 0 100 1000 200 1500\nEND\nRUNG 2\n  TIME2COUNT n 50000\nEND\n",
    );
    let mut plc = load(&text);
    for (x, y) in [(50, 500), (150, 1250), (100, 1000), (0, 0), (200, 1500)] {
        set(plc.as_mut(), "x", x);
        let k = plc.scans();
        run_pattern(plc.as_mut(), &[1], k);
        assert_eq!(get(plc.as_ref(), "y"), y, "x = {x}");
    }
    assert_eq!(get(plc.as_ref(), "n"), 5, "50 ms in 10 ms cycles");
    let file = parse(&text).expect("reads");
    let ladder = to_ladder(&file).expect("draws");
    let out = engine::formats::ldmicro::export(&ladder, file.cycle_us).expect("writes");
    let back = to_ladder(&parse(&out).expect("reads")).expect("draws");
    assert_eq!(back.rungs, ladder.rungs, "{out}");
}

/// Everything `plc` sends at its serial port up to `ms`, typing each of
/// `typed` (a line and its CR) at its time (ms).
fn serial_until(plc: &mut dyn Plc, typed: &[(u64, &str)], ms: u64) -> String {
    let mut out = String::new();
    for &(at, line) in typed {
        plc.run_until(SimTime::from_millis(at));
        plc.serial(line).expect("typed");
    }
    plc.run_until(SimTime::from_millis(ms));
    plc.serial_sent(0, &mut out);
    out
}

#[test]
fn hello_prints_its_counter_once_a_second_right_aligned_in_five_places() {
    // Rosc turns over every TON of 1 s (99 cycles in a 0.1 file, on for
    // one more); each rise adds 1 to cnt and sends "Hello, world: \-5\r\n"
    // one character every other cycle (the transmitter busy for two).
    let Some(text) = real("sample__hello.ld") else {
        return;
    };
    let mut plc = load(&text);
    // Rosc's negated coil turns it on in the first cycle: the first line
    // goes at once, the others a second apart.
    let sent = serial_until(plc.as_mut(), &[], 2500);
    assert_eq!(
        sent,
        "Hello, world:      1\r\nHello, world:      2\r\nHello, world:      3\r\n"
    );
    // The console's terminal gets only what is new.
    let mut more = String::new();
    let seen = plc.serial_sent(0, &mut more);
    plc.run_until(SimTime::from_millis(3500));
    more.clear();
    plc.serial_sent(seen, &mut more);
    assert_eq!(more, "Hello, world:      4\r\n");
}

#[test]
fn the_uart_test_echoes_what_is_typed_and_greets_after_a_second() {
    // RUNG 2: TON 1 s then FORMATTED_STRING "Hello !" (sent once: its
    // power stays on); RUNGs 3-6: each byte received is sent back.
    let Some(text) = real("Tests__test-uart.ld") else {
        return;
    };
    let mut plc = load(&text);
    // Typed one key at a time (Enter alone is a CR): each comes back.
    let sent = serial_until(plc.as_mut(), &[(100, "a"), (300, ""), (400, "b")], 1500);
    assert_eq!(sent, "a\rbHello !");
    // A line typed at once arrives a byte a cycle while the echo sends
    // one every other cycle: what arrives while it is busy is dropped,
    // as on the chip.
    let sent = serial_until(plc.as_mut(), &[(1600, "xyz")], 1700);
    assert_eq!(sent, "a\rbHello !xz");
}

#[test]
fn serial_blinks_its_led_for_a_second_after_a_key_then_shows_an_o() {
    // sample__serial.ld sends A, b, c, CR, LF at each fall of Rosc (a
    // 250 ms TOF/TON pair); a key received sets Rjustgot for a second
    // (TON 1 s), during which Yled follows Rfast (100 ms); then Yled is
    // on while the last key was an "o".
    let Some(text) = real("sample__serial.ld") else {
        return;
    };
    let mut plc = load(&text);
    assert_eq!(stretches(plc.as_mut(), "Yled", 10, 100), [(0, 100)]);
    plc.serial("o").expect("typed");
    let blinking = stretches(plc.as_mut(), "Yled", 10, 1000);
    assert!(blinking.len() >= 6, "Rfast's blinking: {blinking:?}");
    plc.run_until(SimTime::from_millis(1200));
    assert_eq!(stretches(plc.as_mut(), "Yled", 10, 2000).len(), 1);
    assert_eq!(get(plc.as_ref(), "Yled"), 1, "the last key was an o");
    // One letter at each fall of Rosc, every half second.
    plc.run_until(SimTime::from_millis(7000));
    let mut out = String::new();
    plc.serial_sent(0, &mut out);
    assert_eq!(out, "bc\r\nAbc\r\nAbc\r\n");
}

#[test]
fn format_escapes_go_out_as_ldmicro_4_sends_them() {
    let Some(text) = real("sample__frmt_escape.ld") else {
        return;
    };
    let mut plc = load(&text);
    let sent = serial_until(plc.as_mut(), &[], 5000);
    assert!(
        sent.starts_with(" FormFeed as ClearScreen.\u{c}"),
        "{sent:?}"
    );
    assert!(
        sent.contains("Hello, word.\u{7}\u{8}\u{8}ld!\r\nOk\tTAB\n\r"),
        "{sent:?}"
    );
}

#[test]
fn hashigo_console_talks_to_an_ld_files_uart() {
    // An echo that takes a key only while the transmitter is free, so
    // none is dropped; a line's characters are keys, an empty line the
    // Enter key (a CR).
    let tmp = Temp::new("ldmicro-console");
    let ld = tmp.file(
        "echo.ld",
        &program(
            "RUNG 1\n  UART_SEND_READY\n  UART_RECV ch\n  COIL Rgot 0 0 0\nEND\n\
             RUNG 2\n  CONTACTS Rgot 0\n  UART_SEND ch\nEND\n",
        ),
    );
    let out = hashigo(
        &[
            "console",
            "--machine",
            "soft-plc",
            "--program",
            &ld,
            "--step",
            "100ms",
        ],
        "abc\n\nxy\n",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "abc\rxy");
    // A key that is no byte is refused, saying why.
    let out = hashigo(
        &["console", "--machine", "soft-plc", "--program", &ld],
        "\u{3042}\n",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("is not a byte"),
        "{}",
        text(&out.stderr)
    );
    // More keys than the port holds: refused, saying its limit.
    let flood = format!("{}\n", "k".repeat(5000));
    let out = hashigo(
        &["console", "--machine", "soft-plc", "--program", &ld],
        &flood,
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("4096 bytes"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn the_serial_boxes_read_back_from_their_il_with_their_text() {
    let text = program(
        "RUNG 1\n  CONTACTS Xa 0\n  FORMATTED_STRING n 9 97 44 32 40 36 41 92 50 39\n  \
         COIL Rbusy 0 0 0\nEND\nRUNG 2\n  UART_RECV ch\n  UART_SEND ch\n  COIL Yq 0 0 0\nEND\n",
    );
    let ladder = to_ladder(&parse(&text).expect("reads")).expect("draws");
    let il = compile(&ladder, MachineId::SoftPlc, Options::default()).expect("compiles");
    assert!(il.contains("FMT := 'a, ($$)\\2$''"), "{il}");
    let back = engine::ladder::decompile::decompile_text(MachineId::SoftPlc, &il, 10)
        .unwrap_or_else(|e| panic!("{e:?}\n{il}"));
    let boxes = |l: &engine::ladder::Ladder| -> Vec<String> {
        l.rungs
            .iter()
            .flat_map(|r| r.elements().map(|(_, e)| e.to_string()).collect::<Vec<_>>())
            .filter(|e| e.contains("LD_"))
            .collect()
    };
    assert_eq!(boxes(&back), boxes(&ladder), "{il}");
}

#[test]
fn arithmetic_wraps_in_the_width_the_var_list_gives_and_16_bits_by_default() {
    // b is one byte, w says nothing (two), d four bytes; each rung runs
    // once, on Xa's rise.
    let text =
        "LDmicro0.2\nCYCLE=10000\n\nVAR LIST\n    1 bytes b\n    4 bytes d\n    1 bytes r\nEND\n\n\
                IO LIST\n    Xa at 1\nEND\n\nPROGRAM\n\
                RUNG 1\n  CONTACTS Xa 0\n  OSR\n  PARALLEL\n    ADD b b 1\n    ADD w w 1\n    \
                ADD d d 1\n    ROL r r 1\n    SHR s s 1\n    DIV q q 0\n    NEG n n\n  END\nEND\n";
    let mut plc = load(text);
    for (name, v) in [
        ("b", 127),
        ("w", 32767),
        ("d", 32767),
        ("r", -128),
        ("s", -8),
        ("q", 9),
        ("n", -32768),
    ] {
        set(plc.as_mut(), name, v);
    }
    set(plc.as_mut(), "Xa", 1);
    plc.run_until(SimTime::from_millis(15));
    let got: Vec<i64> = ["b", "w", "d", "r", "s", "q", "n"]
        .iter()
        .map(|n| get(plc.as_ref(), n))
        .collect();
    // 127+1 wraps to -128 in a byte, 32767+1 in two; four bytes hold
    // 32768; 0x80 rotated left in a byte is 1; SHR keeps the sign; a
    // division by zero leaves q; -(-32768) wraps to itself in two bytes.
    assert_eq!(got, vec![-128, -32768, 32768, 1, -4, 9, -32768]);
    // Written back, the VAR LIST keeps the widths: the same ladder again.
    let ladder = to_ladder(&parse(text).expect("reads")).expect("draws");
    let out = engine::formats::ldmicro::export(&ladder, 10_000).expect("exports");
    assert!(
        out.contains("VAR LIST\n    1 bytes b\n    4 bytes d\n    1 bytes r\nEND"),
        "{out}"
    );
    let again = to_ladder(&parse(&out).expect("reads")).expect("draws");
    assert_eq!(again.rungs, ladder.rungs);
}

#[test]
fn time2delay_is_refused_as_the_chips_own_delay_loop() {
    let text = program("RUNG 1\n  CONTACTS Xa 0\n  TIME2DELAY n 500\nEND\n");
    let errors = to_ladder(&parse(&text).expect("reads")).expect_err("refused");
    assert_eq!(errors[0].line, 14);
    assert!(
        errors[0]
            .error
            .to_string()
            .starts_with("TIME2DELAY drives hardware"),
        "{}",
        errors[0].error
    );
}

#[test]
fn several_bytes_go_out_and_come_in_the_lowest_first() {
    // w is two bytes (UART_SENDn sends them all); r takes two bytes.
    let text = "LDmicro0.2\nCYCLE=10000\n\nVAR LIST\n    2 bytes w\nEND\n\n\
                IO LIST\n    Xa at 1\n    Yq at 3\nEND\n\nPROGRAM\n\
                RUNG 1\n  CONTACTS Xa 0\n  UART_SENDn w\n  COIL Rbusy 0 0 0\nEND\n\
                RUNG 2\n  UART_RECV r 2 0\n  COIL Yq 0 0 0\nEND\n";
    let mut plc = load(text);
    set(plc.as_mut(), "w", 0x4241);
    set(plc.as_mut(), "Xa", 1);
    plc.run_until(SimTime::from_millis(15));
    assert_eq!(get(plc.as_ref(), "Rbusy"), 1, "on while the bytes go");
    // Released at once: the word still goes whole (LDmicro 4.x starts
    // it again at each scan the power is on when it is done).
    set(plc.as_mut(), "Xa", 0);
    plc.run_until(SimTime::from_millis(100));
    let mut out = String::new();
    plc.serial_sent(0, &mut out);
    assert_eq!(out, "AB", "the low byte first");
    assert_eq!(get(plc.as_ref(), "Rbusy"), 0);
    // Two keys make one word; power passes in the scan the second comes.
    plc.serial("xy").expect("typed");
    plc.run_until(SimTime::from_millis(115));
    assert_eq!((get(plc.as_ref(), "r"), get(plc.as_ref(), "Yq")), (0, 0));
    plc.run_until(SimTime::from_millis(125));
    assert_eq!(
        get(plc.as_ref(), "r"),
        i64::from(u16::from_le_bytes(*b"xy"))
    );
    assert_eq!(get(plc.as_ref(), "Yq"), 1);
    // Written back with their counts, read again the same.
    let ladder = to_ladder(&parse(text).expect("reads")).expect("draws");
    let back = engine::formats::ldmicro::export(&ladder, 10_000).expect("exports");
    assert!(
        back.contains("UART_SEND w 2 0") && back.contains("UART_RECV r 2 0"),
        "{back}"
    );
    assert_eq!(
        to_ladder(&parse(&back).expect("reads"))
            .expect("draws")
            .rungs,
        ladder.rungs
    );
    // Waiting for the bytes (the chip stopped) is refused at its line.
    let waiting = program("RUNG 1\n  UART_SEND w 2 1\nEND\n");
    let errors = to_ladder(&parse(&waiting).expect("reads")).expect_err("refused");
    assert!(
        errors[0].error.to_string().contains("waiting"),
        "{}",
        errors[0].error
    );
}

#[test]
fn travelling_back_shows_what_the_port_had_sent_then_and_typing_replays() {
    use engine::record::Recorded;
    // Echo of each key, the transmitter free first (no key dropped).
    let text = program(
        "RUNG 1\n  UART_SEND_READY\n  UART_RECV ch\n  COIL Rgot 0 0 0\nEND\n\
         RUNG 2\n  CONTACTS Rgot 0\n  UART_SEND ch\nEND\n",
    );
    let ladder = to_ladder(&parse(&text).expect("reads")).expect("draws");
    let il = compile(&ladder, MachineId::SoftPlc, Options::default()).expect("compiles");
    let mut soft = engine::machines::SoftPlc::new();
    soft.load_text(&il).expect("loads");
    let mut r = Recorded::new(soft);
    r.run_until(SimTime::from_millis(50));
    r.serial("ab").expect("typed");
    r.run_until(SimTime::from_millis(200));
    let mut now = String::new();
    assert_eq!(r.serial_sent(0, &mut now), 2);
    assert_eq!(now, "ab");
    // Back before the keys: nothing sent then; live again: both.
    let first = r.recording().first();
    assert!(r.show(first + 1));
    let mut then = String::new();
    assert_eq!(r.serial_sent(0, &mut then), 0, "{then:?}");
    // A replayed scan after the keys shows the first byte sent.
    assert!(r.show(first + 7));
    then.clear();
    r.serial_sent(0, &mut then);
    assert_eq!(then, "a");
    r.go_live();
    then.clear();
    r.serial_sent(0, &mut then);
    assert_eq!(then, "ab");
}

#[test]
fn the_serial_count_example_says_each_press_and_starts_again_at_r() {
    let example = engine::examples::EXAMPLES
        .iter()
        .find(|e| e.id == "serial-count")
        .expect("the example");
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(example.text).expect("loads");
    for (k, on) in [1, 0, 1, 0].into_iter().enumerate() {
        set(plc.as_mut(), "Xcount", on);
        plc.run_until(SimTime::from_millis(400 * (k as u64 + 1)));
    }
    let mut out = String::new();
    plc.serial_sent(0, &mut out);
    assert_eq!(out, "count =      1\r\ncount =      2\r\n");
    plc.serial("r").expect("typed");
    plc.run_until(SimTime::from_millis(1700));
    assert_eq!(get(plc.as_ref(), "count"), 0);
}
