//! PLC-IO86A: the manual's examples, run as the manual says they behave.

#[path = "../common/mod.rs"]
mod common;

mod cli;
mod terminal;

use engine::io86a::{Bit, Machine, Program};
use engine::SimTime;

/// A device running `text` (the manual's listing, END appended), with the
/// input filter off (`!0`) so that inputs reach the next scan; the filter
/// has a test of its own.
fn device(text: &str) -> Machine {
    let program = Program::parse(&format!("{text}\nEND\n")).unwrap_or_else(|e| panic!("{e:?}"));
    let mut m = Machine::new(program);
    m.settings_mut().apply("!0").expect("!0 is a setting");
    m
}

fn ms(n: u64) -> SimTime {
    SimTime::from_millis(n)
}

fn y(m: &Machine, n: u8) -> bool {
    m.output_terminals() >> n & 1 != 0
}

fn bit(m: &Machine, b: Bit) -> bool {
    m.last_scan().bit(b)
}

/// Sets X00..X07 from `bits` and runs two scans.
fn inputs(m: &mut Machine, bits: u8) {
    for n in 0..8 {
        m.set_input(n, bits >> n & 1 != 0);
    }
    let t = m.now();
    m.run_until(t + ms(2));
}

#[test]
fn ld_out_and_the_timer_k19_is_1_9_s() {
    let mut m =
        device("1 LD X00\n2 OUT Y00\n3 LDI X01\n4 OUT M00\n5 OUT T00\n6 K19\n7 LD T00\n8 OUT Y01");
    m.run_until(ms(1_899));
    assert!(!y(&m, 1));
    assert!(bit(&m, Bit::M(0)), "M00 = !X01");
    m.run_until(ms(1_901));
    assert!(
        y(&m, 1),
        "T00 K19 is 1.9 s (coil on at the first scan, 1 ms)"
    );
    assert!(!y(&m, 0));
    m.set_input(0, true);
    m.run_until(ms(1_903));
    assert!(y(&m, 0), "Y00 follows X00");
    m.set_input(1, true);
    m.run_until(ms(1_905));
    assert!(
        !y(&m, 1) && !bit(&m, Bit::M(0)),
        "X01 drops the coil: the timer resets"
    );
}

#[test]
fn and_ani_series_contacts() {
    let mut m = device(
        "1 LD X02\n2 AND X00\n3 OUT Y00\n4 LD Y03\n5 ANI X03\n6 OUT M01\n7 AND T01\n8 OUT Y04",
    );
    for bits in 0..16u8 {
        inputs(&mut m, bits);
        let x = |n: u8| bits >> n & 1 != 0;
        assert_eq!(y(&m, 0), x(2) && x(0), "inputs {bits:04b}");
        assert!(!bit(&m, Bit::M(1)), "Y03 is never on");
        assert!(!y(&m, 4));
    }
}

#[test]
fn or_ori_parallel_contacts() {
    let mut m = device(
        "1 LD X02\n2 OR Y03\n3 ORI M02\n4 OUT Y05\n5 LDI X05\n6 AND X06\n7 OR M03\n8 ANI X04\n9 ORI M10\n10 OUT M03",
    );
    for bits in 0..=255u8 {
        inputs(&mut m, bits);
        // M02 and M10 are never driven, so their NC contacts close both rungs.
        assert!(y(&m, 5) && bit(&m, Bit::M(3)), "inputs {bits:08b}");
    }
}

#[test]
fn orb_joins_blocks_in_parallel() {
    let mut m = device(
        "1 LD X00\n2 AND X01\n3 LD X02\n4 AND X03\n5 ORB\n6 LDI X04\n7 AND X05\n8 ORB\n9 OUT Y05",
    );
    for bits in 0..64u8 {
        inputs(&mut m, bits);
        let x = |n: u8| bits >> n & 1 != 0;
        let expected = (x(0) && x(1)) || (x(2) && x(3)) || (!x(4) && x(5));
        assert_eq!(y(&m, 5), expected, "inputs {bits:06b}");
    }
}

#[test]
fn anb_joins_blocks_in_series() {
    let mut m = device(
        "1 LD X00\n2 OR X01\n3 LD X02\n4 AND X03\n5 LDI X04\n6 AND X05\n7 ORB\n8 OR X06\n9 ANB\n10 OR X03\n11 OUT Y05",
    );
    for bits in 0..128u8 {
        inputs(&mut m, bits);
        let x = |n: u8| bits >> n & 1 != 0;
        let block = (x(2) && x(3)) || (!x(4) && x(5)) || x(6);
        let expected = ((x(0) || x(1)) && block) || x(3);
        assert_eq!(y(&m, 5), expected, "inputs {bits:07b}");
    }
}

#[test]
fn pls_plf_with_set_and_rst() {
    let mut m = device(
        "1 LD X00\n2 PLS M00\n3 LD M00\n4 SET Y00\n5 LD X01\n6 PLF M01\n7 LD M01\n8 RST Y00",
    );
    m.run_until(ms(5));
    m.set_input(0, true);
    m.run_until(ms(6));
    assert!(bit(&m, Bit::M(0)), "M00 on in the scan X00 rose");
    assert!(y(&m, 0), "Y00 set");
    m.run_until(ms(7));
    assert!(!bit(&m, Bit::M(0)), "for exactly one scan");
    m.set_input(0, false);
    m.run_until(ms(20));
    assert!(y(&m, 0), "SET holds after X00 drops");
    m.set_input(1, true);
    m.run_until(ms(30));
    assert!(y(&m, 0), "PLF waits for the fall");
    m.set_input(1, false);
    m.run_until(ms(31));
    assert!(bit(&m, Bit::M(1)) && !y(&m, 0), "the fall resets Y00");
    m.run_until(ms(32));
    assert!(!bit(&m, Bit::M(1)));
}

#[test]
fn counter_counts_rising_edges_to_k_and_rst_clears() {
    let mut m = device("1 LD X00\n2 RST C00\n3 LD X01\n4 OUT C00\n5 K10\n6 LD C00\n7 OUT Y00");
    for pulse in 1..=12 {
        m.set_input(1, true);
        m.run_until(m.now() + ms(3));
        m.set_input(1, false);
        m.run_until(m.now() + ms(3));
        assert_eq!(
            m.last_scan().counters[0].count,
            pulse.min(10),
            "does not pass K"
        );
        assert_eq!(y(&m, 0), pulse >= 10, "after {pulse} pulses");
    }
    m.set_input(0, true);
    m.run_until(m.now() + ms(3));
    assert_eq!(m.last_scan().counters[0].count, 0);
    assert!(!y(&m, 0));
}

#[test]
fn mov_copies_constants_registers_and_timer_values() {
    let mut m = device(
        "1 LD X00\n2 MOV\n3 K10\n4 D00\n5 LD X01\n6 MOV\n7 D00\n8 D01\n9 LD X02\n10 MOV\n11 T00\n12 D02\n13 LD X03\n14 OUT T00\n15 K100",
    );
    m.run_until(ms(10));
    assert_eq!(m.last_scan().d[0], 0, "X00 off: nothing moves");
    m.set_input(0, true);
    m.run_until(ms(12));
    assert_eq!(m.last_scan().d[0], 10);
    m.set_input(1, true);
    m.run_until(ms(14));
    assert_eq!(m.last_scan().d[1], 10);
    m.set_input(3, true);
    m.run_until(ms(1_514));
    m.set_input(2, true);
    m.run_until(ms(1_516));
    assert_eq!(
        m.last_scan().d[2],
        15,
        "T00's current value, in 0.1 s units"
    );
}

#[test]
fn cmp_sets_m60_m61_m62_and_the_manuals_window_lights_y00() {
    let text = "1 LD X00\n2 MOV\n3 K50\n4 D00\n5 LD X01\n6 OUT T00\n7 K100\n8 LD X02\n9 CMP\n10 D00\n11 T00\n\
                12 LD M61\n13 OR Y00\n14 ANI M00\n15 OUT Y00\n16 LD Y00\n17 CMP\n18 D00\n19 T00\n20 LD M62\n21 OUT M00";
    let mut m = device(text);
    m.set_input(0, true);
    m.set_input(2, true);
    m.run_until(ms(10));
    assert!(bit(&m, Bit::M(60)), "D00=50 > T00=0: M60");
    m.set_input(1, true); // T00 starts at the 11 ms scan
    m.run_until(ms(11 + 4_999));
    assert!(!y(&m, 0));
    m.run_until(ms(11 + 5_000));
    assert!(
        bit(&m, Bit::M(61)) && y(&m, 0),
        "T00 = 50 = D00: M61 latches Y00"
    );
    m.run_until(ms(11 + 5_099));
    assert!(y(&m, 0), "held while T00 = 50");
    m.run_until(ms(11 + 5_101));
    assert!(
        bit(&m, Bit::M(62)) && !y(&m, 0),
        "T00 > D00: M62 → M00 drops Y00"
    );
    m.set_input(2, false);
    m.run_until(ms(11 + 5_200));
    assert!(bit(&m, Bit::M(62)), "the flags hold until the next CMP");
}

#[test]
fn inc_dec_act_every_scan_and_wrap() {
    let mut m = device("1 LD X00\n2 MOV\n3 K10\n4 D00\n5 MOV\n6 K5\n7 D01\n8 LD X01\n9 INC D0\n10 LD X02\n11 DEC D01");
    m.set_input(0, true);
    m.run_until(ms(2));
    m.set_input(0, false);
    m.set_input(1, true);
    m.run_until(ms(7)); // five scans with X01 on
    assert_eq!(m.last_scan().d[0], 15, "INC runs on every scan while ON");
    m.set_input(1, false);
    m.set_input(2, true);
    m.run_until(ms(10));
    assert_eq!(m.last_scan().d[1], 2);

    let mut w = device("LD X00\nMOV K32767 D00\nLD X01\nINC D00\nLD X02\nDEC D01");
    w.set_input(0, true);
    w.run_until(ms(1));
    w.set_input(0, false);
    w.set_input(1, true);
    w.set_input(2, true);
    w.run_until(ms(2));
    assert_eq!(w.last_scan().d[0], -32768, "32767 + 1 wraps");
    assert_eq!(w.last_scan().d[1], -1);
}

#[test]
fn led_blink_is_0_2_s_on_0_2_s_off() {
    let mut m =
        device("1 LDI T01\n2 OUT T00\n3 K2\n4 LD T00\n5 OUT T01\n6 K2\n7 LDI T00\n8 OUT Y00");
    let mut edges = Vec::new();
    let mut last = y(&m, 0);
    for t in 1..=2_000 {
        m.run_until(ms(t));
        if y(&m, 0) != last {
            last = y(&m, 0);
            edges.push(t);
        }
    }
    assert!(edges.len() >= 8, "{edges:?}");
    for pair in edges.windows(2).skip(1) {
        let gap = pair[1] - pair[0];
        assert!((199..=202).contains(&gap), "0.2 s phases: {edges:?}");
    }
}

#[test]
fn push_on_push_off_toggles_y00() {
    let mut m =
        device("1 LD X00\n2 PLS M00\n3 LD M00\n4 ANI Y00\n5 LDI M00\n6 AND Y00\n7 ORB\n8 OUT Y00");
    let mut expected = false;
    for _ in 0..4 {
        m.set_input(0, true);
        m.run_until(m.now() + ms(30));
        expected = !expected;
        assert_eq!(y(&m, 0), expected);
        m.set_input(0, false);
        m.run_until(m.now() + ms(30));
        assert_eq!(y(&m, 0), expected, "releasing does not toggle");
    }
}

#[test]
fn system_relays() {
    let mut m = device(
        "LD M57\nOUT Y00\nLD M56\nOUT Y01\nLD M63\nOUT M00\nLD M58\nOUT Y02\nLD M59\nOUT Y03",
    );
    m.run_until(ms(1));
    assert!(y(&m, 0) && !y(&m, 1));
    assert!(bit(&m, Bit::M(0)), "M63 on the first scan");
    m.run_until(ms(2));
    assert!(!bit(&m, Bit::M(0)), "and only then");
    m.run_until(ms(99));
    assert!(!y(&m, 2));
    m.run_until(ms(100));
    assert!(y(&m, 2), "M58 toggles every 0.1 s");
    m.run_until(ms(200));
    assert!(!y(&m, 2));
    m.run_until(ms(999));
    assert!(!y(&m, 3));
    m.run_until(ms(1000));
    assert!(y(&m, 3), "M59 toggles every 1 s");
}

#[test]
fn double_coils_last_out_wins_and_ten_ms_timers() {
    let mut m = device("LD X00\nOUT Y00\nLDI X00\nOUT Y00\nLD M57\nOUT T24\nK5\nLD T24\nOUT Y01");
    m.run_until(ms(2));
    assert!(y(&m, 0), "the second OUT Y00 (X00 off → ON) wins");
    m.run_until(ms(50));
    assert!(!y(&m, 1));
    m.run_until(ms(51));
    assert!(y(&m, 1), "T24 counts 10 ms: K5 = 50 ms");
}

#[test]
fn sets_rsts_collect_writes_for_the_linked_device() {
    let mut a = device("LD X00\nSETS Y00\nLD X01\nRSTS Y00");
    let mut b = device("LD M00\nOUT Y01");
    a.set_input(0, true);
    a.run_until(ms(1));
    for write in a.take_link_writes() {
        b.write_bit(write.bit, write.on);
    }
    b.run_until(ms(1));
    assert!(b.devices().bit(Bit::Y(0)), "A's X00 sets B's Y00");
}

#[test]
fn the_input_filter_holds_changes_for_n_times_10_ms() {
    let program = Program::parse("LD X00\nOUT Y00\nEND\n").expect("parses");
    let mut m = Machine::new(program);
    assert_eq!(m.settings().filter, 2, "!2 after power-on");
    m.run_until(ms(10));
    m.set_input(0, true);
    m.run_until(ms(29));
    assert!(!y(&m, 0), "not before 20 ms");
    m.run_until(ms(30));
    assert!(y(&m, 0), "held 20 ms");
    // A glitch shorter than the filter never reaches the program.
    m.set_input(0, false);
    m.run_until(ms(40));
    m.set_input(0, true);
    m.run_until(ms(80));
    assert!(y(&m, 0));
    m.settings_mut().apply("!5").expect("!5");
    m.set_input(0, false);
    m.run_until(ms(129));
    assert!(y(&m, 0));
    m.run_until(ms(130));
    assert!(!y(&m, 0), "!5: 50 ms");
}

#[test]
fn servo_follows_the_analog_input() {
    let mut m = device("1 LD M57\n2 MOV\n3 D06\n4 D04\n5 OUT Y03");
    m.settings_mut().apply("X04A:401:100").expect("analog");
    m.settings_mut().apply("Y03R").expect("servo");
    use engine::io86a::peripherals::OutputSignal;
    for (mv, d06, pulse_us) in [(0, 100, 500), (2500, 300, 1500), (5000, 500, 2500)] {
        m.set_analog(0, mv);
        m.run_until(m.now() + ms(2));
        assert_eq!(m.last_scan().d[6], d06, "{mv} mV");
        assert_eq!(
            m.output_signal(0),
            OutputSignal::Servo(Some(SimTime::from_micros(pulse_us)))
        );
    }
    assert!(
        !m.last_scan().bit(Bit::X(4)),
        "X04 is no digital input in AD mode"
    );
}

#[test]
fn ir_buttons_light_y00_and_y01_while_held() {
    let text = "1 LD M57\n2 CMP\n3 K30727\n4 D03\n5 LD M61\n6 OUT Y00\n7 LD M57\n8 CMP\n9 K30855\n10 D03\n11 LD M61\n12 OUT Y01";
    let mut m = device(text);
    m.settings_mut().apply("X07I:10EF").expect("IR");
    let a_button = 0x10EF_7807;
    let b_button = 0x10EF_7887;
    m.set_ir(Some(a_button));
    m.run_until(ms(2));
    assert!(y(&m, 0) && !y(&m, 1), "A held");
    m.set_ir(None);
    m.run_until(ms(4));
    assert!(!y(&m, 0), "released");
    m.set_ir(Some(b_button));
    m.run_until(ms(6));
    assert!(y(&m, 1) && !y(&m, 0), "B held");
    m.set_ir(Some(0x00FF_7807)); // another remote's custom code
    m.run_until(ms(8));
    assert!(!y(&m, 0) && !y(&m, 1), "other custom codes are ignored");
    assert_eq!(m.last_ir(), Some(0x00FF_7807), "but `.` shows them");
}

#[test]
fn pwm_duty_follows_d05_while_y04_is_on() {
    use engine::io86a::peripherals::OutputSignal;
    let mut m = device("LD X00\nOUT Y04\nLD M57\nMOV K40 D05");
    m.settings_mut().apply("Y04M").expect("PWM");
    m.run_until(ms(2));
    assert_eq!(
        m.output_signal(1),
        OutputSignal::Pwm { hz: 400, duty: 0 },
        "Y04 off"
    );
    m.set_input(0, true);
    m.run_until(ms(4));
    assert_eq!(m.output_signal(1), OutputSignal::Pwm { hz: 400, duty: 40 });
}

#[test]
fn two_linked_devices_a_x00_lights_b_y00() {
    use engine::io86a::LinkedPair;
    // The manual's example: device A drives device B's Y00; B needs no ladder.
    let a = device("LD X00\nSETS Y00\nLDI X00\nRSTS Y00");
    let b = device("");
    let mut pair = LinkedPair::new(a, b);
    pair.run_until(ms(10));
    assert!(!y(&pair.b, 0));
    pair.a.set_input(0, true);
    pair.run_until(ms(12));
    assert!(y(&pair.b, 0), "A's X00 lights B's Y00");
    pair.a.set_input(0, false);
    pair.run_until(ms(14));
    assert!(!y(&pair.b, 0), "and RSTS puts it out");
}
