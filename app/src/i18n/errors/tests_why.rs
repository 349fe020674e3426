//! One of each type and call problem the soft PLC's loader gives (its
//! kinds with their arguments, issue #49), for the walk of every program
//! error said in Japanese.

use super::tests::s;
use engine::iec::data::DataType;
use engine::iec::LiteralError;
use engine::softplc::LoadError;

/// One of each type and call problem the loader gives.
pub(super) fn types_and_calls() -> Vec<LoadError> {
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
