use super::*;
use crate::iec::data::DataType;

const PROGRAM: &str = "\
VAR
  lamp AT %QX0.0 : BOOL;
  delay : TON;
END_VAR
start:  LD    %IX0.0        (* a comment *)
        ANDN  stop
        ST    lamp
        LD    count
        ADD   INT#1
        ST    count
        GT    100
        JMPC  done
        CAL   delay(IN := lamp, PT := T#500ms, Q => late)
        AND(  a
        OR    b
        )
done:   RET
";

#[test]
fn a_program_reads_line_by_line() {
    let lines = parse_il(PROGRAM).expect("it reads");
    assert_eq!(lines.len(), 13);
    let first = &lines[0];
    assert_eq!(first.label.as_deref(), Some("start"));
    assert_eq!(first.operator, Operator::Ld);
    assert_eq!(first.line, 5);
    assert_eq!(
        first.operand,
        Some(Operand::Address(
            Address::parse("%IX0.0").expect("an address")
        ))
    );
    assert!(lines[1].negated && lines[1].operator == Operator::And);
    assert_eq!(
        lines[4].operand,
        Some(Operand::Literal(Data::integer(DataType::Int, 1)))
    );
    assert_eq!(lines[7].condition, Some(true));
    assert_eq!(lines[7].operand, Some(Operand::Name("done".into())));
    let call = &lines[8];
    assert_eq!(call.operator, Operator::Cal);
    assert_eq!(call.operand, Some(Operand::Name("delay".into())));
    assert_eq!(call.inputs[0], ("IN".into(), Operand::Name("lamp".into())));
    assert_eq!(
        call.inputs[1],
        ("PT".into(), Operand::Literal(Data::Time(500_000_000)))
    );
    assert_eq!(call.outputs, [("Q".to_string(), "late".to_string())]);
    assert!(lines[9].deferred && lines[9].operand == Some(Operand::Name("a".into())));
    assert_eq!(lines[11].operator, Operator::Close);
    assert_eq!(lines[12].label.as_deref(), Some("done"));
}

#[test]
fn modifiers_go_where_iec_allows_them() {
    let one = |text: &str| parse_il(text).map(|mut l| l.remove(0));
    assert!(one("LDN x").is_ok_and(|l| l.negated));
    assert!(one("STN x").is_ok_and(|l| l.negated));
    assert!(one("JMPCN out").is_ok_and(|l| l.condition == Some(false)));
    assert!(one("RETC").is_ok_and(|l| l.condition == Some(true)));
    assert!(one("ADD(").is_ok_and(|l| l.deferred && l.operand.is_none()));
    assert!(one("ld x").is_ok(), "any case");
}

fn errors(text: &str) -> Vec<(usize, String)> {
    crate::iec::said(parse_il(text))
}

#[test]
fn each_bad_line_says_why_at_its_line() {
    let got = errors(
        "LD x\n\
         FOO y\n\
         STC y\n\
         LD( y\n\
         NOT y\n\
         LD\n\
         JMP 3x\n\
         LD %QX0.9\n\
         LD INT#99999\n\
         CAL t(IN = x)\n\
         l1: LD x\n\
         L1: LD y\n\
         READ x\n\
         l2:",
    );
    let lines: Vec<usize> = got.iter().map(|(l, _)| *l).collect();
    // `l2:` alone at the end labels a RET (a label on its own line).
    assert_eq!(lines, [2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 13], "{got:?}");
    assert_eq!(got[0].1, "unknown operator `FOO`");
    assert!(got[1].1.contains("no such modifier"));
    assert!(got[2].1.contains("no such modifier"));
    assert_eq!(got[3].1, "`NOT` takes no operand");
    assert_eq!(got[4].1, "`LD` needs an operand");
    assert_eq!(got[5].1, "`JMP` needs a label");
    assert!(got[6].1.contains("a bit number is 0-7"));
    assert!(got[7].1.contains("out of range for INT"));
    assert!(got[8].1.contains("a call is CAL name("));
    assert_eq!(got[9].1, "label `L1` is used twice (first on line 11)");
    assert_eq!(got[10].1, "unknown operator `READ`");
}

#[test]
fn functions_by_name_with_their_operands() {
    let lines = parse_il("SHL 2\nLIMIT a, 100\nint_to_dint\nNEG\nSEL x, y").expect("it reads");
    assert_eq!(lines[0].operator, Operator::Function(Function::Shl));
    assert_eq!(lines[1].args.len(), 2);
    assert_eq!(
        lines[2].operator,
        Operator::Function(Function::Convert {
            from: DataType::Int,
            to: DataType::Dint
        })
    );
    assert_eq!(lines[3].operator, Operator::Function(Function::Neg));
    assert_eq!(
        errors("LD x\nSHL\nLIMIT 1\nREAL_TO_FLOAT"),
        [
            (
                2,
                "`SHL` takes 1 operand(s) after the current result".to_string()
            ),
            (
                3,
                "`LIMIT` takes 2 operand(s) after the current result".to_string()
            ),
            (4, "unknown operator `REAL_TO_FLOAT`".to_string()),
        ]
    );
}

#[test]
fn comments_anywhere_and_var_blocks_are_skipped() {
    let lines =
        parse_il("(* head *)\nVAR\n  x : BOOL;\nEND_VAR\nLD (* mid *) x (* two\nlines *) ST y")
            .expect("it reads");
    assert_eq!(lines.len(), 2);
    assert_eq!(lines[0].operand, Some(Operand::Name("x".into())));
    assert_eq!(
        lines[1].line, 6,
        "a line keeps its number after a long comment"
    );
    let open = crate::iec::said(parse_il("LD x\nST y (* never closed\nST z"));
    assert_eq!(
        open,
        [(2, "a comment `(*` is never closed with `*)`".to_string())]
    );
}

proptest::proptest! {
    #[test]
    fn any_text_reads_or_says_why_at_a_line(text in "[ -~\\n]{0,80}") {
        let n = text.lines().count();
        if let Err(errors) = parse_il(&text) {
            proptest::prop_assert!(errors.iter().all(|e| (1..=n).contains(&e.line)));
        }
    }
}
