//! Every kind of the share link's, a break condition's and each
//! machine's program text errors said in Japanese without an English
//! sentence; English as the engine says it (issue #49).

use super::tests::{is_japanese, s};
use super::*;
use engine::MachineId;

#[test]
fn every_share_link_error_is_said_in_japanese() {
    use engine::formats::share::ShareError;
    let mut all = vec![
        ShareError::Version(s()),
        ShareError::Base64,
        ShareError::Inflate,
        ShareError::TooLong(9),
        ShareError::RungTooLarge {
            rung: 1,
            rows: 2,
            columns: 3,
        },
        ShareError::Data {
            at: 4,
            what: "a bad element tag",
        },
    ];
    for what in [
        "rungs",
        "links in one rung",
        "test cases",
        "expectations in one test case",
        "plant wiring lines",
        "plant faults",
        "plant parameters",
        "pins of one box",
        "variables",
        "settings",
        "device comments",
    ] {
        all.push(ShareError::TooMany {
            what,
            count: 9,
            limit: 1,
        });
    }
    for e in &all {
        is_japanese(&format!("{e:?}"), &share_error(Lang::Ja, e));
        assert_eq!(share_error(Lang::En, e), e.to_string());
    }
}

#[test]
fn a_break_condition_refused_is_said_in_japanese() {
    use engine::record::{Condition, ConditionError};
    let machine = engine::io86a::plc::Io86aPlc::new();
    let refused = |text: &str| match Condition::parse(text, &machine) {
        Err(e) => e,
        Ok(_) => panic!("{text} is refused"),
    };
    let form = refused("Y01 jumps");
    let device = refused("Q99 rises");
    assert!(matches!(device, ConditionError::Device(_)), "{device:?}");
    for e in [&form, &device] {
        is_japanese(&format!("{e:?}"), &condition_error(Lang::Ja, e));
        assert_eq!(condition_error(Lang::En, e), e.to_string());
    }
}

#[test]
fn every_io86a_program_text_error_is_said_in_japanese() {
    use engine::io86a::asm::AsmError as A;
    use engine::io86a::isa::{parse_bit, Bit};
    let bit = Bit::X(0);
    let all = [
        A::TooManyLines(9),
        A::StepNumber {
            found: s(),
            expected: 2,
        },
        A::MissingInstruction,
        A::UnknownMnemonic(s()),
        A::MissingOperand("OUT", 1),
        A::MissingOperand("MOV", 2),
        A::Unexpected(s()),
        A::StrayOperand(s()),
        A::Operand(parse_bit("Q9").expect_err("no Q")),
        A::OutputToInput("OUT", bit),
        A::SystemRelay("OUT", bit),
        A::NotAllowed("PLS", bit),
        A::BadPreset(s()),
        A::NotARegister("MOV", s()),
        A::NoBlockToJoin("ORB"),
        A::NoRung,
        A::TooManySteps(600),
    ];
    for e in &all {
        is_japanese(&format!("{e:?}"), &io86a_asm(Lang::Ja, e));
        assert_eq!(io86a_asm(Lang::En, e), e.to_string());
    }
    let errors = engine::io86a::Program::parse("1 LD X00\n2 FOO X01\n").expect_err("FOO");
    assert!(
        io86a_asm(Lang::Ja, &errors[0].error).starts_with("不明な命令 \"FOO\""),
        "{errors:?}"
    );
}

#[test]
fn every_avr_program_text_error_is_said_in_japanese() {
    use engine::avr::asm::AsmError as A;
    use engine::avr::ProgramError as P;
    let asm = [
        A::TooManyLines(9),
        A::UnknownDirective(s()),
        A::EquSyntax,
        A::Redefined(s(), 1),
        A::UnknownSymbol(s()),
        A::Expression(s()),
        A::DivisionByZero(s()),
        A::Overflow(s()),
        A::TooDeep(s()),
        A::Range(s(), 300),
        A::ByteOutsideDseg,
        A::DbInDseg,
    ];
    let mut all: Vec<P> = asm.into_iter().map(P::Asm).collect();
    all.extend([
        P::UnknownCode(20),
        P::Register(40),
        P::Pattern(3),
        P::TimerAddress(5),
        P::NoTimerTop,
        P::NotOperand,
        P::ShortRecord(3),
        P::NoEnd,
    ]);
    for e in &all {
        is_japanese(&format!("{e:?}"), &avr_program(Lang::Ja, e));
        assert_eq!(avr_program(Lang::En, e), e.to_string());
    }
}

#[test]
fn every_arduino_program_text_error_is_said_in_japanese() {
    use engine::arduino::isa::AsmError as A;
    let all = [
        A::TooManyLines(9),
        A::UnknownMnemonic(s()),
        A::MissingOperand("LD"),
        A::BadOperand(s()),
        A::OutToInput(s()),
        A::BadStep(s()),
        A::Unexpected(s()),
        A::MissingMnemonic,
        A::StepOrder {
            found: s(),
            next: 2,
        },
        A::TooManySteps {
            step: 300,
            capacity: 256,
        },
    ];
    for e in &all {
        is_japanese(&format!("{e:?}"), &arduino_asm(Lang::Ja, e));
        assert_eq!(arduino_asm(Lang::En, e), e.to_string());
    }
}

#[test]
fn load_as_ladder_says_each_machines_text_errors_in_japanese() {
    use engine::ladder::decompile::decompile_text;
    for (machine, text) in [
        (MachineId::Io86a, "1 LD X00\n2 FOO X01\n"),
        (MachineId::MinasecU, "LD X00\nFOO X01\n"),
        (MachineId::ArduinoPlc, "0 LD X000\n1 FOO\n"),
        (MachineId::AvrPlc, ".foo\n"),
    ] {
        let e = decompile_text(machine, text, 10).expect_err("FOO");
        let ja = text_error(Lang::Ja, &e);
        assert!(
            ja.starts_with("2 行目: ") || ja.starts_with("1 行目: "),
            "{machine}: {ja}"
        );
        is_japanese(&format!("{machine}: {e}"), &ja);
        assert_eq!(text_error(Lang::En, &e), e.to_string());
    }
}
