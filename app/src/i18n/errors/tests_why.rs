//! One of each type and call problem the soft PLC's loader gives (its
//! kinds with their arguments, issue #49), for the walk of every program
//! error said in Japanese; every step with no ladder form said so.

use super::tests::{is_japanese, s};
use super::*;
use engine::iec::data::DataType;
use engine::iec::LiteralError;
use engine::softplc::LoadError;

#[test]
fn every_type_and_call_problem_is_said_in_japanese() {
    for e in types_and_calls() {
        is_japanese(&format!("{e:?}"), &load_error(Lang::Ja, &e));
        assert_eq!(load_error(Lang::En, &e), e.to_string());
    }
}

/// One of each type and call problem the loader gives.
fn types_and_calls() -> Vec<LoadError> {
    use engine::runtime::ldmicro::format::FormatError as F;
    use engine::runtime::ldmicro::printf::PrintfError as P;
    use engine::softplc::program::{CallWhy as C, TypeWhy as T};
    let types = [
        T::NegNumber,
        T::ShiftIntegers,
        T::StringConversion,
        T::Convert {
            current: DataType::Dint,
            from: DataType::Int,
        },
        T::SelectBool,
        T::SelectOneType,
        T::TextInput {
            block: "LD_STRING".into(),
            pin: "FMT".into(),
        },
        T::Pin {
            block: "TON".into(),
            pin: "IN".into(),
            is: DataType::Bool,
        },
        T::NotInstance {
            name: s(),
            pin: "Q".into(),
        },
        T::ReadOnly(s()),
        T::JumpBrings {
            line: 7,
            label: s(),
            used: DataType::Int,
            brings: Some(DataType::Dint),
        },
        T::JumpBrings {
            line: 7,
            label: s(),
            used: DataType::Int,
            brings: None,
        },
        T::LabelTypes {
            label: s(),
            types: (DataType::Int, DataType::Dint),
        },
        T::Text(LiteralError::WideChar('\u{100}')),
        T::BlockAsValue(s()),
        T::StoreLiteral,
        T::SetBool {
            op: "S".into(),
            what: s(),
            is: DataType::Int,
        },
        T::Store {
            current: DataType::Bool,
            what: s(),
            needs: DataType::Int,
        },
    ];
    let printf = [
        P::Conversion("%s".into()),
        P::Second,
        P::Star,
        P::NoValue,
        P::Length("%lc".into()),
    ];
    let format = [
        F::TwoNumbers,
        F::BadEscape("q".into()),
        F::NoVariable,
        F::NoNumber,
        F::NotAByte('\u{100}'),
    ];
    let pin = || "FMT".to_string();
    let mut calls = vec![
        C::NeedsInstance,
        C::TextTwice {
            instance: s(),
            pin: pin(),
        },
        C::NotVariable(s()),
        C::InputRead {
            instance: s(),
            pin: "IN".into(),
            block: "TON".into(),
        },
        C::Instances(s()),
        C::Nesting {
            name: s(),
            holds: None,
        },
        C::Nesting {
            name: s(),
            holds: Some("A".into()),
        },
        C::BodySteps,
        C::Variables(s()),
    ];
    calls.extend(printf.map(|error| C::Printf { pin: pin(), error }));
    calls.extend(format.map(|error| C::Format { pin: pin(), error }));
    types
        .into_iter()
        .map(LoadError::Type)
        .chain(calls.into_iter().map(LoadError::Call))
        .collect()
}

#[test]
fn every_step_with_no_ladder_form_is_said_in_japanese() {
    use engine::ladder::decompile::{DecompileError, StepError, StepWhy as S, TextError};
    use engine::ladder::net::TooLarge;
    let whys = [
        S::AfterOutputs,
        S::UsedAgain,
        S::NoLoad,
        S::TwoBlocks,
        S::TooDeep,
        S::OutputFirst,
        S::Labels,
        S::NoOpen,
        S::Line("ADD 1".into()),
        S::BoxWithoutOutput,
        S::ParallelBox,
        S::NoPowerOut,
        S::EdgeOnLiteral,
        S::TimerPreset,
        S::Call("t0".into()),
        S::NoLabel,
        S::NoBoxReads,
        S::Jump(3),
        S::Word(0xBEEF),
        S::RegisterValue,
        S::SecondDevice,
    ];
    let all = whys
        .into_iter()
        .map(|why| DecompileError::Step(StepError { step: 2, why }))
        .chain([DecompileError::Drawing {
            rung: 1,
            size: TooLarge {
                rows: 9,
                columns: 9,
            },
        }]);
    for e in all.map(TextError::Decompile) {
        is_japanese(&format!("{e:?}"), &text_error(Lang::Ja, &e));
        assert_eq!(text_error(Lang::En, &e), e.to_string());
    }
    // A real one: the soft PLC's ADD has no ladder form.
    let e = engine::ladder::decompile::decompile_text(
        engine::MachineId::SoftPlc,
        "VAR\n  i : INT;\nEND_VAR\nLD i\nADD 1\nST i",
        10,
    )
    .expect_err("no ladder form");
    assert_eq!(
        text_error(Lang::Ja, &e),
        "ステップ 1: `ADD 1` はまだラダーにできません"
    );
    // (tests/e2e/test_japanese.py loads this one as a ladder.)
    let e = engine::ladder::decompile::decompile_text(
        engine::MachineId::Io86a,
        "LD X00\nSETS Y00\nEND\n",
        10,
    )
    .expect_err("no ladder form");
    assert_eq!(
        text_error(Lang::Ja, &e),
        "ステップ 1: SETS / RSTS は 2 つ目のデバイスを駆動します: ここではラダーにできません"
    );
}

#[test]
fn every_boards_own_setting_refusal_is_said_in_japanese() {
    use engine::io86a::peripherals::SettingError as Io;
    use engine::minasec::{SettingError as Mi, TimerId};
    use engine::plc::{Own, SettingError};
    let own = [
        Own::new(Mi::DelayOutOfRange {
            timer: TimerId::T0,
            delay: engine::SimTime::from_millis(50),
        }),
        Own::new(Mi::PresetOutOfRange(120)),
        Own::new(Mi::NoSuchInput(9)),
        Own::new(Mi::BadClock(s())),
        Own::new(Io::Unknown(s())),
        Own::new(Io::Analog(s())),
        Own::new(Io::CustomCode(s())),
        Own::new(Io::Filter(s())),
    ];
    for e in own.map(|o| PlcError::Setting(SettingError::Own(o))) {
        is_japanese(&format!("{e:?}"), &plc_error(Lang::Ja, &e));
        assert_eq!(plc_error(Lang::En, &e), e.to_string());
    }
    // A real one: MINASEC-U's counter set above 99.
    let mut plc = engine::machines::new_plc(engine::MachineId::MinasecU);
    let e = plc
        .apply(engine::plc::Command::Setting {
            name: "C0".into(),
            value: "120".into(),
        })
        .expect_err("0..99");
    assert_eq!(
        plc_error(Lang::Ja, &e),
        "カウンタの設定値 120 は範囲外です: 0..99 (BCD 2 桁)"
    );
}
