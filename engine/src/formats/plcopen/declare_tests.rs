//! Tests of the declarations reader: located variables by rule, maps.

use super::*;

#[test]
fn located_variables_map_by_rule_within_the_machines_sizes() {
    let io = MachineId::Io86a;
    assert_eq!(located(io, "%IX0.3").as_deref(), Ok("X03"));
    assert_eq!(located(io, "%QX0.5").as_deref(), Ok("Y05"));
    assert_eq!(located(io, "%MX1.2").as_deref(), Ok("M10"));
    assert_eq!(located(io, "%m0.1").as_deref(), Ok("M01"));
    assert!(located(io, "%QX0.6").is_err(), "IO86A has Y00-Y05");
    assert_eq!(
        located(io, "%IW1").as_deref(),
        Ok("D07"),
        "X05's analog value"
    );
    assert!(located(io, "%IW2").is_err(), "a word IO86A lacks");
    assert!(located(MachineId::MinasecU, "%IW0").is_err(), "a word");
    assert!(located(io, "IX0.0").is_err());
    assert!(located(io, "%IX0.9").is_err());
    let m = MachineId::MinasecU;
    assert_eq!(located(m, "%MX1.3").as_deref(), Ok("M13"));
    assert!(located(m, "%MX1.4").is_err(), "MINASEC-U has M10-M13");
    assert_eq!(
        located(MachineId::ArduinoPlc, "%QX0.0").as_deref(),
        Ok("Y000")
    );
    let avr = MachineId::AvrPlc;
    assert_eq!(located(avr, "%IX0.3").as_deref(), Ok("R4.3"));
    assert_eq!(located(avr, "%QX0.7").as_deref(), Ok("R5.7"));
    assert_eq!(located(avr, "%MX1.2").as_deref(), Ok("R7.2"));
    assert_eq!(located(avr, "%MX9.7").as_deref(), Ok("R15.7"));
    let past = located(avr, "%MX10.0").expect_err("R16 is the compiler's");
    assert_eq!(
        past.to_string(),
        "%MX10.0 is past the AVR PLC's relays (R6.0-R15.7 in Hashigo)"
    );
    assert!(located(avr, "%IX1.0").is_err(), "R4 holds the inputs");
    assert!(located(avr, "%QX0.8").is_err());
}

#[test]
fn map_files_read_and_refuse_by_line() {
    let map =
        VarMap::parse("name,device\n# lamps\nStart, X00\nTON0,T00 # the timer\n\n").expect("a map");
    assert_eq!(
        map.entries,
        vec![
            ("Start".into(), "X00".into(), 3),
            ("TON0".into(), "T00".into(), 4)
        ]
    );
    let errors = VarMap::parse("Start\nA,X00\na,X01\nB,\n").expect_err("bad lines");
    let lines: Vec<usize> = errors.iter().map(|e| e.line).collect();
    assert_eq!(lines, vec![1, 3, 4]);
}
