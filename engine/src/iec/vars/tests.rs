use super::*;
use crate::iec::address::Size;

const HEADER: &str = "\
VAR
  start AT %IX0.0 : BOOL;      (* start button *)
  count : INT := 5;
  level AT %IW0 : INT;
  delay : ton;
END_VAR
(* the body is not read here *)
LD start
VAR_RETAIN
  total : UDINT := 16#FFFF_FFFF;
END_VAR
";

#[test]
fn a_header_with_located_named_retained_and_block_variables() {
    let vars = parse_vars(HEADER).expect("it reads");
    assert_eq!(vars.len(), 5);
    assert_eq!(vars[0].name, "start");
    assert_eq!(vars[0].comment, "start button");
    assert_eq!(
        vars[0].address.map(|a| a.to_string()),
        Some("%IX0.0".into())
    );
    assert_eq!(
        vars[1].kind,
        Kind::Value {
            data_type: DataType::Int,
            init: Data::integer(DataType::Int, 5)
        }
    );
    assert_eq!(vars[2].address.map(|a| a.size), Some(Size::Word));
    assert_eq!(vars[3].kind, Kind::Block("TON".into()));
    assert!(vars[4].retain && !vars[1].retain);
    assert_eq!(
        vars[4].kind,
        Kind::Value {
            data_type: DataType::Udint,
            init: Data::integer(DataType::Udint, 0xFFFF_FFFF)
        }
    );
}

fn errors(text: &str) -> Vec<(usize, String)> {
    crate::iec::said(parse_vars(text))
}

#[test]
fn every_bad_line_is_named_with_why() {
    let got = errors(
        "VAR\n\
         a : INT\n\
         1x : BOOL;\n\
         b : FLOAT;\n\
         c AT %QW2 : BOOL;\n\
         d : INT := 70000;\n\
         e AT %IX0.0 : TON;\n\
         A : BOOL;\n\
         a2 : INT;\n\
         END_VAR\n\
         END_VAR",
    );
    let lines: Vec<usize> = got.iter().map(|(l, _)| *l).collect();
    assert_eq!(lines, [2, 3, 4, 5, 6, 7, 11], "{got:?}");
    assert!(got[0].1.contains("is not a declaration"), "{got:?}");
    assert!(got[1].1.contains("`1x` is not a name"));
    assert_eq!(got[2].1, "unknown type `FLOAT`");
    assert_eq!(got[3].1, "a BOOL cannot be at %QW2");
    assert!(got[4].1.contains("out of range for INT"));
    assert!(got[5].1.contains("is a function block"));
    assert_eq!(got[6].1, "`END_VAR` without its pair");
}

#[test]
fn a_name_twice_in_any_case_is_refused_at_the_second() {
    let got = errors("VAR\n  Lamp : BOOL;\n  LAMP : BOOL;\nEND_VAR");
    assert_eq!(
        got,
        [(3, "`LAMP` is declared twice (first on line 2)".to_string())]
    );
}

#[test]
fn an_unclosed_var_is_named_at_its_line() {
    assert_eq!(
        errors("LD x\nVAR\n  x : BOOL;"),
        [(2, "`VAR` without its pair".to_string())]
    );
}
