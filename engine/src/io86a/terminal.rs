//! PLC-IO86A's serial terminal (CUI): lines typed at the device go in, the
//! characters it sends back come out (echo, response, prompt; CR LF line
//! ends). Commands as the manual lists them (machines.md §2).

use super::asm::Program;
use super::isa::{parse_bit, parse_word, Bit, Word};
use super::machine::Machine;

/// What the terminal is doing with typed lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Entry {
    /// Commands.
    Command,
    /// Program lines overwrite from this line (1-based) on.
    Overwrite(usize),
    /// Program lines are inserted before this line (1-based).
    Insert(usize),
}

/// The terminal: the program's text lines as edited, and the entry mode.
#[derive(Clone, Debug)]
pub struct Terminal {
    lines: Vec<String>,
    entry: Entry,
}

const CRLF: &str = "\r\n";

impl Terminal {
    /// A terminal for `machine`, holding its program's lines.
    pub fn new(machine: &Machine) -> Terminal {
        let lines = machine
            .program()
            .listing()
            .lines()
            .map(|l| l.split_once(' ').map_or(l, |(_, text)| text).to_string())
            .collect();
        Terminal {
            lines,
            entry: Entry::Command,
        }
    }

    /// The prompt the device shows now: `R>` running, `>` stopped, and the
    /// next line number while entering a program.
    pub fn prompt(&self, machine: &Machine) -> String {
        match self.entry {
            Entry::Overwrite(n) | Entry::Insert(n) => format!("{n} "),
            Entry::Command if machine.running() => "R>".to_string(),
            Entry::Command => ">".to_string(),
        }
    }

    /// The program lines as edited (not yet run).
    pub fn lines(&self) -> &[String] {
        &self.lines
    }

    /// Types one line (without its line end; `^C` is Ctrl-C) and returns
    /// what the device sends back: the echo, the response and the prompt.
    pub fn type_line(&mut self, machine: &mut Machine, line: &str) -> String {
        let line = line.trim_end_matches(['\r', '\n']);
        let mut out = String::from(line);
        out.push_str(CRLF);
        for reply in self.respond(machine, line.trim()) {
            out.push_str(&reply);
            out.push_str(CRLF);
        }
        out.push_str(&self.prompt(machine));
        out
    }

    fn respond(&mut self, m: &mut Machine, line: &str) -> Vec<String> {
        if line == "^C" || line == "\u{3}" {
            if self.entry != Entry::Command {
                self.entry = Entry::Command;
            } else {
                m.set_running(false);
            }
            return Vec::new();
        }
        match self.entry {
            Entry::Command => self.command(m, line),
            Entry::Overwrite(n) | Entry::Insert(n) => {
                if line.eq_ignore_ascii_case("Q") {
                    self.entry = Entry::Command;
                    return Vec::new();
                }
                self.enter(n, line)
            }
        }
    }

    /// A program line typed in entry mode at line `n`.
    fn enter(&mut self, n: usize, text: &str) -> Vec<String> {
        if text.is_empty() {
            return Vec::new();
        }
        let text = text.to_ascii_uppercase();
        match self.entry {
            Entry::Insert(_) => {
                self.lines.insert((n - 1).min(self.lines.len()), text);
                self.entry = Entry::Insert(n + 1);
            }
            _ => {
                if n <= self.lines.len() {
                    self.lines[n - 1] = text;
                } else {
                    self.lines.push(text);
                }
                self.entry = Entry::Overwrite(n + 1);
            }
        }
        Vec::new()
    }

    fn command(&mut self, m: &mut Machine, line: &str) -> Vec<String> {
        let upper = line.to_ascii_uppercase();
        let err = |message: &str| vec![format!("ERR {message}")];
        if upper.is_empty() {
            return Vec::new();
        }
        match upper.as_str() {
            "V" => return vec!["PLC-IO86A (Hashigo)".to_string(), m.settings().to_string()],
            "L" => {
                return self
                    .lines
                    .iter()
                    .enumerate()
                    .map(|(i, l)| format!("{} {l}", i + 1))
                    .collect()
            }
            "R" => return self.run(m),
            "@" => {
                m.reset_outputs();
                return Vec::new();
            }
            "." => {
                return vec![m
                    .last_ir()
                    .map_or("NONE".to_string(), |f| format!("{f:08X}"))]
            }
            "NA" => {
                return self.edit(m, |t| {
                    t.lines.clear();
                    Vec::new()
                })
            }
            _ => {}
        }
        if let Some(rest) = upper.strip_prefix("N ") {
            return match rest.trim().parse::<usize>() {
                Ok(n) if n >= 1 => self.edit(m, |t| {
                    t.lines.truncate(n - 1);
                    Vec::new()
                }),
                _ => err("N nn: a line number from 1"),
            };
        }
        if let Some(rest) = line.strip_prefix("l ").or_else(|| line.strip_prefix("I ")) {
            return match rest.trim().parse::<usize>() {
                Ok(n) if n >= 1 && n <= self.lines.len() + 1 => self.edit(m, |t| {
                    t.entry = Entry::Insert(n);
                    Vec::new()
                }),
                _ => err("l nn: a line number from 1 to one past the last line"),
            };
        }
        if upper.starts_with('!') || is_setting(&upper) {
            return match m.settings_mut().apply(&upper) {
                Ok(()) => Vec::new(),
                Err(e) => err(&e.to_string()),
            };
        }
        if let Some(reply) = read_command(m, &upper) {
            return reply;
        }
        if let Some((device, value)) = upper.split_once('=') {
            return write_command(m, device, value).map_or_else(|e| err(&e), |()| Vec::new());
        }
        // A program line: `nn instruction` or an instruction (from line 1).
        let mut words = upper.splitn(2, ' ');
        let first = words.next().unwrap_or("");
        if let Ok(n) = first.parse::<usize>() {
            let text = words.next().unwrap_or("").trim().to_string();
            if n == 0 || n > self.lines.len() + 1 {
                return err(&format!(
                    "line {n}: the program has {} lines",
                    self.lines.len()
                ));
            }
            return self.edit(m, |t| {
                t.entry = Entry::Overwrite(n);
                t.enter(n, &text)
            });
        }
        if is_instruction(first) {
            return self.edit(m, |t| {
                t.entry = Entry::Overwrite(1);
                t.enter(1, &upper)
            });
        }
        err(&format!("unknown command {}", crate::error::shown(line)))
    }

    /// Program edits happen only while stopped, as on the device.
    fn edit(&mut self, m: &Machine, f: impl FnOnce(&mut Terminal) -> Vec<String>) -> Vec<String> {
        if m.running() {
            return vec!["ERR stop the program first (Ctrl-C)".to_string()];
        }
        f(self)
    }

    /// `R`: the edited lines become the program and run; errors keep it
    /// stopped, each reported with its line.
    fn run(&mut self, m: &mut Machine) -> Vec<String> {
        if m.running() {
            return Vec::new();
        }
        let text: String = self.lines.iter().map(|l| format!("{l}\n")).collect();
        match Program::parse(&text) {
            Ok(program) => {
                if program != *m.program() {
                    m.load(program);
                }
                m.set_running(true);
                Vec::new()
            }
            Err(errors) => errors
                .iter()
                .map(|e| format!("ERR line {}: {}", e.line, e.error))
                .collect(),
        }
    }
}

fn is_setting(upper: &str) -> bool {
    ["X04A", "X05A", "X04D", "X05D", "X07I", "X07D", "Y03", "Y04"]
        .iter()
        .any(|p| upper.starts_with(p))
        && !upper.contains(['?', '='])
}

fn is_instruction(word: &str) -> bool {
    [
        "LD", "LDI", "AND", "ANI", "OR", "ORI", "ORB", "ANB", "OUT", "PLS", "PLF", "SET", "RST",
        "SETS", "RSTS", "CMP", "MOV", "INC", "DEC", "END",
    ]
    .contains(&word)
}

/// The read commands: `X?`, `Xnn?`, `X?0`, `D?`, `Dnn?`, …
fn read_command(m: &Machine, upper: &str) -> Option<Vec<String>> {
    let d = m.devices();
    let kind = upper.chars().next()?;
    let rest = &upper[kind.len_utf8()..];
    let (count, bits): (u8, Box<dyn Fn(u8) -> bool>) = match kind {
        'X' => (8, Box::new(|n| d.bit(Bit::X(n)))),
        'Y' => (6, Box::new(|n| d.bit(Bit::Y(n)))),
        'M' => (64, Box::new(|n| d.bit(Bit::M(n)))),
        'S' => (8, Box::new(|n| d.bit(Bit::S(n)))),
        'T' => (32, Box::new(|n| d.bit(Bit::T(n)))),
        'C' => (8, Box::new(|n| d.bit(Bit::C(n)))),
        'D' => (8, Box::new(|_| false)),
        _ => return None,
    };
    // Bit numbers are computed in u32: `X?200` must not overflow.
    let bit = |n: u32| n < u32::from(count) && bits(n as u8);
    if rest == "?" {
        if kind == 'D' {
            return Some((0..8).map(|n| format_d(n, d.d[usize::from(n)])).collect());
        }
        // Groups of eight, each written from its highest bit: M07..M00 M15..M08.
        let groups: Vec<String> = (0..u32::from(count).div_ceil(8))
            .map(|g| {
                (0..8)
                    .rev()
                    .map(|i| if bit(g * 8 + i) { '1' } else { '0' })
                    .collect()
            })
            .collect();
        return Some(vec![format!("{kind}:{}", groups.join(" "))]);
    }
    if let Some(group) = rest.strip_prefix('?') {
        let g: u32 = group.parse::<u8>().ok()?.into();
        let word: u16 = (0..16).fold(0, |w, i| w | u16::from(bit(g * 16 + i)) << i);
        return Some(vec![format!("{word:04X}")]);
    }
    let name = rest.strip_suffix('?')?;
    let device = format!("{kind}{name}");
    if kind == 'D' {
        return Some(match parse_word(&device) {
            Ok(Word::D(n)) => vec![format_d(n, d.d[usize::from(n)])],
            _ => vec![format!(
                "ERR unknown device {}",
                crate::error::shown(&device)
            )],
        });
    }
    Some(match parse_bit(&device) {
        Ok(b) => vec![format!("{b}:{}", u8::from(d.bit(b)))],
        Err(e) => vec![format!("ERR {e}")],
    })
}

/// A D register as the device prints it: hex, then decimal.
fn format_d(n: u8, value: i16) -> String {
    format!("D{n:02}:{:04X}({value})", value as u16)
}

/// The write commands: `Y00=1`, `M05=0`, `D01=xFF`, `D01=255`.
fn write_command(m: &mut Machine, device: &str, value: &str) -> Result<(), String> {
    if device.starts_with('D') {
        let Ok(Word::D(n)) = parse_word(device) else {
            return Err(format!("unknown device {}", crate::error::shown(device)));
        };
        let parsed = match value.strip_prefix('X') {
            Some(hex) => u16::from_str_radix(hex, 16).map(|v| v as i16).ok(),
            None => value.parse::<i16>().ok(),
        };
        let v = parsed.ok_or_else(|| {
            format!(
                "bad value {}: decimal, or hex as xFF",
                crate::error::shown(value)
            )
        })?;
        m.write_word(n, v);
        return Ok(());
    }
    let bit = parse_bit(device).map_err(|e| e.to_string())?;
    if matches!(bit, Bit::X(_)) {
        return Err(format!("{bit} is an input"));
    }
    let on = match value {
        "1" => true,
        "0" => false,
        _ => return Err(format!("bad value {}: 0 or 1", crate::error::shown(value))),
    };
    m.write_bit(bit, on);
    Ok(())
}
