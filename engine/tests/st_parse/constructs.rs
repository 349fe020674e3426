//! Each construct of the list parses to the tree it should, and
//! survives printing.

use engine::iec::st::ast::{
    Arg, ArrayInit, CaseLabel, Elementary, ExprKind, Init, Item, Literal, PouKind, StmtKind,
    TypeDef, TypeRef, VarKind,
};
use engine::iec::st::{parse_body, parse_expr, parse_source};

use super::{grouping, round_trip, round_trip_body, var_name};

fn literal(text: &str) -> Literal {
    match parse_expr(text).map(|e| e.kind) {
        Ok(ExprKind::Literal(l)) => l,
        other => panic!("{text}: {other:?}"),
    }
}

#[test]
fn literals() {
    use Elementary::*;
    for (text, want) in [
        ("42", Literal::Integer(42, None)),
        ("1_000", Literal::Integer(1000, None)),
        ("16#FF", Literal::Integer(255, None)),
        ("2#1010_1010", Literal::Integer(170, None)),
        ("8#17", Literal::Integer(15, None)),
        ("INT#5", Literal::Integer(5, Some(Int))),
        ("int#-5", Literal::Integer(-5, Some(Int))),
        ("SINT#-128", Literal::Integer(-128, Some(Sint))),
        ("USINT#16#FF", Literal::Integer(255, Some(Usint))),
        ("BYTE#2#1010_1010", Literal::Integer(170, Some(Byte))),
        (
            "LWORD#16#FFFF_FFFF_FFFF_FFFF",
            Literal::Integer(u64::MAX.into(), Some(Lword)),
        ),
        ("TRUE", Literal::Bool(true)),
        ("false", Literal::Bool(false)),
        ("BOOL#1", Literal::Bool(true)),
        ("1.5", Literal::Real(1.5, None)),
        ("1.0E3", Literal::Real(1000.0, None)),
        ("2.5e-2", Literal::Real(0.025, None)),
        ("REAL#2", Literal::Real(2.0, Some(Real))),
        ("LREAL#-1.25", Literal::Real(-1.25, Some(Lreal))),
        ("T#1s200ms", Literal::Time(1_200_000_000)),
        ("TIME#1h2m", Literal::Time(3_720_000_000_000)),
        ("t#500ms", Literal::Time(500_000_000)),
        ("T#-1s", Literal::Time(-1_000_000_000)),
        ("T#1h_2m", Literal::Time(3_720_000_000_000)),
        ("'it$'s $$5$N'", Literal::String("it's $5\n".into())),
        ("'$41$42'", Literal::String("AB".into())),
        ("''", Literal::String(String::new())),
    ] {
        assert_eq!(literal(text), want, "{text}");
    }
}

#[test]
fn comments_nest_and_keep_lines() {
    let body = "(* outer (* inner *) still comment *)\n// line comment := 1\n  x := 1; (* c *)\n";
    let stmts = parse_body(body).expect("parses");
    assert_eq!(stmts.len(), 1);
    assert_eq!((stmts[0].span.line, stmts[0].span.column), (3, 3));
}

#[test]
fn assignments_to_elements_members_and_outputs() {
    let stmts = parse_body("a[i, j] := 1; s.m := 2; fb.out := 3; arr[1].m[2] := 4;").unwrap();
    let targets: Vec<String> = stmts
        .iter()
        .map(|s| match &s.kind {
            StmtKind::Assign { target, .. } => var_name(target),
            k => panic!("{k:?}"),
        })
        .collect();
    assert_eq!(targets, ["a[i,j]", "s.m", "fb.out", "arr[1].m[2]"]);
}

#[test]
fn if_elsif_else() {
    let stmts =
        parse_body("IF a THEN x := 1; ELSIF b THEN x := 2; ELSIF c THEN ; ELSE x := 3; END_IF;")
            .unwrap();
    let StmtKind::If {
        branches,
        otherwise,
    } = &stmts[0].kind
    else {
        panic!()
    };
    assert_eq!(branches.len(), 3);
    assert_eq!(grouping(&branches[1].0), "b");
    assert_eq!(otherwise.as_ref().map(Vec::len), Some(1));
    let no_else = parse_body("if a then end_if;").unwrap();
    assert!(matches!(
        &no_else[0].kind,
        StmtKind::If {
            otherwise: None,
            ..
        }
    ));
}

#[test]
fn case_values_lists_ranges_else() {
    let text = "CASE n OF\n 1: x := 1;\n 2, 3: x := 2; y := 0;\n 4..6, -1: ;\n k: x := 4;\nELSE x := 0;\nEND_CASE;";
    let stmts = parse_body(text).unwrap();
    let StmtKind::Case {
        arms, otherwise, ..
    } = &stmts[0].kind
    else {
        panic!()
    };
    assert_eq!(arms.len(), 4);
    assert_eq!(arms[1].labels.len(), 2);
    assert_eq!(arms[1].body.len(), 2);
    assert!(matches!(&arms[2].labels[0], CaseLabel::Range(a, b)
        if grouping(a) == "4" && grouping(b) == "6"));
    assert_eq!(
        grouping(match &arms[2].labels[1] {
            CaseLabel::Value(v) => v,
            l => panic!("{l:?}"),
        }),
        "(-1)"
    );
    assert_eq!(otherwise.as_ref().map(Vec::len), Some(1));
}

#[test]
fn loops_exit_return() {
    let text = "FOR i := 1 TO 10 BY 2 DO IF i > 5 THEN EXIT; END_IF; END_FOR;
        FOR j := 10 TO 1 DO END_FOR;
        WHILE x < 10 DO x := x + 1; END_WHILE;
        REPEAT x := x - 1; UNTIL x <= 0 END_REPEAT;
        RETURN;";
    let stmts = parse_body(text).unwrap();
    assert!(matches!(&stmts[0].kind, StmtKind::For { by: Some(_), body, .. } if body.len() == 1));
    assert!(matches!(&stmts[1].kind, StmtKind::For { by: None, .. }));
    assert!(matches!(&stmts[2].kind, StmtKind::While { .. }));
    assert!(matches!(&stmts[3].kind, StmtKind::Repeat { .. }));
    assert!(matches!(&stmts[4].kind, StmtKind::Return));
    assert_eq!(stmts[2].span.line, 3);
}

#[test]
fn calls_formal_positional_and_outputs() {
    let stmts = parse_body("t0(IN := x, PT := T#1s); y := t0.Q;\nctu1(CU := b, Q => done, NOT Q => idle, CV => n);\nz := LIMIT(0, v, 100) + ABS(IN := w);").unwrap();
    let StmtKind::Call(c) = &stmts[0].kind else {
        panic!()
    };
    assert_eq!(c.callee.name, "t0");
    assert!(matches!(&c.args[1], Arg::Input(n, e)
        if n.name == "PT" && matches!(e.kind, ExprKind::Literal(Literal::Time(1_000_000_000)))));
    let StmtKind::Call(c) = &stmts[2].kind else {
        panic!()
    };
    assert!(
        matches!(&c.args[1], Arg::Output { name, negated: false, target } if name.name == "Q" && var_name(target) == "done")
    );
    assert!(matches!(&c.args[2], Arg::Output { negated: true, .. }));
    let StmtKind::Assign { value, .. } = &stmts[3].kind else {
        panic!()
    };
    let ExprKind::Binary(_, limit, _) = &value.kind else {
        panic!()
    };
    assert!(matches!(&limit.kind, ExprKind::Call(c) if c.args.len() == 3
        && c.args.iter().all(|a| matches!(a, Arg::Positional(_)))));
    assert_eq!(parse_body("f();").map(|s| s.len()), Ok(1));
}

pub const POUS: &str = "
TYPE
    Point : STRUCT
        x, y : INT;
        tag : STRING[20] := 'p';
    END_STRUCT;
    Grid : ARRAY [1..3, 0..1] OF INT := [1, 2, 2(0), 2()];
    Level : LREAL := 0.5;
END_TYPE

VAR_GLOBAL
    g_run AT %QX0.0 : BOOL;
END_VAR

FUNCTION Scale : REAL
    VAR_INPUT
        raw : INT;
        lo, hi : REAL := 1.0;
    END_VAR
    Scale := lo + (hi - lo) * INT_TO_REAL(raw) / 32767.0;
END_FUNCTION

function_block Counter
    VAR_INPUT up : BOOL; END_VAR
    VAR_OUTPUT count : UDINT; END_VAR
    VAR_IN_OUT total : DINT; END_VAR
    VAR edge : R_TRIG; p : Point := (x := 1, y := -2); END_VAR
    VAR_TEMP t : LWORD; END_VAR
    VAR CONSTANT step : UDINT := 1; END_VAR
    edge(CLK := up);
    IF edge.Q THEN count := count + step; total := total + 1; END_IF;
END_FUNCTION_BLOCK

PROGRAM Main
    VAR
        start AT %IX0.0 : BOOL;
        c : Counter;
        grid : Grid;
        v : ARRAY [-2..2] OF SINT := [5(1)];
        b : BYTE := 16#0F;
        s : STRING;
        n : UDINT;
        u : USINT := 1;
    END_VAR
    VAR_EXTERNAL g_run : BOOL; END_VAR
    c(up := start, count => n);
    g_run := c.count > 10;
END_PROGRAM
";

#[test]
fn pous_declarations_and_types() {
    let source = parse_source(POUS).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(source.items.len(), 5);
    let Item::Types(types) = &source.items[0] else {
        panic!()
    };
    let TypeDef::Struct(members) = &types[0].def else {
        panic!()
    };
    assert_eq!(members[0].names.len(), 2);
    assert_eq!(members[1].ty, TypeRef::String(Some(20)));
    let TypeDef::Alias(TypeRef::Array { dims, of }, Some(Init::Array(items))) = &types[1].def
    else {
        panic!()
    };
    assert_eq!(dims, &[(1, 3), (0, 1)]);
    assert_eq!(**of, TypeRef::Elementary(Elementary::Int));
    assert!(matches!(items[2], ArrayInit::Repeat(2, Some(_))));
    assert!(matches!(items[3], ArrayInit::Repeat(2, None)));
    let Item::Globals(g) = &source.items[1] else {
        panic!()
    };
    assert_eq!(g.decls[0].location.as_deref(), Some("%QX0.0"));
    let Item::Pou(f) = &source.items[2] else {
        panic!()
    };
    assert_eq!(
        f.kind,
        PouKind::Function(TypeRef::Elementary(Elementary::Real))
    );
    let Item::Pou(fb) = &source.items[3] else {
        panic!()
    };
    assert_eq!(fb.kind, PouKind::FunctionBlock);
    let kinds: Vec<(VarKind, bool)> = fb.vars.iter().map(|b| (b.kind, b.constant)).collect();
    use VarKind::*;
    assert_eq!(
        kinds,
        [
            (Input, false),
            (Output, false),
            (InOut, false),
            (Local, false),
            (Temp, false),
            (Local, true)
        ]
    );
    assert!(matches!(&fb.vars[3].decls[1].init, Some(Init::Struct(m)) if m.len() == 2));
    let Item::Pou(main) = &source.items[4] else {
        panic!()
    };
    assert_eq!(
        main.vars[0].decls[3].ty,
        TypeRef::Array {
            dims: vec![(-2, 2)],
            of: Box::new(TypeRef::Elementary(Elementary::Sint)),
        }
    );
    assert_eq!(main.body.len(), 2);
}

#[test]
fn everything_round_trips() {
    round_trip(POUS);
    round_trip_body(
        "CASE n OF 1, 2..3: x := -(-5); -4: y := NOT (a AND b) OR c; ELSE ; END_CASE;
         IF a THEN b := 1.0E20 * LREAL#-2.5; ELSIF c THEN RETURN; ELSE EXIT; END_IF;
         FOR i := 0 TO 3 BY -1 DO a[i] := (1 - 2) - (3 - 4) ** 2 ** (1 + 1); END_FOR;
         WHILE NOT done DO REPEAT ; UNTIL TRUE END_REPEAT; END_WHILE;
         t(IN := T#1d2h3m4s5ms6us7ns, PT := T#-2m, NOT Q => y, ET => e); s := 'a$'(*$N';",
    );
}
