use super::*;
use crate::iec::literal::parse_literal;
use crate::iec::literal::LiteralError;

fn int(t: DataType, v: i128) -> Data {
    Data::integer(t, v)
}

#[test]
fn integers_wrap_in_their_width() {
    use Arith::*;
    let i = |v| int(DataType::Int, v);
    assert_eq!(i(32767).arith(Add, &i(1)), Some(i(-32768)));
    assert_eq!(i(-32768).arith(Sub, &i(1)), Some(i(32767)));
    assert_eq!(i(300).arith(Mul, &i(300)), Some(i(90000 - 65536)));
    let u = |v| int(DataType::Uint, v);
    assert_eq!(u(0).arith(Sub, &u(1)), Some(u(65535)));
    assert_eq!(u(65535).to_value(), Value::Uint(65535));
    let ul = |v| int(DataType::Ulint, v);
    assert_eq!(
        ul(i128::from(u64::MAX)).arith(Mul, &ul(i128::from(u64::MAX))),
        Some(ul(1))
    );
    assert_eq!(
        int(DataType::Lint, i128::from(i64::MIN)).negate(),
        Some(int(DataType::Lint, i128::from(i64::MIN)))
    );
}

#[test]
fn division_truncates_and_by_zero_gives_zero() {
    use Arith::*;
    let d = |v| int(DataType::Dint, v);
    assert_eq!(d(7).arith(Div, &d(2)), Some(d(3)));
    assert_eq!(d(-7).arith(Div, &d(2)), Some(d(-3)));
    assert_eq!(d(-7).arith(Mod, &d(2)), Some(d(-1)));
    assert_eq!(d(5).arith(Div, &d(0)), Some(d(0)));
    assert_eq!(d(5).arith(Mod, &d(0)), Some(d(0)));
    let Some(Data::Real(r)) = Data::Real(1.0).arith(Div, &Data::Real(0.0)) else {
        panic!("a REAL divides");
    };
    assert!(r.is_infinite());
    assert_eq!(Data::Real(1.0).arith(Mod, &Data::Real(2.0)), None);
}

#[test]
fn different_types_do_not_mix() {
    let a = int(DataType::Int, 1);
    let b = int(DataType::Dint, 1);
    assert_eq!(a.arith(Arith::Add, &b), None);
    assert_eq!(a.compare(&b), None);
    assert_eq!(Data::Real(f32::NAN).compare(&Data::Real(1.0)), None);
    assert_eq!(
        int(DataType::Word, 0xFFFF).compare(&int(DataType::Word, 1)),
        Some(Ordering::Greater),
        "a WORD compares unsigned"
    );
}

#[test]
fn conversions_wrap_round_and_saturate() {
    assert_eq!(
        int(DataType::Dint, 70000).convert(DataType::Int),
        int(DataType::Int, 70000 - 65536)
    );
    assert_eq!(
        int(DataType::Int, -1).convert(DataType::Uint),
        int(DataType::Uint, 65535)
    );
    assert_eq!(
        Data::Real(2.5).convert(DataType::Int),
        int(DataType::Int, 3)
    );
    assert_eq!(
        Data::Real(-2.5).convert(DataType::Int),
        int(DataType::Int, -3)
    );
    assert_eq!(
        Data::Real(1e9).convert(DataType::Int),
        int(DataType::Int, 32767)
    );
    assert_eq!(
        Data::Real(-5.0).convert(DataType::Uint),
        int(DataType::Uint, 0)
    );
    assert_eq!(
        Data::Real(f32::NAN).convert(DataType::Dint),
        int(DataType::Dint, 0)
    );
    assert_eq!(
        int(DataType::Int, 3).convert(DataType::Real),
        Data::Real(3.0)
    );
    assert_eq!(
        Data::Time(1_500_000_000).convert(DataType::Dint),
        int(DataType::Dint, 1500)
    );
    assert_eq!(
        int(DataType::Dint, 250).convert(DataType::Time),
        Data::Time(250_000_000)
    );
    assert_eq!(
        Data::Bool(true).convert(DataType::Int),
        int(DataType::Int, 1)
    );
    assert_eq!(
        int(DataType::Int, 2).convert(DataType::Bool),
        Data::Bool(true)
    );
    assert_eq!(Data::Time(2_000_000).to_value(), Value::Int(2));
}

#[test]
fn words_bitwise_shifted_and_rotated_in_their_width() {
    let w = |v| int(DataType::Word, v);
    assert_eq!(w(0xF0F0).bitwise(Bitwise::And, &w(0xFF00)), Some(w(0xF000)));
    assert_eq!(w(0xF0F0).bitwise(Bitwise::Xor, &w(0xFFFF)), Some(w(0x0F0F)));
    assert_eq!(w(0x00FF).invert(), Some(w(0xFF00)));
    assert_eq!(int(DataType::Int, 0).invert(), Some(int(DataType::Int, -1)));
    assert_eq!(
        Data::Bool(true).bitwise(Bitwise::Or, &Data::Bool(false)),
        Some(Data::Bool(true))
    );
    assert_eq!(
        w(0x8001).shift(Shift::Shl, &Data::integer(DataType::Udint, 1)),
        Some(w(0x0002))
    );
    assert_eq!(
        w(0x8001).shift(Shift::Shr, &Data::integer(DataType::Udint, 1)),
        Some(w(0x4000))
    );
    assert_eq!(
        w(0x8001).shift(Shift::Rol, &Data::integer(DataType::Udint, 1)),
        Some(w(0x0003))
    );
    assert_eq!(
        w(0x8001).shift(Shift::Ror, &Data::integer(DataType::Udint, 1)),
        Some(w(0xC000))
    );
    assert_eq!(
        w(0x8001).shift(Shift::Rol, &Data::integer(DataType::Udint, 17)),
        Some(w(0x0003)),
        "modulo the width"
    );
    assert_eq!(
        w(0x8001).shift(Shift::Shl, &Data::integer(DataType::Udint, 16)),
        Some(w(0))
    );
    assert_eq!(
        int(DataType::Int, -2).shift(Shift::Shr, &Data::integer(DataType::Udint, 1)),
        Some(int(DataType::Int, 0x7FFF))
    );
    let l = |v| int(DataType::Ulint, v);
    assert_eq!(
        l(1).shift(Shift::Ror, &Data::integer(DataType::Udint, 1)),
        Some(l(1 << 63))
    );
    assert_eq!(
        l(1).shift(Shift::Shl, &Data::integer(DataType::Udint, 64)),
        Some(l(0))
    );
    assert_eq!(
        Data::Real(1.0).shift(Shift::Shl, &Data::integer(DataType::Udint, 1)),
        None
    );
}

#[test]
fn min_max_limit_and_sel() {
    let i = |v| int(DataType::Int, v);
    assert_eq!(min(&i(3), &i(-2)), Some(i(-2)));
    assert_eq!(max(&i(3), &i(-2)), Some(i(3)));
    assert_eq!(limit(&i(0), &i(150), &i(100)), Some(i(100)));
    assert_eq!(limit(&i(0), &i(-5), &i(100)), Some(i(0)));
    assert_eq!(limit(&i(0), &i(42), &i(100)), Some(i(42)));
    assert_eq!(min(&i(1), &int(DataType::Dint, 1)), None);
    assert_eq!(select(false, &i(1), &i(2)), i(1));
    assert_eq!(select(true, &i(1), &i(2)), i(2));
}

#[test]
fn literals_of_every_kind() {
    let p = |s| parse_literal(s, None);
    assert_eq!(p("TRUE"), Ok(Data::Bool(true)));
    assert_eq!(p("42"), Ok(int(DataType::Dint, 42)));
    assert_eq!(p("-5"), Ok(int(DataType::Dint, -5)));
    assert_eq!(p("16#FF"), Ok(int(DataType::Dint, 255)));
    assert_eq!(p("2#1010_0101"), Ok(int(DataType::Dint, 0b1010_0101)));
    assert_eq!(p("INT#-5"), Ok(int(DataType::Int, -5)));
    assert_eq!(p("UINT#16#FFFF"), Ok(int(DataType::Uint, 65535)));
    assert_eq!(p("1.5"), Ok(Data::Real(1.5)));
    assert_eq!(p("1.0E3"), Ok(Data::Real(1000.0)));
    assert_eq!(p("REAL#2"), Ok(Data::Real(2.0)));
    assert_eq!(p("T#500ms"), Ok(Data::Time(500_000_000)));
    assert_eq!(p("TIME#1h2m3.5s"), Ok(Data::Time(3_723_500_000_000)));
    assert_eq!(p("t#-1s"), Ok(Data::Time(-1_000_000_000)));
    assert_eq!(p("5000000000"), Ok(int(DataType::Lint, 5_000_000_000)));
    assert_eq!(
        parse_literal("7", Some(DataType::Word)),
        Ok(int(DataType::Word, 7))
    );
}

#[test]
fn bad_literals_say_why() {
    let p = |s| parse_literal(s, None);
    assert_eq!(p(""), Err(LiteralError::Empty));
    assert!(matches!(p("FOO#1"), Err(LiteralError::UnknownType(t)) if t == "FOO"));
    assert!(matches!(
        p("INT#40000"),
        Err(LiteralError::OutOfRange {
            data_type: DataType::Int,
            ..
        })
    ));
    assert!(matches!(p("UINT#-1"), Err(LiteralError::OutOfRange { .. })));
    assert!(matches!(p("16#FG"), Err(LiteralError::BadNumber(_))));
    assert!(matches!(p("1__0"), Err(LiteralError::BadNumber(_))));
    assert!(matches!(p("T#5"), Err(LiteralError::BadTime(_))));
    assert!(
        matches!(p("T#1s2h"), Err(LiteralError::BadTime(_))),
        "largest unit first"
    );
    assert!(matches!(p("T#1s1s"), Err(LiteralError::BadTime(_))));
    assert!(matches!(
        parse_literal("INT#5", Some(DataType::Dint)),
        Err(LiteralError::WrongType {
            expected: DataType::Dint,
            ..
        })
    ));
    assert!(matches!(
        parse_literal("2", Some(DataType::Bool)),
        Err(LiteralError::WrongType { .. })
    ));
    assert!(matches!(
        p("99999999999999999999999"),
        Err(LiteralError::OutOfRange {
            data_type: DataType::Lint,
            ..
        })
    ));
    assert!(matches!(p("12ab"), Err(LiteralError::BadNumber(_))));
    assert_eq!(
        p("INT#40000").map_err(|e| e.to_string()),
        Err("`INT#40000` is out of range for INT".to_string())
    );
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    fn int_type() -> impl Strategy<Value = DataType> {
        prop::sample::select(
            DataType::ALL
                .into_iter()
                .filter(|t| t.bits().is_some())
                .collect::<Vec<_>>(),
        )
    }

    proptest! {
        #[test]
        fn any_text_is_a_literal_or_says_why(text in "\\PC{0,24}") {
            let _ = parse_literal(&text, None);
            for t in DataType::ALL {
                let _ = parse_literal(&text, Some(t));
            }
        }

        #[test]
        fn integer_results_stay_in_their_range(
            t in int_type(), a in any::<i64>(), b in any::<i64>(), op in 0usize..5
        ) {
            let op = [Arith::Add, Arith::Sub, Arith::Mul, Arith::Div, Arith::Mod][op];
            let (x, y) = (Data::integer(t, i128::from(a)), Data::integer(t, i128::from(b)));
            let Some(Data::Int(rt, _)) = x.arith(op, &y) else {
                panic!("integers of one type give an integer");
            };
            prop_assert_eq!(rt, t);
            let (lo, hi) = t.range().expect("an integer type");
            for v in [x.arith(op, &y), x.negate(), Some(x.convert(DataType::Int)), Some(Data::Real(a as f32).convert(t))] {
                if let Some(Data::Int(vt, _)) = v {
                    let w = match v.as_ref().map(Data::to_value) {
                        Some(Value::Int(w)) => i128::from(w),
                        Some(Value::Uint(w)) => i128::from(w),
                        other => panic!("{other:?}"),
                    };
                    let (lo, hi) = if vt == t { (lo, hi) } else { vt.range().expect("int") };
                    prop_assert!((lo..=hi).contains(&w), "{v:?}");
                }
            }
        }
    }
}
