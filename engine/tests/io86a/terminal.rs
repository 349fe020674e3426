//! The serial terminal, typed at as a user would.

use engine::io86a::{Machine, Program, Terminal};
use engine::SimTime;

/// A device and its terminal; `type_line` returns the reply without the
/// echo and the prompt, as lines.
struct Session {
    machine: Machine,
    terminal: Terminal,
}

impl Session {
    fn new(program: &str) -> Session {
        let machine = Machine::new(Program::parse(program).expect("parses"));
        let terminal = Terminal::new(&machine);
        Session { machine, terminal }
    }

    fn type_line(&mut self, line: &str) -> Vec<String> {
        let out = self.terminal.type_line(&mut self.machine, line);
        let mut lines: Vec<String> = out.split("\r\n").map(str::to_string).collect();
        let prompt = lines.pop().unwrap_or_default();
        assert_eq!(
            prompt,
            self.terminal.prompt(&self.machine),
            "ends with the prompt"
        );
        assert_eq!(
            lines.first().map(String::as_str),
            Some(line),
            "echoes the line"
        );
        lines.remove(0);
        lines
    }

    fn wait(&mut self, ms: u64) {
        let t = self.machine.now() + SimTime::from_millis(ms);
        self.machine.run_until(t);
    }

    fn prompt(&self) -> String {
        self.terminal.prompt(&self.machine)
    }
}

#[test]
fn enter_list_and_run_a_program() {
    let mut s = Session::new("");
    assert_eq!(s.prompt(), "R>", "power-on runs");
    assert!(s.type_line("^C").is_empty());
    assert_eq!(s.prompt(), ">", "Ctrl-C stops");
    s.type_line("LD M57");
    assert_eq!(s.prompt(), "2 ", "entry numbers the next line");
    s.type_line("OUT Y02");
    s.type_line("END");
    s.type_line("Q");
    assert_eq!(s.prompt(), ">");
    assert_eq!(s.type_line("L"), ["1 LD M57", "2 OUT Y02", "3 END"]);
    assert!(s.type_line("R").is_empty());
    assert_eq!(s.prompt(), "R>");
    s.wait(10);
    assert_eq!(s.type_line("Y?"), ["Y:00000100"]);
    assert_eq!(s.type_line("Y02?"), ["Y02:1"]);
    assert_eq!(s.type_line("Y?0"), ["0004"]);
}

#[test]
fn overwrite_insert_delete_and_erase_lines() {
    let mut s = Session::new("LD X00\nOUT Y00\nEND\n");
    s.type_line("^C");
    s.type_line("2 OUT Y01");
    s.type_line("^C");
    assert_eq!(s.type_line("L"), ["1 LD X00", "2 OUT Y01", "3 END"]);
    s.type_line("l 2");
    s.type_line("ANI X01");
    s.type_line("Q");
    assert_eq!(
        s.type_line("L"),
        ["1 LD X00", "2 ANI X01", "3 OUT Y01", "4 END"]
    );
    s.type_line("N 3");
    assert_eq!(s.type_line("L"), ["1 LD X00", "2 ANI X01"]);
    s.type_line("NA");
    assert!(s.type_line("L").is_empty());
    assert_eq!(
        s.type_line("9 LD X00"),
        ["ERR line 9: the program has 0 lines"]
    );
}

#[test]
fn run_reports_program_errors_by_line_and_stays_stopped() {
    let mut s = Session::new("");
    s.type_line("^C");
    s.type_line("LD X00");
    s.type_line("OUT T00");
    s.type_line("OUT X01");
    s.type_line("Q");
    let reply = s.type_line("R");
    assert_eq!(
        reply,
        [
            "ERR line 2: OUT T/C needs its set value on the next step, e.g. K10",
            "ERR line 3: OUT X01: X01 is an input and cannot be driven"
        ]
    );
    assert_eq!(s.prompt(), ">");
}

#[test]
fn edits_wait_for_stop() {
    let mut s = Session::new("LD X00\nOUT Y00\nEND\n");
    assert_eq!(
        s.type_line("1 LD X01"),
        ["ERR stop the program first (Ctrl-C)"]
    );
    assert_eq!(s.type_line("NA"), ["ERR stop the program first (Ctrl-C)"]);
    assert_eq!(s.type_line("L").len(), 3, "listing works while running");
}

#[test]
fn reads_writes_and_reset_outputs() {
    let mut s = Session::new("LD M00\nOUT Y01\nLD M57\nMOV K10 D00\nEND\n");
    s.wait(5);
    assert_eq!(s.type_line("D00?"), ["D00:000A(10)"]);
    assert_eq!(s.type_line("D?").len(), 8);
    assert!(s.type_line("M00=1").is_empty());
    s.wait(5);
    assert_eq!(s.type_line("Y01?"), ["Y01:1"], "M00 drives Y01");
    let m = s.type_line("M?");
    assert_eq!(
        m,
        ["M:00000001 00000000 00000000 00000000 00000000 00000000 00000000 00000010"]
    );
    assert!(s.type_line("D01=xFF").is_empty());
    assert_eq!(s.type_line("D01?"), ["D01:00FF(255)"]);
    assert!(s.type_line("D02=-2").is_empty());
    assert_eq!(s.type_line("D02?"), ["D02:FFFE(-2)"]);
    assert_eq!(s.type_line("X00=1"), ["ERR X00 is an input"]);
    assert_eq!(s.type_line("Y00=2"), ["ERR bad value \"2\": 0 or 1"]);
    s.type_line("^C");
    s.type_line("Y03=1");
    assert_eq!(s.type_line("Y?"), ["Y:00001010"]);
    s.type_line("@");
    assert_eq!(s.type_line("Y?"), ["Y:00000000"], "@ resets every Y");
}

#[test]
fn settings_and_the_v_command() {
    let mut s = Session::new("");
    for command in ["X04A:401:100", "Y03R", "X07I:10EF", "!3"] {
        assert!(s.type_line(command).is_empty(), "{command}");
    }
    assert_eq!(
        s.type_line("V")[1],
        "X04A:401:100 X05D X07I:10EF Y03R Y04D !3"
    );
    assert_eq!(
        s.type_line("X04A:0:0")[0],
        "ERR bad analog setting \"X04A:0:0\": X04A:n1:n2 with n1 2..1024"
    );
    assert_eq!(s.type_line("."), ["NONE"]);
    s.machine.set_ir(Some(0x10EF_00F8));
    assert_eq!(s.type_line("."), ["10EF00F8"], "the manual's example frame");
}

#[test]
fn unknown_commands_are_errors() {
    let mut s = Session::new("");
    assert_eq!(s.type_line("FOO"), ["ERR unknown command \"FOO\""]);
    assert_eq!(s.type_line("Q99?"), ["ERR unknown command \"Q99?\""]);
    assert_eq!(s.type_line("M99?")[0], "ERR unknown device \"M99\": PLC-IO86A has X00-X07, Y00-Y05, M00-M63, S00-S07, T00-T31, C00-C07, D00-D07");
}
