//! The AVR simplified PLC: the seed's examples and its timer warning.

#[path = "../common/mod.rs"]
mod common;

mod cli;

use engine::avr::{Machine, Program, ProgramError};
use engine::SimTime;

/// The seed's bit definitions and self-holding rungs, with End_PLC added
/// (the seed shows the rungs as a fragment).
pub const SELF_HOLD: &str = "\
;***** Bit Definition ******
.equ INPUT1_R=4
.equ INPUT1_B=Bit0
.equ INPUT2_R=4
.equ INPUT2_B=Bit1
.equ INPUT3_R=4
.equ INPUT3_B=Bit2
.equ COIL1_R=5
.equ COIL1_B=Bit0
.equ COIL2_R=5
.equ COIL2_B=Bit1
; First Rung
.csg
.db   Load_A,INPUT1_R,INPUT1_B,0
.db   And_A,INPUT2_R,INPUT2_B,0
.db   Coil_A,COIL1_R,COIL1_B,0
;  Second Rung
.db   Load_A,COIL1_R,COIL1_B,0
.db   Or_A,COIL2_R,COIL2_B,0
.db   And_B,INPUT3_R,INPUT3_B,0
.db   Coil_A,COIL2_R,COIL2_B,0
.db   End_PLC,0,0,0
";

/// The seed's timer example, with its bits defined.
pub const E_STOP: &str = "\
.equ Run_R=4
.equ Run_B=Bit0
.equ Direct_R=4
.equ Direct_B=Bit1
.equ E_Stop_R=6
.equ E_Stop_B=Bit7
.dseg
PLC_Timer_Top: ; PLC Timers
E_Stop_Timer:    .byte 2
Start_TP:        .byte 2
Stop_TP:         .byte 2
.cseg
; Run  Direct    E_Stop
;--| |--| |--[TOF]--( )-|
.db Load_A,Run_R,Run_B,0
.db And_A,Direct_R,Direct_B,0
.db TOF,LOW(E_Stop_Timer),LOW(1000/Scan),HIGH(1000/Scan)
.db Coil_A,E_Stop_R,E_Stop_B,0
.db End_PLC,0,0,0
";

fn machine(text: &str) -> Machine {
    Machine::new(Program::parse(text, 10).unwrap_or_else(|e| panic!("{e:?}")))
}

fn set(m: &mut Machine, name: &str, on: bool) {
    let bit = m
        .program()
        .bit(name)
        .unwrap_or_else(|| panic!("no bit {name}"));
    m.set_input(bit, on);
}

fn get(m: &Machine, name: &str) -> bool {
    m.bit(
        m.program()
            .bit(name)
            .unwrap_or_else(|| panic!("no bit {name}")),
    )
}

fn after(m: &mut Machine, ms: u64) {
    let t = m.now() + SimTime::from_millis(ms);
    m.run_until(t);
}

#[test]
fn the_seeds_self_holding_rungs() {
    let mut m = machine(SELF_HOLD);
    after(&mut m, 20);
    assert!(!get(&m, "COIL1") && !get(&m, "COIL2"));
    set(&mut m, "INPUT1", true);
    set(&mut m, "INPUT2", true);
    after(&mut m, 20);
    assert!(
        get(&m, "COIL1") && get(&m, "COIL2"),
        "INPUT1 and INPUT2: COIL1, then COIL2"
    );
    set(&mut m, "INPUT1", false);
    after(&mut m, 20);
    assert!(!get(&m, "COIL1"), "COIL1 drops with INPUT1");
    assert!(get(&m, "COIL2"), "COIL2 holds itself");
    set(&mut m, "INPUT3", true);
    after(&mut m, 20);
    assert!(!get(&m, "COIL2"), "INPUT3 breaks the hold");
    assert!(get(&m, "R4.2"), "bits can be named by register and bit");
}

#[test]
fn tof_is_on_for_its_time_after_power_up_as_the_seed_warns() {
    let mut m = machine(E_STOP);
    after(&mut m, 10);
    assert!(get(&m, "E_Stop"), "on at power-up with Run and Direct off");
    m.run_until(SimTime::from_millis(1000));
    assert!(get(&m, "E_Stop"), "for 1000/Scan = 100 scans");
    m.run_until(SimTime::from_millis(1010));
    assert!(!get(&m, "E_Stop"), "then off");
    set(&mut m, "Run", true);
    set(&mut m, "Direct", true);
    after(&mut m, 10);
    assert!(get(&m, "E_Stop"));
    set(&mut m, "Direct", false);
    after(&mut m, 990);
    assert!(get(&m, "E_Stop"), "held for 1 s after IN drops");
    after(&mut m, 20);
    assert!(!get(&m, "E_Stop"));
}

const TIMERS: &str = "\
.equ IN_R=4
.equ IN_B=Bit0
.equ ON_R=5
.equ ON_B=Bit0
.equ PULSE_R=5
.equ PULSE_B=Bit1
.dseg
PLC_Timer_Top:
T_on: .byte 2
T_pulse: .byte 2
.cseg
.db Load_A,IN_R,IN_B,0
.db TON,LOW(T_on),5,0
.db Coil_A,ON_R,ON_B,0
.db Load_A,IN_R,IN_B,0
.db TP,LOW(T_pulse),3,0
.db Coil_A,PULSE_R,PULSE_B,0
.db End_PLC,0,0,0
";

#[test]
fn ton_delays_by_its_preset_in_scans() {
    let mut m = machine(TIMERS);
    set(&mut m, "IN", true);
    m.run_until(SimTime::from_millis(10)); // scan 1 sees IN
    m.run_until(SimTime::from_millis(50));
    assert!(!get(&m, "ON"), "4 scans after IN");
    m.run_until(SimTime::from_millis(60));
    assert!(get(&m, "ON"), "5 scans after IN");
    set(&mut m, "IN", false);
    after(&mut m, 10);
    assert!(!get(&m, "ON"), "off at once");
}

#[test]
fn tp_pulses_its_preset_and_is_not_retriggerable() {
    let mut m = machine(TIMERS);
    let mut trace = Vec::new();
    let inputs = [1, 1, 0, 1, 1, 1, 1, 1, 0, 1, 0];
    for &i in &inputs {
        set(&mut m, "IN", i == 1);
        after(&mut m, 10);
        trace.push(u8::from(get(&m, "PULSE")));
    }
    // Rising edge at scan 1: on for 3 scans whatever IN does; IN must drop
    // before the next pulse (scan 9 rises again).
    assert_eq!(trace, [1, 1, 1, 0, 0, 0, 0, 0, 0, 1, 1]);
    assert_eq!(m.timer(1).map(|t| t.count), Some(2));
}

#[test]
fn not_pulses_set_reset_and_inverted_coils() {
    let src = "\
.equ A_R=4
.equ A_B=Bit0
.equ B_R=4
.equ B_B=Bit1
.equ P_R=5
.equ P_B=Bit0
.equ N_R=5
.equ N_B=Bit1
.equ MP_R=6
.equ MP_B=Bit0
.equ MN_R=6
.equ MN_B=Bit1
.equ L_R=5
.equ L_B=Bit2
.equ INV_R=5
.equ INV_B=Bit3
.db Load_A,A_R,A_B,0
.db Pulse_A,MP_R,MP_B,0
.db Coil_A,P_R,P_B,0
.db Load_A,A_R,A_B,0
.db Pulse_B,MN_R,MN_B,0
.db Coil_A,N_R,N_B,0
.db Load_A,A_R,A_B,0
.db Set_Coil,L_R,L_B,0
.db Load_A,B_R,B_B,0
.db Reset_Coil,L_R,L_B,0
.db Load_A,A_R,A_B,0
.db Not,0,0,0
.db Coil_B,INV_R,INV_B,0
.db End_PLC,0,0,0
";
    let mut m = machine(src);
    after(&mut m, 10);
    assert!(!get(&m, "INV"), "Not then an inverted coil: INV = A");
    set(&mut m, "A", true);
    after(&mut m, 10);
    assert!(get(&m, "P") && !get(&m, "N") && get(&m, "L") && get(&m, "INV"));
    after(&mut m, 10);
    assert!(!get(&m, "P"), "P lasts one scan");
    set(&mut m, "A", false);
    after(&mut m, 10);
    assert!(get(&m, "N"), "N on the fall");
    assert!(get(&m, "L"), "the set coil holds");
    after(&mut m, 10);
    assert!(!get(&m, "N"));
    set(&mut m, "B", true);
    after(&mut m, 10);
    assert!(!get(&m, "L"), "reset coil");
}

#[test]
fn bad_sources_are_located() {
    let src = ".equ X_R=4\n.equ X_B=$03\n.db Load_A,X_R,X_B,0\n.db 42,4,1,0\n.db TON,0,10,0\n.db Load_A,40,1,0\n.db Not,4,1,0\n.db End_PLC,0,0,0\n";
    let errors = Program::parse(src, 10).unwrap_err();
    let found: Vec<(usize, ProgramError)> = errors.into_iter().map(|e| (e.line, e.error)).collect();
    assert_eq!(
        found,
        [
            (3, ProgramError::Pattern(3)),
            (4, ProgramError::UnknownCode(42)),
            (5, ProgramError::NoTimerTop),
            (6, ProgramError::Register(40)),
            (7, ProgramError::NotOperand),
        ]
    );
    let no_end = Program::parse(".db Load_A,4,1,0\n", 10).unwrap_err();
    assert_eq!(
        (no_end[0].line, &no_end[0].error),
        (1, &ProgramError::NoEnd)
    );
}

#[test]
fn an_input_event_on_a_timer_is_refused_naming_the_timer_as_written() {
    use engine::events::InputValue;
    use engine::machines::AvrPlc;
    use engine::plc::Plc;
    let mut plc = AvrPlc::new();
    plc.load_text(E_STOP)
        .expect("the seed's timer example loads");
    let timer = plc.device("Start_TP.v").expect("a timer word by its label");
    let refused = plc
        .check_input(timer, InputValue::Int(1))
        .expect_err("a timer is no input")
        .to_string();
    assert!(refused.contains("Start_TP.v"), "{refused}");
    assert!(!refused.contains("timer 1"), "{refused}");
}
