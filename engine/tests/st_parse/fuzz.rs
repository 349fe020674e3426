//! No input makes the parser panic: random token soup, and random
//! mutations (a token dropped, doubled or swapped) of valid programs.

use engine::iec::st::{check_source, parse_body, parse_source, print_source, KEYWORDS};
use proptest::prelude::*;

/// What the soup is made of besides the lexer's keywords: symbols,
/// literals, a name, comment marks.
const OTHERS: [&str; 22] = [
    ":=", "=>", "..", "**", "(", ")", "[", "]", ",", ";", ":", ".", "-", "x", "INT#5", "16#FF",
    "T#1s", "'s'", "1.5", "%IX0.0", "(*", "*)",
];

/// The lexer's keywords (its own list, so a keyword added there is fed
/// here too) and the others.
fn soup_words() -> Vec<&'static str> {
    KEYWORDS.iter().chain(OTHERS.iter()).copied().collect()
}

const VALID: [&str; 3] = [
    "PROGRAM p VAR a : ARRAY [1..3] OF INT := [1, 2(0)]; t : TON; END_VAR
     t(IN := a[1] > 0, PT := T#1s, Q => q);
     CASE a[2] OF 1, 2..3: x := -2 ** 2; ELSE x := 0; END_CASE;
     FOR i := 1 TO 3 BY 1 DO IF a[i] = 0 THEN EXIT; END_IF; END_FOR;
     END_PROGRAM",
    "FUNCTION f : REAL VAR_INPUT x : REAL; END_VAR
     WHILE x > 1.0 DO x := x / 2.0; END_WHILE; REPEAT x := x + 1.0; UNTIL x > 2.0 END_REPEAT;
     f := x; END_FUNCTION",
    "TYPE p : STRUCT a, b : INT := 1; END_STRUCT; END_TYPE
     FUNCTION_BLOCK b VAR_INPUT i : BOOL; END_VAR VAR_OUTPUT o : BOOL; END_VAR
     o := NOT i AND (i OR FALSE) XOR i; END_FUNCTION_BLOCK",
];

fn words(text: &str) -> Vec<String> {
    text.split_whitespace().map(str::to_string).collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn token_soup_never_panics(picks in prop::collection::vec(any::<prop::sample::Index>(), 0..60)) {
        let words = soup_words();
        let text: Vec<&str> = picks.iter().map(|i| words[i.index(words.len())]).collect();
        let text = text.join(" ");
        if let Ok(tree) = parse_source(&text) {
            let _ = check_source(&tree);
        }
        let _ = parse_body(&text);
    }

    #[test]
    fn mutated_programs_never_panic(
        which in 0..VALID.len(),
        edits in prop::collection::vec((0..3u8, any::<prop::sample::Index>(), any::<prop::sample::Index>()), 1..4),
    ) {
        let mut w = words(VALID[which]);
        for (op, a, b) in edits {
            if w.is_empty() { break; }
            let (i, j) = (a.index(w.len()), b.index(w.len()));
            match op {
                0 => { w.remove(i); }
                1 => { let t = w[i].clone(); w.insert(i, t); }
                _ => w.swap(i, j),
            }
        }
        let text = w.join(" ");
        if let Ok(tree) = parse_source(&text) {
            let _ = check_source(&tree);
            // Whatever parses also prints to text that parses.
            let printed = print_source(&tree);
            prop_assert!(parse_source(&printed).is_ok(), "{}\n{}", text, printed);
        }
    }

    #[test]
    fn random_bytes_never_panic(text in "\\PC{0,80}") {
        let _ = parse_source(&text);
        let _ = parse_body(&text);
    }
}

#[test]
fn valid_programs_parse_and_round_trip() {
    for v in VALID {
        super::round_trip(v);
    }
}

/// A random expression's text, parenthesised at random.
fn expression() -> impl Strategy<Value = String> {
    let leaf = prop::sample::select(vec![
        "a", "b", "1", "2.5", "TRUE", "INT#-3", "T#1s", "f(x)", "a[1].m",
    ])
    .prop_map(str::to_string);
    leaf.prop_recursive(5, 40, 2, |inner| {
        let ops = prop::sample::select(vec![
            "OR", "XOR", "AND", "&", "=", "<>", "<", ">", "<=", ">=", "+", "-", "*", "/", "MOD",
            "**",
        ]);
        prop_oneof![
            (inner.clone(), ops, inner.clone()).prop_map(|(a, op, b)| format!("{a} {op} {b}")),
            (prop::sample::select(vec!["-", "NOT ", "+"]), inner.clone())
                .prop_map(|(op, x)| format!("{op}{x}")),
            inner.prop_map(|x| format!("({x})")),
        ]
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Printing keeps the grouping: the printed expression parses to the
    /// same tree, however the original was parenthesised.
    #[test]
    fn expressions_round_trip(text in expression()) {
        if engine::iec::st::parse_expr(&text).is_ok() {
            super::round_trip_body(&format!("x := {text};"));
        }
    }
}
