use super::*;

const MS: i64 = 1_000_000;

fn load(text: &str) -> Program {
    Program::load(text).unwrap_or_else(|e| panic!("{e:?}"))
}

fn addr(a: &str) -> Address {
    Address::parse(a).expect("an address")
}

fn on(p: &Program, name: &str) -> bool {
    p.value(name) == Some(Data::Bool(true))
}

#[test]
fn a_seal_in_holds_until_stop() {
    let mut p = load(
        "VAR\n  lamp AT %QX0.0 : BOOL;\nEND_VAR\n\
         LD %IX0.0\nOR lamp\nANDN %IX0.1\nST lamp",
    );
    assert!(p.set_input(addr("%IX0.0"), Data::Bool(true)));
    p.scan(0);
    assert!(on(&p, "%QX0.0"));
    p.set_input(addr("%IX0.0"), Data::Bool(false));
    p.scan(10 * MS);
    assert!(on(&p, "lamp"), "held");
    p.set_input(addr("%IX0.1"), Data::Bool(true));
    p.scan(20 * MS);
    assert!(!on(&p, "lamp"));
    assert!(
        !p.set_input(addr("%QX0.0"), Data::Bool(true)),
        "an output has no terminal to set"
    );
    assert_eq!(p.io().count(), 3);
}

#[test]
fn arithmetic_counts_and_wraps_as_iec_says() {
    let mut p = load(
        "VAR\n  count : INT := 32766;\n  big : BOOL;\nEND_VAR\n\
         LD count\nADD 1\nST count\nGT 0\nST big",
    );
    p.scan(0);
    assert_eq!(p.value("count"), Some(Data::integer(DataType::Int, 32767)));
    assert!(on(&p, "big"));
    p.scan(10 * MS);
    assert_eq!(
        p.value("COUNT"),
        Some(Data::integer(DataType::Int, -32768)),
        "wraps"
    );
    assert!(!on(&p, "big"));
}

#[test]
fn two_timers_blink_500_500() {
    let mut p = load(
        "VAR\n  lamp AT %QX0.0 : BOOL;\n  x : BOOL;\n  a : BOOL;\n  b : BOOL;\n  \
         t1 : TON;\n  t2 : TON;\nEND_VAR\n\
         LDN b\nST x\n\
         CAL t1(IN := x, PT := T#500ms, Q => a)\n\
         CAL t2(IN := a, PT := T#500ms, Q => b)\n\
         LD a\nST lamp",
    );
    let mut seen = Vec::new();
    for k in 0..=300 {
        p.scan(k * 10 * MS);
        seen.push(on(&p, "lamp"));
    }
    // Each half of the cycle lasts 500 ms plus the scan the timers reset in.
    let changes: Vec<usize> = (1..seen.len())
        .filter(|&i| seen[i] != seen[i - 1])
        .collect();
    assert_eq!(&changes[..4], [50, 101, 152, 203], "{changes:?}");
}

#[test]
fn deferred_operations_and_conditional_jumps() {
    let mut p = load(
        "VAR\n  a : BOOL := TRUE;\n  b : BOOL;\n  c : BOOL := TRUE;\n  y : BOOL;\n  n : DINT;\nEND_VAR\n\
         LD a\nAND( b\nOR c\n)\nST y\n\
         JMPC skip\nLD n\nADD 100\nST n\n\
         skip: LD n\nADD 1\nST n",
    );
    p.scan(0);
    assert!(on(&p, "y"), "a AND (b OR c)");
    assert_eq!(
        p.value("n"),
        Some(Data::integer(DataType::Dint, 1)),
        "the ADD 100 was jumped over"
    );
}

#[test]
fn a_loop_that_never_ends_is_cut_short() {
    let mut p = load("VAR\n  x : BOOL;\nEND_VAR\nloop: LD x\nJMPCN loop");
    p.scan(0);
    assert!(p.overran());
}

#[test]
fn retained_values_survive_a_power_cycle() {
    let mut p = load(
        "VAR\n  n : INT;\nEND_VAR\nVAR_RETAIN\n  total : INT;\nEND_VAR\n\
         LD n\nADD 1\nST n\nLD total\nADD 1\nST total",
    );
    p.scan(0);
    p.scan(10 * MS);
    p.power_cycle();
    assert_eq!(p.value("n"), Some(Data::integer(DataType::Int, 0)));
    assert_eq!(p.value("total"), Some(Data::integer(DataType::Int, 2)));
}

#[test]
fn functions_take_the_current_result_first() {
    let mut p = load(
        "VAR\n  level AT %IW0 : INT;\n  pct : INT;\n  big : DINT;\n  w : WORD := 16#8001;\n  \
         alarm : BOOL;\n  pick : INT;\nEND_VAR\n\
         LD INT#0\nLIMIT level, 100\nST pct\n\
         LD level\nINT_TO_DINT\nMUL 1000\nST big\n\
         LD w\nROL 1\nST w\n\
         LD pct\nGE 90\nST alarm\n\
         LD alarm\nSEL INT#1, 2\nST pick",
    );
    assert!(p.set_input(addr("%IW0"), Data::integer(DataType::Int, 250)));
    p.scan(0);
    assert_eq!(
        p.value("pct"),
        Some(Data::integer(DataType::Int, 100)),
        "LIMIT(0, 250, 100)"
    );
    assert_eq!(
        p.value("big"),
        Some(Data::integer(DataType::Dint, 250_000)),
        "no INT overflow after the conversion"
    );
    assert_eq!(p.value("w"), Some(Data::integer(DataType::Word, 0x0003)));
    assert!(on(&p, "alarm"));
    assert_eq!(p.value("pick"), Some(Data::integer(DataType::Int, 2)));
}

fn errors(text: &str) -> Vec<(usize, String)> {
    crate::iec::said(Program::load(text))
}

#[test]
fn what_does_not_load_says_why_at_its_line() {
    let got = errors(
        "VAR\n  i : INT;\n  d : DINT;\n  t : TON;\nEND_VAR\n\
         LD ghost\n\
         LD i\nADD d\n\
         LD i\nST 5\n\
         JMP nowhere\n\
         LD %IB0\n\
         CAL t(XX := i)\n\
         CAL t(PT := i)\n\
         l: ST i\n\
         LD i\nAND( i\n",
    );
    let lines: Vec<usize> = got.iter().map(|(l, _)| *l).collect();
    assert_eq!(lines, [6, 8, 10, 11, 12, 13, 14, 15, 17], "{got:?}");
    assert_eq!(got[0].1, "`ghost` is not declared");
    assert_eq!(got[1].1, "INT and DINT do not mix: convert one (*_TO_*)");
    assert!(got[2].1.contains("stored in a variable"), "{}", got[2].1);
    assert_eq!(got[3].1, "no line has the label `nowhere`");
    assert_eq!(got[4].1, "%IB0: the soft PLC has no byte type");
    assert_eq!(got[5].1, "TON has no input `XX`");
    assert_eq!(got[6].1, "TON's PT is a TIME");
    assert!(got[7].1.contains("start with LD"));
    assert_eq!(got[8].1, "this `(` is never closed with `)`");
    let got = errors(
        "VAR\n  i : INT;\n  r : REAL;\n  b : BOOL;\nEND_VAR\n\
         LD i\nDINT_TO_INT\n\
         LD r\nSHL 1\n\
         LD i\nSEL 1, 2\n\
         LD b\nNEG\n\
         LD i\nMIN r",
    );
    assert_eq!(
        got.iter().map(|(l, _)| *l).collect::<Vec<_>>(),
        [7, 9, 11, 13, 15],
        "{got:?}"
    );
    assert_eq!(got[0].1, "the current result is INT, not DINT");
    assert!(got[1].1.contains("shift an integer"));
    assert!(got[2].1.contains("SEL's first input"));
    assert_eq!(got[3].1, "NEG needs a number");
    assert_eq!(got[4].1, "INT and REAL do not mix: convert one (*_TO_*)");
}

const COUNTER: &str = "FUNCTION_BLOCK Counter\n\
VAR_INPUT\n  up : BOOL;\nEND_VAR\n\
VAR_OUTPUT\n  count : INT;\n  done : BOOL;\nEND_VAR\n\
VAR\n  e : R_TRIG;\n  rise : BOOL;\nEND_VAR\n\
CAL e(CLK := up, Q => rise)\n\
LD rise\nJMPCN skip\nLD count\nADD 1\nST count\n\
skip: LD count\nGE INT#3\nST done\n\
END_FUNCTION_BLOCK\n\
VAR\n  a : Counter;\n  b : Counter;\n  na : INT;\n  nb : INT;\n  da : BOOL;\nEND_VAR\n\
CAL a(up := %IX0.0, count => na, done => da)\n\
CAL b(up := %IX0.1, count => nb)\n\
LD da\nST %QX0.0\n";

#[test]
fn the_programs_own_function_blocks_keep_a_state_per_instance() {
    let mut p = load(COUNTER);
    let mut now = 0;
    let mut press = |p: &mut Program, input: &str| {
        for on in [true, false] {
            assert!(p.set_input(addr(input), Data::Bool(on)));
            now += 10_000_000;
            p.scan(now);
        }
    };
    for _ in 0..3 {
        press(&mut p, "%IX0.0");
    }
    press(&mut p, "%IX0.1");
    assert_eq!(p.value("na"), Some(Data::integer(DataType::Int, 3)));
    assert_eq!(p.value("nb"), Some(Data::integer(DataType::Int, 1)));
    assert!(on(&p, "da") && on(&p, "%QX0.0"));
    // The front ends see inside each instance.
    assert_eq!(p.value("a.count"), Some(Data::integer(DataType::Int, 3)));
    assert_eq!(p.value("B.COUNT"), Some(Data::integer(DataType::Int, 1)));
    // The listing keeps the block and loads back to itself.
    let listing = p.listing();
    assert!(
        listing.starts_with("FUNCTION_BLOCK Counter\nVAR_INPUT\n  up : BOOL;\nEND_VAR\n"),
        "{listing}"
    );
    assert_eq!(load(&listing).listing(), listing);
}

#[test]
fn a_function_block_that_holds_itself_or_is_called_wrongly_says_where() {
    let itself = errors("FUNCTION_BLOCK Loop\nVAR\n  inner : Loop;\nEND_VAR\nEND_FUNCTION_BLOCK\nVAR\n  l : Loop;\nEND_VAR\n");
    assert!(
        itself[0]
            .1
            .contains("more than 8 deep (does Loop hold itself?)"),
        "{itself:?}"
    );
    let text = COUNTER.replace("CAL b(up := %IX0.1, count => nb)", "CAL b(down := %IX0.1)");
    let got = errors(&text);
    assert_eq!(got, [(31, "Counter has no input `down`".to_string())]);
    let unended = errors("FUNCTION_BLOCK F\nVAR\n  x : BOOL;\nEND_VAR\n");
    assert_eq!(
        unended,
        [(1, "FUNCTION_BLOCK F has no END_FUNCTION_BLOCK".to_string())]
    );
    // An error in a body is said once, however many instances it has.
    let body = COUNTER.replace("ADD 1", "ADD ghost");
    assert_eq!(errors(&body), [(17, "`ghost` is not declared".to_string())]);
}

proptest::proptest! {
    /// Any text of the pieces a program is made of loads, or is refused
    /// with every error at one of its lines; never a panic.
    #[test]
    fn any_text_loads_or_says_why_at_a_line(
        pieces in proptest::collection::vec(proptest::sample::select(vec![
            "FUNCTION_BLOCK F", "END_FUNCTION_BLOCK", "VAR", "VAR_INPUT", "VAR_OUTPUT",
            "END_VAR", "  x : BOOL;", "  n : INT;", "  f : F;", "  t : TON;",
            "LD x", "ST x", "CAL f(x := TRUE, n => n)", "CAL f", "LD n", "ADD 1", "ST n",
            "RET", "l: LD x", "JMPC l", "(* a", "b *)", "PROGRAM p", "END_PROGRAM",
            "LD 40000", "ADD 2", "GT 3", "MAX 5", "SEL 1, 2", "INT_TO_DINT", "LD t.Q",
            "ADD( 7", ")", "LD f.n", "ST t.Q", "CAL t(IN := x, IN := x)", "CAL t(,)",
            "  w : WORD;", "ST w", "LD -1", "SHL 40", "NOT",
        ]), 0..24)
    ) {
        let text = pieces.join("\n");
        let n = text.lines().count().max(1);
        if let Err(errors) = Program::load(&text) {
            proptest::prop_assert!(errors.iter().all(|e| (1..=n).contains(&e.line)), "{errors:?}\n{text}");
        }
    }
}

#[test]
fn instances_that_would_multiply_past_the_limits_are_refused() {
    // Ten instances of the next block, seven deep: 10^7 if built.
    let mut text = String::new();
    for level in 0..7 {
        text.push_str(&format!("FUNCTION_BLOCK B{level}\nVAR\n"));
        for k in 0..10 {
            text.push_str(&format!("  i{k} : B{};\n", level + 1));
        }
        text.push_str("END_VAR\nEND_FUNCTION_BLOCK\n");
    }
    text.push_str("FUNCTION_BLOCK B7\nVAR\n  x : BOOL;\nEND_VAR\nLD x\nST x\nEND_FUNCTION_BLOCK\n");
    text.push_str("VAR\n  top : B0;\nEND_VAR\n");
    let said = errors(&text);
    assert!(said[0].1.contains("more than 10000 instances"), "{said:?}");
}

#[test]
fn a_formatted_string_takes_its_text_as_a_literal_and_sends_it() {
    // Commas and `$'` inside the literal do not split the call.
    let mut p = load(
        "VAR\n  f : LD_FMTSTR;\n  n : DINT := 7;\nEND_VAR\n\
         CAL f(IN := TRUE, V := n, FMT := 'it$'s, \\2$R$N')",
    );
    for k in 0..20 {
        p.scan(k * 10 * MS);
    }
    let sent: String = p.uart.sent_after(0).map(char::from).collect();
    assert_eq!(sent, "it's,  7\r\n");
    // A power cycle keeps the text.
    p.power_cycle();
    for k in 0..20 {
        p.scan(k * 10 * MS);
    }
    assert_eq!(p.uart.sent_total(), 20);
}

#[test]
fn a_text_is_a_string_and_goes_only_where_one_is_taken() {
    let said = |text: &str| crate::iec::said(Program::load(text));
    let head = "VAR\n  f : LD_FMTSTR;\n  n : DINT;\nEND_VAR\n";
    assert_eq!(
        said(&format!("{head}CAL f(IN := TRUE, FMT := 5)")),
        [(5, "LD_FMTSTR's FMT is a text: '…'".to_string())]
    );
    assert_eq!(
        said(&format!("{head}CAL f(FMT := 'a')\nCAL f(FMT := 'b')")),
        [(
            6,
            "f already has another text: one FMT for each instance".to_string()
        )]
    );
    assert_eq!(
        said(&format!("{head}LD 'a'\nST n"))[0],
        (6, "the current result is STRING, n needs DINT".to_string())
    );
    assert_eq!(
        said(&format!("{head}LD 'a'\nADD 'b'"))[0],
        (6, "this operation does not apply to STRING".to_string())
    );
    let long = format!("'{}'", "x".repeat(255));
    assert_eq!(
        said(&format!("{head}LD {long}"))[0],
        (
            5,
            "a STRING holds at most 254 characters; this text has 255".to_string()
        )
    );
    let bad = said(&format!("{head}CAL f(FMT := '\\9')"));
    assert!(bad[0].1.starts_with("FMT: `\\9` is no escape"), "{bad:?}");
    let open = said(&format!("{head}CAL f(FMT := 'a)"));
    assert_eq!(open[0].0, 5, "{open:?}");
}

#[test]
fn strings_are_declared_moved_and_compared_as_iec_says() {
    let text = "VAR\n  greeting : STRING := 'Hello $'PLC$'';\n  copy : STRING;\n  \
                same : BOOL;\n  later : BOOL;\n  least : STRING;\n  picked : STRING;\nEND_VAR\n\
                LD greeting\nST copy\nEQ 'Hello $'PLC$''\nST same\n\
                LD 'abc'\nGT 'abb'\nST later\n\
                LD 'pear'\nMIN 'apple'\nMAX 'aardvark'\nST least\n\
                LD later\nSEL 'no', greeting\nMOVE\nST picked";
    let mut p = load(text);
    assert_eq!(p.value("copy"), Some(Data::text("")));
    p.scan(0);
    assert_eq!(p.value("copy"), Some(Data::text("Hello 'PLC'")));
    assert!(on(&p, "same"), "a text equals its copy");
    assert!(on(&p, "later"), "texts compare by their characters");
    assert_eq!(p.value("least"), Some(Data::text("apple")));
    assert_eq!(p.value("picked"), Some(Data::text("Hello 'PLC'")));
    // The listing reads back as the same program.
    let again = load(&p.listing());
    assert_eq!(again.listing(), p.listing());
    assert!(p
        .listing()
        .contains("greeting : STRING := 'Hello $'PLC$'';"));
}

#[test]
fn a_string_is_refused_where_it_does_not_fit_saying_so() {
    let said = |text: &str| crate::iec::said(Program::load(text));
    assert_eq!(
        said("VAR\n  s : STRING[20];\nEND_VAR\n"),
        [(
            2,
            "`STRING[20]`: write STRING without a length (every STRING holds up to 254 characters)"
                .to_string()
        )]
    );
    assert_eq!(
        said("VAR\n  s : STRING := 5;\nEND_VAR\n"),
        [(2, "`5` is not a STRING value".to_string())]
    );
    assert_eq!(
        said("VAR\n  n : INT := 'a';\nEND_VAR\n"),
        [(2, "`'a'` is not an INT value".to_string())]
    );
    assert_eq!(
        said("VAR\n  s AT %MD0 : STRING;\nEND_VAR\n")[0].0,
        2,
        "a STRING has no address"
    );
    let head = "VAR\n  s : STRING;\n  n : INT;\n  r : REAL;\nEND_VAR\n";
    for (body, says) in [
        (
            "LD s\nSTRING_TO_INT",
            "conversions to and from STRING do not run on the soft PLC yet",
        ),
        (
            "LD n\nINT_TO_STRING",
            "conversions to and from STRING do not run on the soft PLC yet",
        ),
        ("LD s\nNEG", "NEG needs a number"),
        ("LD s\nNOT", "NOT needs a BOOL or a bit string, not STRING"),
        (
            "LD s\nSTN s",
            "STN needs a BOOL or a bit string, not STRING",
        ),
        ("LD r\nSTN r", "STN needs a BOOL or a bit string, not REAL"),
    ] {
        assert_eq!(
            said(&format!("{head}{body}")),
            [(7, says.to_string())],
            "{body}"
        );
    }
    let long = format!("VAR\n  s : STRING := '{}';\nEND_VAR\n", "y".repeat(300));
    assert_eq!(
        said(&long),
        [(
            2,
            "a STRING holds at most 254 characters; this text has 300".to_string()
        )]
    );
}

#[test]
fn ldmicro_string_prints_into_its_destination_while_powered() {
    let mut p = load(
        "VAR\n  s : LD_STRING;\n  n : DINT := 7;\n  out : STRING := 'old';\n  go : BOOL;\nEND_VAR\n\
         LD go\nCAL s(IN := go, V := n, D := out, FMT := '[%3d]', D => out)",
    );
    p.scan(0);
    assert_eq!(p.value("out"), Some(Data::text("old")), "unpowered: kept");
    let go = p.slot_of("go").expect("go");
    p.values[go] = Data::Bool(true);
    p.scan(10 * MS);
    assert_eq!(p.value("out"), Some(Data::text("[  7]")));
    let said = |text: &str| crate::iec::said(Program::load(text));
    let head = "VAR\n  s : LD_STRING;\n  out : STRING;\nEND_VAR\n";
    assert_eq!(
        said(&format!("{head}CAL s(FMT := '%f')")),
        [(
            5,
            "FMT: `%f` prints no integer: the text takes %d %i %u %x %X %o %c or %%".to_string()
        )]
    );
    assert_eq!(
        said(&format!("{head}CAL s(D => n)"))[0].0,
        5,
        "an output to an undeclared name"
    );
}
