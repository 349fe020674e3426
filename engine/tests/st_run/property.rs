//! Random integer expressions: ST (printed with the fewest parentheses
//! the standard's precedence needs), the same computation written in IL
//! by hand's rules, and wrapping DINT arithmetic in Rust agree.

use engine::iec::data::Data;
use engine::softplc::Program;
use proptest::prelude::*;

#[derive(Clone, Debug)]
enum E {
    Var(usize),
    Num(i32),
    Bin(Op, Box<E>, Box<E>),
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Op {
    Add,
    Sub,
    Mul,
    Div,
    Mod,
}

impl Op {
    fn prec(self) -> u8 {
        match self {
            Op::Add | Op::Sub => 6,
            _ => 7,
        }
    }
    fn st(self) -> &'static str {
        ["+", "-", "*", "/", "MOD"][self as usize]
    }
    fn il(self) -> &'static str {
        ["ADD", "SUB", "MUL", "DIV", "MOD"][self as usize]
    }
}

const NAMES: [&str; 3] = ["a", "b", "c"];

fn expr() -> impl Strategy<Value = E> {
    let leaf = prop_oneof![(0..3usize).prop_map(E::Var), (0..1000i32).prop_map(E::Num)];
    leaf.prop_recursive(5, 24, 2, |inner| {
        prop_oneof![
            (
                prop_oneof![Just(Op::Add), Just(Op::Sub), Just(Op::Mul)],
                inner.clone(),
                inner
            )
                .prop_map(|(op, a, b)| E::Bin(op, Box::new(a), Box::new(b))),
            // Divisors are non-zero literals: a division by zero is not
            // what this compares.
            (
                prop_oneof![Just(Op::Div), Just(Op::Mod)],
                any::<u8>(),
                1..50i32
            )
                .prop_map(|(op, v, d)| E::Bin(
                    op,
                    Box::new(E::Var(v as usize % 3)),
                    Box::new(E::Num(d))
                )),
        ]
    })
}

fn st(e: &E) -> String {
    match e {
        E::Var(i) => NAMES[*i].to_string(),
        E::Num(n) => n.to_string(),
        E::Bin(op, a, b) => {
            let left = wrap(a, op.prec(), false);
            let right = wrap(b, op.prec(), true);
            format!("{left} {} {right}", op.st())
        }
    }
}

/// Parentheses only where the standard's precedence (and left
/// association) needs them.
fn wrap(e: &E, parent: u8, right: bool) -> String {
    match e {
        E::Bin(op, ..) if op.prec() < parent || (right && op.prec() == parent) => {
            format!("({})", st(e))
        }
        _ => st(e),
    }
}

fn il(e: &E, out: &mut Vec<String>) {
    match e {
        E::Var(_) | E::Num(_) => out.push(format!("LD {}", st(e))),
        E::Bin(op, a, b) => {
            il(a, out);
            match **b {
                E::Bin(..) => {
                    out.push(format!("{}(", op.il()));
                    il(b, out);
                    out.push(")".into());
                }
                _ => out.push(format!("{} {}", op.il(), st(b))),
            }
        }
    }
}

fn eval(e: &E, v: &[i32; 3]) -> i32 {
    match e {
        E::Var(i) => v[*i],
        E::Num(n) => *n,
        E::Bin(op, a, b) => {
            let (x, y) = (eval(a, v), eval(b, v));
            match op {
                Op::Add => x.wrapping_add(y),
                Op::Sub => x.wrapping_sub(y),
                Op::Mul => x.wrapping_mul(y),
                Op::Div => x.wrapping_div(y),
                Op::Mod => x.wrapping_rem(y),
            }
        }
    }
}

fn result(mut p: Program) -> i64 {
    p.scan(0);
    match p.value("r") {
        Some(Data::Int(_, v)) => v,
        other => panic!("r is {other:?}"),
    }
}

proptest! {
    #[test]
    fn st_and_il_agree_on_integer_expressions(e in expr(), v in any::<[i16; 3]>()) {
        let v = v.map(i32::from);
        let vars = format!(
            "VAR\n  a : DINT := {};\n  b : DINT := {};\n  c : DINT := {};\n  r : DINT;\nEND_VAR\n",
            v[0], v[1], v[2]
        );
        let st_text = format!("PROGRAM t\n{vars}r := {};\nEND_PROGRAM\n", st(&e));
        let mut lines = Vec::new();
        il(&e, &mut lines);
        let il_text = format!("PROGRAM t\n{vars}{}\nST r\nEND_PROGRAM\n", lines.join("\n"));
        let from_st = result(Program::load_st(&st_text).map_err(|e| format!("{e:?}\n{st_text}")).unwrap());
        let from_il = result(Program::load(&il_text).map_err(|e| format!("{e:?}\n{il_text}")).unwrap());
        let want = i64::from(eval(&e, &v));
        prop_assert_eq!(from_st, want, "{}", st_text);
        prop_assert_eq!(from_il, want, "{}", il_text);
    }
}
