//! The sketch's serial monitor (9600 baud, lines end with CR): `?` help,
//! `s<step> <mnemonic> <operand>` assemble one step, `l` disassemble, `p`
//! hex dump, `e` enable, `d` disable.

use super::isa::{assemble, disassemble, ERASED};
use super::machine::Machine;

const CRLF: &str = "\r\n";

/// The sketch's help text, line by line.
const HELP: [&str; 6] = [
    "? help",
    "s assemble",
    "l disassemble",
    "p show PLC code with hexadecimal format",
    "e enable PLC handling",
    "d disable PLC handling",
];

/// Types one line at the monitor and returns what the sketch sends back.
/// The sketch does not echo; it answers every line with CR LF first.
///
/// Where the sketch would store a garbled word for a bad `s` line, this
/// refuses it and answers `ERR …` instead.
pub fn type_line(machine: &mut Machine, line: &str) -> String {
    let line = line.trim_end_matches(['\r', '\n']);
    let mut out = String::from(CRLF);
    let mut chars = line.chars();
    match chars.next() {
        Some('?') => {
            for help in HELP {
                out.push_str(help);
                out.push_str(CRLF);
            }
        }
        Some('s') => {
            if let Err(message) = store(machine, chars.as_str()) {
                out.push_str(&format!("ERR {message}{CRLF}"));
            }
        }
        Some('l') => {
            for &word in machine.eeprom().iter().take(256) {
                if word == ERASED {
                    break;
                }
                out.push_str(&disassemble(word));
                out.push_str(CRLF);
            }
        }
        Some('p') => out.push_str(&hex_dump(machine.eeprom())),
        Some('e') => machine.set_enabled(true),
        Some('d') => machine.set_enabled(false),
        _ => {}
    }
    out
}

/// The `p` dump: the first 256 words, four hex digits and a space each,
/// sixteen to a line.
pub fn hex_dump(eeprom: &[u16]) -> String {
    let mut out = String::new();
    for i in 0..256 {
        let word = eeprom.get(i).copied().unwrap_or(ERASED);
        out.push_str(&format!("{word:04X} "));
        if i & 15 == 15 {
            out.push_str(CRLF);
        }
    }
    out
}

/// `s<step> <mnemonic> [operand]`, case-insensitive.
fn store(machine: &mut Machine, rest: &str) -> Result<(), String> {
    let mut words = rest.split_whitespace();
    let step: usize = words
        .next()
        .and_then(|s| s.parse().ok())
        .ok_or("s<step> <mnemonic> <operand>, e.g. s0 LD X000")?;
    let mnemonic = words.next().ok_or("a mnemonic after the step")?;
    let operand = words.next();
    if let Some(extra) = words.next() {
        return Err(format!("unexpected {}", crate::error::shown(extra)));
    }
    let word = assemble(mnemonic, operand).map_err(|e| e.to_string())?;
    if machine.write_word(step, word) {
        Ok(())
    } else {
        Err(format!(
            "step {step} is beyond the EEPROM ({} steps)",
            machine.chip().capacity()
        ))
    }
}
