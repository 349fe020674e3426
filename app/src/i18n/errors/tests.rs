//! Every kind of each family said in Japanese without an English
//! sentence; English as the engine says it.

use super::*;
use engine::cases::{EdgeSeen, ExpectError};
use engine::events::EventError;
use engine::iec::data::DataType;
use engine::iec::il::IlError;
use engine::iec::{AddressError, LiteralError, VarError};
use engine::ladder::edit::{ClipError, Cursor, ReplaceError, VariableEditError};
use engine::ladder::target::ElementError;
use engine::ladder::variables::VariableError;
use engine::ladder::Pos;
use engine::plc::{DeviceError, Drives, Own, SettingError};
use engine::softplc::plc::SoftDeviceError;
use engine::softplc::pou::PouError;
use engine::time::TimeError;
use engine::{Located, MachineId, SimTime};

pub(super) fn s() -> String {
    "X".to_string()
}

/// Japanese, and no run of English words (`what` names the kind).
pub(super) fn is_japanese(what: &str, ja: &str) {
    assert!(ja.chars().any(|c| c > '\u{3000}'), "{what}: {ja}");
    assert_eq!(english_run(ja), None, "{what}: {ja}");
}

#[test]
fn the_english_rule_finds_a_sentence_and_lets_names_and_mnemonics_be() {
    assert_eq!(
        english_run("rung 1: the rung has no output"),
        Some("the rung has".into())
    );
    assert_eq!(english_run("Y00 was 0 at 4ms"), None, "words apart");
    assert_eq!(english_run("CAL TON0(IN := %IX0.0, PT := T#5s)"), None);
    assert_eq!(english_run("回路 1: ST count"), None);
    assert!(english_run("Unknown device: name a variable").is_some());
}

fn addresses() -> Vec<AddressError> {
    vec![
        AddressError::NoArea(s()),
        AddressError::BadSize(s()),
        AddressError::BadNumber(s()),
        AddressError::BitOutOfRange(s()),
        AddressError::WrongType {
            address: s(),
            data_type: DataType::Int,
        },
    ]
}

fn literals() -> Vec<LiteralError> {
    vec![
        LiteralError::Empty,
        LiteralError::UnknownType(s()),
        LiteralError::BadNumber(s()),
        LiteralError::OutOfRange {
            text: s(),
            data_type: DataType::Int,
        },
        LiteralError::BadTime(s()),
        LiteralError::WrongType {
            text: s(),
            expected: DataType::Int,
        },
        LiteralError::BadText(s()),
        LiteralError::TooLong(300),
        LiteralError::WideChar('字'),
    ]
}

#[test]
fn every_edit_refusal_is_said_in_japanese() {
    let mut all = vec![
        EditError::NoSuchRung(3),
        EditError::OutsideGrid(Cursor::default()),
        EditError::BranchOnTopRow,
        EditError::BranchNotContact,
        EditError::NothingToDo,
        EditError::BlockAcrossRungs,
        EditError::Clip(ClipError::NotAClip("expected value at line 1".into())),
        EditError::Clip(ClipError::TooLarge),
        EditError::Clip(ClipError::OutsideGrid),
        EditError::Clip(ClipError::Element {
            rung: 0,
            pos: Pos::new(0, 1),
            error: ElementError::ZeroTimer,
        }),
        EditError::Replace(ReplaceError::Empty),
        EditError::Replace(ReplaceError::Range(s())),
        EditError::Replace(ReplaceError::Counts {
            from: s(),
            old: 2,
            to: s(),
            new: 3,
        }),
        EditError::Variable(VariableEditError::NoSuchVariable(s())),
        EditError::Variable(VariableEditError::NameTaken(s())),
        EditError::Variable(VariableEditError::UseNoLongerFits(
            engine::ladder::LadderError::wiring(
                0,
                None,
                engine::ladder::LadderErrorKind::NoOutput,
                RungProblem::NoOutput,
            ),
        )),
    ];
    let declarations = [
        VariableError::BadName(s()),
        VariableError::BlockWithValue(s(), s()),
        VariableError::UnknownType(s(), s()),
    ];
    let declarations = declarations
        .into_iter()
        .chain(
            addresses()
                .into_iter()
                .map(|e| VariableError::Address(s(), e)),
        )
        .chain(
            literals()
                .into_iter()
                .map(|e| VariableError::Initial(s(), e)),
        );
    all.extend(declarations.map(|e| EditError::Variable(VariableEditError::Declaration(e))));
    for e in &all {
        is_japanese(&format!("{e:?}"), &edit_error(Lang::Ja, e));
        assert_eq!(edit_error(Lang::En, e), e.to_string());
    }
}

#[test]
fn every_wiring_problem_is_said_in_japanese() {
    use RungProblem as P;
    let all = [
        P::NoOutput,
        P::OutputNotLast,
        P::AfterOutput,
        P::LinkPastRung,
        P::OutputNotJoined,
        P::ShortCircuit,
        P::OutputOnRail,
        P::Dangling,
        P::DanglingWire,
        P::NoPath,
        P::TooLarge { rows: 2, width: 3 },
        P::InputInBoxColumn(s()),
        P::InputWithoutBox(s()),
        P::NoBoolInput(s(), s(), String::new()),
        P::NoBoolInput(s(), s(), "R".into()),
        P::FunctionInput(s()),
        P::InputTwice(s(), s()),
        P::InputLinkedAbove(s(), s()),
        P::InputWithoutNetwork,
        P::NotSeriesParallel,
        P::TooDeep,
    ];
    for p in &all {
        is_japanese(&format!("{p:?}"), &rung_problem(Lang::Ja, p));
        assert_eq!(rung_problem(Lang::En, p), p.to_string());
    }
}

#[test]
fn a_problem_in_the_listing_is_said_in_japanese_at_its_place() {
    use engine::ladder::{Element, Ladder, Rung};
    let mut rung = Rung::default();
    rung.set(Pos::new(0, 0), Some(Element::coil("Y00")));
    rung.set(Pos::new(0, 2), Some(Element::no("X00")));
    let ladder = Ladder {
        rungs: vec![rung],
        ..Ladder::default()
    };
    let errors = ladder.logic(MachineId::MinasecU).expect_err("misplaced");
    let ja = crate::i18n::engine::ladder_error(Lang::Ja, &errors[0]);
    assert!(ja.starts_with("回路 1、行 1、列 3: 出力の後には"), "{ja}");
    is_japanese("the problem", &ja);
}

fn times() -> Vec<TimeError> {
    vec![
        TimeError::BadNumber(s()),
        TimeError::BadUnit(s()),
        TimeError::Negative(s()),
        TimeError::Exponent(s()),
        TimeError::TooLong(s()),
    ]
}

fn devices() -> Vec<DeviceError> {
    vec![
        DeviceError::Own(Own::new(SoftDeviceError::Unknown("%IX0.0".into()))),
        DeviceError::Own(Own::new(SoftDeviceError::NoOutput {
            block: s(),
            pin: s(),
        })),
        DeviceError::Own(Own::new(SoftDeviceError::BlockOutput(s()))),
        DeviceError::Own(Own::new(SoftDeviceError::Value {
            device: s(),
            data_type: DataType::Int,
            value: s(),
        })),
        DeviceError::Own(Own::new(engine::minasec::isa::OperandError::UnknownDevice(
            s(),
        ))),
        DeviceError::Own(Own::new(engine::io86a::isa::OperandError::NotAWord(s()))),
        DeviceError::ArduinoPin(s()),
        DeviceError::AvrBit(s()),
        DeviceError::AvrTimer(s()),
        DeviceError::Constant(s()),
        DeviceError::NotAnInput {
            device: s(),
            drives: Drives::Terminals("X00-X07"),
        },
        DeviceError::NotAnInput {
            device: s(),
            drives: Drives::TerminalsAndButton("X00-X07", "CNTCLR"),
        },
        DeviceError::NotAnInput {
            device: s(),
            drives: Drives::Bits,
        },
        DeviceError::IsAnOutput {
            device: s(),
            drives: Drives::Terminals("X00-X07"),
        },
        DeviceError::BitValue(s()),
        DeviceError::NeedsAnalogMode(s()),
        DeviceError::NeedsVoltage(s()),
        DeviceError::IrFrame(s()),
    ]
}

#[test]
fn every_test_error_is_said_in_japanese() {
    let mut expects: Vec<ExpectError> = vec![
        ExpectError::Form(s()),
        ExpectError::Value(s()),
        ExpectError::OutOfRange(s()),
        ExpectError::Window,
        ExpectError::Text(s()),
        ExpectError::TextOrder("<"),
    ];
    expects.extend(times().into_iter().map(ExpectError::Time));
    let mut events = vec![
        EventError::FieldCount(2),
        EventError::MissingDevice,
        EventError::BadValue(s()),
        EventError::TooMany(9),
    ];
    events.extend(times().into_iter().map(EventError::Time));
    let mut all: Vec<CaseError> = expects
        .into_iter()
        .map(|e| CaseError::Expect(0, e))
        .collect();
    all.push(CaseError::Events(
        events.into_iter().map(|e| Located::new(1, e)).collect(),
    ));
    all.push(CaseError::TooLong);
    let settings = [
        SettingError::Unknown {
            machine: MachineId::Io86a,
            name: s(),
            takes: "scan",
        },
        SettingError::CounterPreset(s()),
        SettingError::PeriodOutOfRange {
            what: "scan",
            period: SimTime::from_millis(0),
            max: SimTime::from_millis(1000),
        },
        SettingError::AvrScan(SimTime::from_millis(0)),
        SettingError::Choice {
            setting: "chip",
            value: s(),
            choices: "ATmega328P",
        },
        SettingError::ChipTooSmall {
            step: 9,
            capacity: 8,
        },
        SettingError::Time(TimeError::BadUnit(s())),
    ];
    let plcs = devices()
        .into_iter()
        .map(PlcError::Device)
        .chain(settings.into_iter().map(PlcError::Setting))
        .chain([
            PlcError::NotThisMachine {
                machine: MachineId::SoftPlc,
                lacks: "front panel",
            },
            PlcError::Program(vec![Located::new(2, Own::new(LoadError::Undeclared(s())))]),
        ]);
    all.extend(plcs.map(|e| CaseError::Device(0, e)));
    for e in &all {
        is_japanese(&format!("{e:?}"), &case_error(Lang::Ja, e));
        assert_eq!(case_error(Lang::En, e), e.to_string());
    }
}

#[test]
fn every_observation_of_a_failed_expectation_is_said_in_japanese() {
    let at = SimTime::from_millis(5);
    let observed = [
        Observed::Was {
            device: s(),
            value: "0".into(),
            at,
        },
        Observed::NumberNotText {
            device: s(),
            value: "1".into(),
        },
        Observed::TextNotNumber {
            device: s(),
            value: "'a'".into(),
        },
        Observed::NoEdge {
            device: s(),
            falling: false,
            seen: EdgeSeen::Stayed("0".into()),
        },
        Observed::NoEdge {
            device: s(),
            falling: true,
            seen: EdgeSeen::Went {
                first: "1".into(),
                last: "1".into(),
                opposite: Some(at),
            },
        },
        Observed::NoEdge {
            device: s(),
            falling: true,
            seen: EdgeSeen::Went {
                first: "1".into(),
                last: "0".into(),
                opposite: None,
            },
        },
    ];
    for o in &observed {
        is_japanese(&format!("{o:?}"), &super::observed(Lang::Ja, o));
        assert_eq!(super::observed(Lang::En, o), o.to_string());
    }
}

#[test]
fn every_typed_program_error_is_said_in_japanese() {
    let mut ils = vec![
        IlError::UnknownOperator(s()),
        IlError::BadModifier(s()),
        IlError::LabelAlone,
        IlError::NoOperand(s()),
        IlError::NeedsLabel(s()),
        IlError::NeedsOperand(s()),
        IlError::OperandCount(s(), 2),
        IlError::BadName(s()),
        IlError::BadCall(s()),
        IlError::OpenComment,
        IlError::DuplicateLabel {
            label: s(),
            first: 1,
        },
        IlError::SecondProgram(1),
        IlError::TwiceGiven(s()),
        IlError::EmptyParameter,
    ];
    ils.extend(addresses().into_iter().map(IlError::Address));
    ils.extend(literals().into_iter().map(IlError::Literal));
    let vars = [
        VarError::Syntax(s()),
        VarError::BadName(s()),
        VarError::Duplicate {
            name: s(),
            first: 1,
        },
        VarError::UnknownType(s()),
        VarError::StringLength(s()),
        VarError::BlockWithValue(s()),
        VarError::Unbalanced(s()),
    ];
    let pous = [
        PouError::BadName(s()),
        PouError::Nested,
        PouError::NoStart,
        PouError::NeverEnded(s()),
        PouError::Duplicate {
            name: s(),
            first: 1,
        },
    ];
    let all = ils
        .into_iter()
        .map(LoadError::Il)
        .chain(vars.into_iter().map(LoadError::Var))
        .chain(pous.into_iter().map(LoadError::Pou))
        .chain([
            LoadError::Undeclared(s()),
            LoadError::UntypedAddress(s()),
            LoadError::NoLabel(s()),
            LoadError::UnknownResult,
            LoadError::Unbalanced,
            LoadError::Unclosed,
            LoadError::Mix(DataType::Int, DataType::Real),
            LoadError::NotBits("LDN".into(), DataType::Real),
            LoadError::NotFor(DataType::String),
            LoadError::NeedsBool("JMPC"),
            LoadError::NoPin {
                block: "TON".into(),
                pin: "XX".into(),
                output: false,
            },
            LoadError::NoPin {
                block: "TON".into(),
                pin: "XX".into(),
                output: true,
            },
            LoadError::NotAnInstance(s()),
        ]);
    for e in all {
        is_japanese(&format!("{e:?}"), &load_error(Lang::Ja, &e));
        assert_eq!(load_error(Lang::En, &e), e.to_string());
    }
}

#[test]
fn a_soft_plc_program_error_is_said_in_japanese_from_the_loader() {
    let errors = engine::softplc::Program::load("PROGRAM p\n  LD\nEND_PROGRAM\n")
        .expect_err("LD needs an operand");
    let ja = load_error(Lang::Ja, &errors[0].error);
    assert_eq!(ja, "`LD` にはオペランドが必要です");
    // A SEL whose two values are of two types: a kind, not the English.
    // (tests/e2e/test_japanese.py types this text.)
    let errors = engine::softplc::Program::load(
        "PROGRAM p\nVAR\n  b : BOOL;\n  i : INT;\n  r : REAL;\nEND_VAR\n  LD b\n  SEL i, r\n  ST i\n  LD r\n  SHL 1\n  ST r\nEND_PROGRAM\n",
    )
    .expect_err("SEL of an INT and a REAL, a shift of a REAL");
    let said: Vec<(usize, String)> = errors
        .iter()
        .map(|e| (e.line, load_error(Lang::Ja, &e.error)))
        .collect();
    assert!(
        said.contains(&(8, "SEL の 2 つの値は同じ型にしてください".into())),
        "{said:?}"
    );
    assert!(
        said.contains(&(11, "SHL, SHR, ROL, ROR は整数を整数ぶんシフトします".into())),
        "{said:?}"
    );
    assert_eq!(
        load_error(Lang::En, &errors[0].error),
        "SEL's two values have one type"
    );
}

#[test]
fn every_minasec_program_text_error_is_said_in_japanese() {
    use engine::minasec::isa::{Opcode, OperandError};
    use engine::minasec::AsmError as A;
    let all = [
        A::TooManyLines(9),
        A::BadStepNumber(s()),
        A::StepOutOfOrder {
            found: 3,
            expected: 4,
        },
        A::MissingOpcode,
        A::UnknownOpcode(s()),
        A::MissingOperand(Opcode::Ld),
        A::Operand(OperandError::UnknownDevice(s())),
        A::Operand(OperandError::BadRawAddress(s())),
        A::Unexpected(s()),
        A::BinaryMismatch {
            written: "1".into(),
            expected: "0".into(),
        },
        A::TooManySteps(300),
    ];
    for e in &all {
        is_japanese(&format!("{e:?}"), &minasec_asm(Lang::Ja, e));
        assert_eq!(minasec_asm(Lang::En, e), e.to_string());
    }
    let errors = engine::minasec::Program::parse("LD X00\nFOO X01\n").expect_err("FOO");
    assert_eq!(
        minasec_asm(Lang::Ja, &errors[0].error),
        "不明な命令 \"FOO\": MINASEC-U の命令は LD LDI AND ANDI OR ORI ST STI です"
    );
}
