//! Declarations (issue #18): the names a PLCopen file gives its variables
//! (`Start`, `Q1`, `lamp`) turned into the machine's devices. A located
//! variable maps by rule ([`located`]: `%IX0.n` an input, `%QX0.n` an
//! output, `%MX0.n` / `%M0.n` an internal relay, the machine's sizes
//! checked); any other from a map file (`name,device` a line, given as
//! `--map`), which may name function-block instances too (`TON0,T00`).
//! A map entry the file does not use is a warning. Names the file does not
//! declare, and declared names that are the machine's own devices, stay as
//! written (a file written for Hashigo uses `X00`).

use std::collections::{HashMap, HashSet};

use super::dom::Node;
use crate::error::Located;
use crate::ladder::element::Element;
use crate::ladder::target::{check_device, check_element, ElementError};
use crate::MachineId;

/// A map file: `name,device` a line (`#` comments, blank lines and a
/// `name,device` header skipped).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct VarMap {
    /// (name, device, line), in file order.
    pub entries: Vec<(String, String, usize)>,
}

impl VarMap {
    /// A map of `pairs` (name, device), numbered as lines 1, 2, … (what
    /// a file of them would be: the page's mapping table, a proposal).
    pub fn from_pairs(pairs: impl IntoIterator<Item = (String, String)>) -> VarMap {
        let entries = pairs
            .into_iter()
            .enumerate()
            .map(|(i, (name, device))| (name, device, i + 1))
            .collect();
        VarMap { entries }
    }

    /// Reads a map file as a CSV reader would: a byte-order mark skipped,
    /// fields optionally in double quotes (`"I1","X00"`, `""` for a quote
    /// inside), `#` comments outside quotes, blank lines and a
    /// `name,device` header skipped; every malformed line is an error at
    /// its line.
    pub fn parse(text: &str) -> Result<VarMap, Vec<Located<String>>> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut entries = Vec::new();
        let mut errors = Vec::new();
        let mut seen: HashMap<String, usize> = HashMap::new();
        for (i, raw) in text.lines().enumerate() {
            let line = i + 1;
            let malformed = || format!("expected NAME,DEVICE, found {}", crate::shown(raw.trim()));
            let Some(fields) = csv_fields(raw) else {
                errors.push(Located::new(line, malformed()));
                continue;
            };
            let (name, device) = match fields.as_slice() {
                [] => continue,
                [name, device] => (name.as_str(), device.as_str()),
                _ => {
                    errors.push(Located::new(line, malformed()));
                    continue;
                }
            };
            if line == 1
                && name.eq_ignore_ascii_case("name")
                && device.eq_ignore_ascii_case("device")
            {
                continue;
            }
            if name.is_empty() || device.is_empty() {
                errors.push(Located::new(line, malformed()));
                continue;
            }
            if let Some(first) = seen.insert(name.to_ascii_lowercase(), line) {
                errors.push(Located::new(
                    line,
                    format!(
                        "{} is mapped twice (first at line {first})",
                        crate::shown(name)
                    ),
                ));
                continue;
            }
            entries.push((name.to_string(), device.to_string(), line));
        }
        if errors.is_empty() {
            Ok(VarMap { entries })
        } else {
            Err(errors)
        }
    }

    /// Checks every device the map names (each part of a `T01+M20`) on
    /// `machine`, each error at the entry's line, before any import uses
    /// them.
    pub fn check(&self, machine: MachineId) -> Result<(), Vec<Located<ElementError>>> {
        let errors: Vec<_> = self
            .entries
            .iter()
            .flat_map(|(_, device, line)| {
                device
                    .split('+')
                    .filter_map(move |part| check_device(machine, part).err())
                    .map(move |e| Located::new(*line, e))
            })
            .collect();
        if errors.is_empty() {
            Ok(())
        } else {
            Err(errors)
        }
    }
}

/// One CSV line's fields, trimmed, with `#` starting a comment outside
/// quotes; `None` when a quote is not closed or text follows one.
fn csv_fields(line: &str) -> Option<Vec<String>> {
    let mut fields = Vec::new();
    let mut chars = line.chars().peekable();
    loop {
        while chars.next_if(|c| *c == ' ' || *c == '\t').is_some() {}
        let mut field = String::new();
        if chars.next_if_eq(&'"').is_some() {
            loop {
                match chars.next()? {
                    '"' if chars.next_if_eq(&'"').is_some() => field.push('"'),
                    '"' => break,
                    c => field.push(c),
                }
            }
            while chars.next_if(|c| *c == ' ' || *c == '\t').is_some() {}
            if !matches!(chars.peek(), None | Some(',' | '#')) {
                return None;
            }
        } else {
            while let Some(c) = chars.next_if(|c| *c != ',' && *c != '#') {
                field.push(c);
            }
            field.truncate(field.trim_end().len());
        }
        let blank_line = fields.is_empty() && field.is_empty() && chars.peek() != Some(&',');
        if !blank_line {
            fields.push(field);
        }
        match chars.next() {
            Some(',') => continue,
            _ => return Some(fields),
        }
    }
}

/// What a name stands for.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Meaning {
    /// A device, from the variable's address or the map (its line).
    Device(String, Option<usize>),
    /// A declared variable with neither (the declaration's line).
    Unmapped(usize),
    /// A located variable the machine has no device for (why, line).
    Refused(String, usize),
}

/// A file's names and what each stands for on one machine.
#[derive(Debug, Default)]
pub struct Names {
    by_name: HashMap<String, (String, Meaning)>,
    /// Declared initial values (`T#2s`, `10`) and their lines, by
    /// lower-case name.
    initial: HashMap<String, (String, String, usize)>,
    /// Declared elementary types (`BOOL`, `INT`), by lower-case name.
    types: HashMap<String, String>,
    used_map_lines: std::cell::RefCell<HashSet<usize>>,
    map_lines: Vec<(String, usize)>,
}

impl Names {
    /// No names: every variable as written.
    pub fn none() -> Names {
        Names::default()
    }

    /// The device `name` (a variable or block instance, as written in the
    /// body) stands for: mapped, located, or `name` itself when the file
    /// does not declare it.
    pub fn device(&self, name: &str) -> Result<String, String> {
        match self.by_name.get(&name.trim().to_ascii_lowercase()) {
            None => Ok(name.trim().to_string()),
            Some((declared, meaning)) => match meaning {
                Meaning::Device(d, map_line) => {
                    if let Some(l) = map_line {
                        self.used_map_lines.borrow_mut().insert(*l);
                    }
                    Ok(d.clone())
                }
                Meaning::Unmapped(line) => Err(format!(
                    "variable {declared} (declared at line {line}) has no device: give it an \
                     address (%IX0.0, %QX0.0, %MX0.0) or map it (--map: {declared},DEVICE)"
                )),
                Meaning::Refused(why, line) => {
                    Err(format!("variable {declared} (line {line}): {why}"))
                }
            },
        }
    }

    /// The elementary type `name` is declared with (`BOOL`, `INT`), if
    /// the file declares it with one.
    pub fn declared_type(&self, name: &str) -> Option<&str> {
        self.types
            .get(&name.trim().to_ascii_lowercase())
            .map(String::as_str)
    }

    /// The initial value `name` is declared with (a PT or PV given by a
    /// constant-initialised variable).
    pub fn initial(&self, name: &str) -> Option<&str> {
        self.initial
            .get(&name.trim().to_ascii_lowercase())
            .map(|(_, v, _)| v.as_str())
    }

    /// Variables declared to start on (a BOOL `TRUE`, a non-zero number)
    /// and the device each stands for: (name, device, value, line).
    pub fn starting_on(&self) -> Vec<(String, String, String, usize)> {
        let mut out: Vec<(String, String, String, usize)> = self
            .initial
            .iter()
            .filter(|(_, (_, v, _))| {
                let v = v.trim();
                !v.eq_ignore_ascii_case("FALSE")
                    && v.parse::<f64>()
                        .map_or(v.eq_ignore_ascii_case("TRUE"), |n| n != 0.0)
            })
            .filter_map(|(key, (name, value, line))| {
                let device = match self.by_name.get(key) {
                    Some((_, Meaning::Device(d, _))) => d.clone(),
                    Some(_) => return None,
                    None => name.clone(),
                };
                Some((name.clone(), device, value.clone(), *line))
            })
            .collect();
        out.sort_by_key(|o| o.3);
        out
    }

    /// The device a block instance stands for, if the map names it.
    pub fn instance(&self, name: &str) -> Option<String> {
        match self.by_name.get(&name.trim().to_ascii_lowercase()) {
            Some((_, Meaning::Device(d, Some(l)))) => {
                self.used_map_lines.borrow_mut().insert(*l);
                Some(d.clone())
            }
            _ => None,
        }
    }

    /// The variable names of the devices used, for device comments.
    pub fn comments(&self) -> Vec<(String, String)> {
        let mut out: Vec<(String, String)> = self
            .by_name
            .values()
            .filter_map(|(name, m)| match m {
                Meaning::Device(d, _) if !d.eq_ignore_ascii_case(name) => {
                    Some((d.clone(), name.clone()))
                }
                _ => None,
            })
            .collect();
        out.sort();
        out
    }

    /// The machine's relays no name stands for (a mapped instance's
    /// `T01+M20` counts its relay) and not in `also`: what the importer
    /// may take to hold a network's power (highest first, as
    /// [`Vec::pop`] gives them).
    pub fn spare_relays(&self, machine: MachineId, also: &HashSet<String>) -> Vec<String> {
        let mut taken = self.taken();
        taken.extend(also.iter().map(|d| d.to_ascii_uppercase()));
        Pools::of(machine)
            .relays
            .into_iter()
            .filter(|r| !taken.contains(r))
            .collect()
    }

    /// Every device a name stands for, upper case (a mapped instance's
    /// `T01+M20` gives both).
    fn taken(&self) -> HashSet<String> {
        self.by_name
            .values()
            .filter_map(|(_, m)| match m {
                Meaning::Device(d, _) => Some(d),
                _ => None,
            })
            .flat_map(|d| d.split('+'))
            .map(|d| d.trim().to_ascii_uppercase())
            .collect()
    }

    /// The map's lines that no element used.
    pub fn unused_map_lines(&self) -> Vec<(String, usize)> {
        let used = self.used_map_lines.borrow();
        self.map_lines
            .iter()
            .filter(|(_, l)| !used.contains(l))
            .cloned()
            .collect()
    }
}

/// Reads every variable declared in `root` (each POU's interface, the
/// configurations' and resources' globals) for `machine`, with `map`.
pub fn names(root: &Node, machine: MachineId, map: Option<&VarMap>) -> Names {
    let mut names = Names::none();
    let mut variables = Vec::new();
    for scope in [
        "localVars",
        "inputVars",
        "outputVars",
        "inOutVars",
        "externalVars",
        "globalVars",
        "tempVars",
    ] {
        let mut blocks = Vec::new();
        root.descendants(scope, &mut blocks);
        for b in blocks {
            variables.extend(b.all("variable"));
        }
    }
    for v in variables {
        let Some(name) = v.attr("name") else {
            continue;
        };
        let initial = v
            .child("initialValue")
            .and_then(|i| i.child("simpleValue"))
            .and_then(|s| s.attr("value"));
        if let Some(value) = initial {
            names.initial.insert(
                name.to_ascii_lowercase(),
                (name.to_string(), value.to_string(), v.line),
            );
        }
        if let Some(ty) = v
            .child("type")
            .and_then(|t| t.children.first())
            .filter(|t| t.name != "derived")
        {
            names
                .types
                .insert(name.to_ascii_lowercase(), ty.name.to_ascii_uppercase());
        }
        // A file written for Hashigo names the devices themselves.
        if check_element(machine, &Element::no(name)).is_ok() {
            continue;
        }
        let elementary = v
            .child("type")
            .is_some_and(|t| t.children.iter().all(|c| c.name != "derived"));
        let meaning = match v.attr("address") {
            Some(address) => match located(machine, address) {
                Ok(device) => Meaning::Device(device, None),
                Err(why) => Meaning::Refused(why, v.line),
            },
            // A function-block instance is the block itself unless mapped.
            None if !elementary => continue,
            None => Meaning::Unmapped(v.line),
        };
        names
            .by_name
            .insert(name.to_ascii_lowercase(), (name.to_string(), meaning));
    }
    for (name, device, line) in map.map(|m| m.entries.as_slice()).unwrap_or(&[]) {
        names.map_lines.push((name.clone(), *line));
        names.by_name.insert(
            name.to_ascii_lowercase(),
            (name.clone(), Meaning::Device(device.clone(), Some(*line))),
        );
    }
    names
}

/// The device a located variable's address stands for on `machine`:
/// `%IX0.n` input n, `%QX0.n` output n, `%MX0.n` (or `%M0.n`) internal
/// relay n (byte b, bit n: b × 8 + n), within the machine's sizes.
pub fn located(machine: MachineId, address: &str) -> Result<String, String> {
    let a = address.trim().to_ascii_uppercase();
    let bad = || {
        format!(
            "address {} is not %IX0.0, %QX0.0 or %MX0.0",
            crate::shown(address)
        )
    };
    let rest = a.strip_prefix('%').ok_or_else(bad)?;
    let mut chars = rest.chars();
    let area = chars.next().ok_or_else(bad)?;
    let rest = chars.as_str();
    // IO86A reads X04 / X05 as analog words into D06 / D07.
    if machine == MachineId::Io86a && area == 'I' {
        match rest {
            "W0" => return Ok("D06".to_string()),
            "W1" => return Ok("D07".to_string()),
            _ => {}
        }
    }
    let rest = match rest.chars().next() {
        Some('X') => &rest[1..],
        Some('B' | 'W' | 'D' | 'L') => {
            return Err(format!(
                "{address} is a word: Hashigo's ladders import bit variables only (and IO86A's analog inputs %IW0, %IW1)"
            ))
        }
        _ => rest,
    };
    let (byte, bit) = rest.split_once('.').ok_or_else(bad)?;
    let (byte, bit): (u32, u32) = (
        byte.parse().map_err(|_| bad())?,
        bit.parse().map_err(|_| bad())?,
    );
    if bit > 7 {
        return Err(bad());
    }
    let n = byte.saturating_mul(8).saturating_add(bit);
    let device = match (machine, area) {
        (MachineId::Io86a | MachineId::MinasecU, 'I') => format!("X{n:02}"),
        (MachineId::Io86a | MachineId::MinasecU, 'Q') => format!("Y{n:02}"),
        (MachineId::Io86a, 'M') => format!("M{n:02}"),
        // MINASEC-U's relays are M00-M07 and M10-M13.
        (MachineId::MinasecU, 'M') => format!("M{}{}", n / 8, n % 8),
        (MachineId::ArduinoPlc, 'I') => format!("X{n:03}"),
        (MachineId::ArduinoPlc, 'Q') => format!("Y{n:03}"),
        (MachineId::ArduinoPlc, 'M') => {
            return Err("the Arduino PLC has no internal relays".to_string())
        }
        (MachineId::AvrPlc, 'I' | 'Q' | 'M') => return avr_located(area, n, address),
        _ => return Err(bad()),
    };
    check_element(machine, &Element::no(&device))
        .map(|_| device)
        .map_err(|e| format!("{address} is {e}"))
}

/// The AVR PLC has no fixed inputs or outputs (any register bit may be
/// either); Hashigo follows the seed's own program, inputs in R4 and
/// coils in R5, relays after them, and leaves R16-R25 to the compiler's
/// temporaries: `%IX0.n` → R4.n, `%QX0.n` → R5.n, `%MXb.n` → R(6+b).n
/// up to R15.7.
fn avr_located(area: char, n: u32, address: &str) -> Result<String, String> {
    let (registers, what) = match area {
        'I' => (AVR_INPUTS, "inputs"),
        'Q' => (AVR_OUTPUTS, "outputs"),
        _ => (AVR_RELAYS, "relays"),
    };
    let bits = registers.len() as u32 * 8;
    if n >= bits {
        let (first, last) = (registers.start, registers.end - 1);
        return Err(format!(
            "{address} is past the AVR PLC's {what} (R{first}.0-R{last}.7 in Hashigo)"
        ));
    }
    Ok(format!("R{}.{}", registers.start as u32 + n / 8, n % 8))
}

/// The AVR PLC's registers for inputs, outputs and relays
/// ([`avr_located`], and what `propose` hands out).
const AVR_INPUTS: std::ops::Range<u8> = 4..5;
const AVR_OUTPUTS: std::ops::Range<u8> = 5..6;
const AVR_RELAYS: std::ops::Range<u8> = 6..16;

/// A device proposed for every declared variable and block instance of
/// the file that has none yet (`map` and addresses first), for the page's
/// mapping table and `hashigo map`: a variable some coil writes gets the
/// next free output (then relay), one only read the next free input
/// (then relay); a timer instance the next free timer, a counter the next
/// counter, a flip-flop the next relay. Where the machine runs out, or has
/// no such device (the Arduino PLC's relays, the AVR PLC's counters), the
/// name is left out: the user maps it by hand. In file order, each once.
pub fn propose(root: &Node, machine: MachineId, map: Option<&VarMap>) -> Vec<(String, String)> {
    propose_in(root, root, machine, map)
}

/// [`propose`] for what one POU (`scope`, `--pou NAME`) uses: its own
/// declarations, and the globals its body names.
pub fn propose_in(
    root: &Node,
    scope: &Node,
    machine: MachineId,
    map: Option<&VarMap>,
) -> Vec<(String, String)> {
    let names = names(root, machine, map);
    let mut taken = names.taken();
    // Every name the bodies use for power, and whether something writes it.
    let mut used: Vec<(String, bool)> = Vec::new();
    let mut note = |name: &str, writes: bool| {
        let name = name.trim();
        match used.iter_mut().find(|(n, _)| n.eq_ignore_ascii_case(name)) {
            Some((_, w)) => *w |= writes,
            None if !name.is_empty() => used.push((name.to_string(), writes)),
            None => {}
        }
    };
    for (tag, child, writes) in [
        ("contact", "variable", false),
        ("coil", "variable", true),
        ("outVariable", "expression", true),
    ] {
        let mut found = Vec::new();
        scope.descendants(tag, &mut found);
        for n in found {
            if let Some(v) = n.child(child) {
                note(&v.text, writes);
            }
        }
    }
    let written: HashSet<String> = used
        .iter()
        .filter(|(_, w)| *w)
        .map(|(n, _)| n.to_ascii_lowercase())
        .collect();
    // The machine's own devices the bodies name (`X00`) are taken too.
    taken.extend(
        used.iter()
            .filter(|(n, _)| !names.by_name.contains_key(&n.to_ascii_lowercase()))
            .filter(|(n, _)| check_element(machine, &Element::no(n)).is_ok())
            .map(|(n, _)| n.to_ascii_uppercase()),
    );
    let mut blocks = Vec::new();
    scope.descendants("block", &mut blocks);
    let mut instances: Vec<(String, String)> = Vec::new();
    for b in blocks {
        let (Some(ty), Some(name)) = (b.attr("typeName"), b.attr("instanceName")) else {
            continue;
        };
        if !name.is_empty() && !instances.iter().any(|(n, _)| n.eq_ignore_ascii_case(name)) {
            instances.push((name.to_string(), ty.to_ascii_uppercase()));
        }
    }
    let pools = Pools::of(machine);
    let next = |pool: &[String], taken: &mut HashSet<String>| {
        let free = pool.iter().find(|d| !taken.contains(*d))?.clone();
        taken.insert(free.clone());
        Some(free)
    };
    let mut out: Vec<(String, String)> = Vec::new();
    // Declared BOOLs with no device (or an address the machine lacks),
    // then names the bodies use without declaring them.
    let open = |name: &str| {
        matches!(
            names.by_name.get(&name.to_ascii_lowercase()),
            Some((_, Meaning::Unmapped(_) | Meaning::Refused(..)))
        )
    };
    let mut variables = Vec::new();
    scope.descendants("variable", &mut variables);
    let declared = variables.iter().filter_map(|v| {
        let name = v.attr("name")?;
        let bool_typed = v.child("type").is_some_and(|t| t.child("BOOL").is_some());
        (bool_typed && open(name)).then(|| name.to_string())
    });
    // One POU: the globals (declared outside it) its body names too.
    let scoped = !std::ptr::eq(root, scope);
    let globals = used
        .iter()
        .filter(move |(name, _)| scoped && open(name))
        .map(|(name, _)| name.clone());
    let undeclared = used.iter().filter_map(|(name, _)| {
        let known = names.by_name.contains_key(&name.to_ascii_lowercase())
            || check_element(machine, &Element::no(name)).is_ok();
        (!known).then(|| name.clone())
    });
    let candidates: Vec<String> = declared.chain(globals).chain(undeclared).collect();
    for name in candidates {
        let key = name.to_ascii_lowercase();
        if out.iter().any(|(n, _)| n.eq_ignore_ascii_case(&name)) {
            continue;
        }
        let device = if written.contains(&key) {
            next(&pools.outputs, &mut taken).or_else(|| next(&pools.relays, &mut taken))
        } else {
            next(&pools.inputs, &mut taken).or_else(|| next(&pools.relays, &mut taken))
        };
        if let Some(d) = device {
            out.push((name, d));
        }
    }
    for (name, ty) in instances {
        if names.instance(&name).is_some() || check_element(machine, &Element::no(&name)).is_ok() {
            continue;
        }
        // IO86A's timers are on-delay: a TOF or TP also holds its output
        // in a relay (`T01+M20`).
        if machine == MachineId::Io86a && matches!(ty.as_str(), "TOF" | "TP") {
            let timer = next(&pools.timers, &mut taken);
            let relay = next(&pools.relays, &mut taken);
            if let (Some(t), Some(m)) = (timer, relay) {
                out.push((name, format!("{t}+{m}")));
            }
            continue;
        }
        let pool = match ty.as_str() {
            "TON" | "TOF" | "TP" => &pools.timers,
            "CTU" | "CTD" | "CTUD" => &pools.counters,
            "SR" | "RS" => &pools.relays,
            _ => continue,
        };
        if let Some(d) = next(pool, &mut taken) {
            out.push((name, d));
        }
    }
    out
}

/// A machine's devices by kind, in the order proposals take them.
struct Pools {
    inputs: Vec<String>,
    outputs: Vec<String>,
    relays: Vec<String>,
    timers: Vec<String>,
    counters: Vec<String>,
}

impl Pools {
    fn of(machine: MachineId) -> Pools {
        let range = |prefix: &str, width: usize, ns: std::ops::Range<u32>| -> Vec<String> {
            ns.map(|n| format!("{prefix}{n:0width$}")).collect()
        };
        match machine {
            MachineId::Io86a => Pools {
                inputs: range("X", 2, 0..8),
                outputs: range("Y", 2, 0..6),
                // M56-M63 are the special relays.
                relays: range("M", 2, 0..56),
                timers: range("T", 2, 0..32),
                counters: range("C", 2, 0..8),
            },
            MachineId::MinasecU => Pools {
                inputs: range("X", 2, 0..8),
                outputs: range("Y", 2, 0..8),
                relays: [range("M", 2, 0..8), range("M1", 1, 0..4)].concat(),
                timers: vec!["T0".into(), "T1".into()],
                counters: vec!["C0".into()],
            },
            MachineId::ArduinoPlc => Pools {
                inputs: range("X", 3, 0..6),
                outputs: range("Y", 3, 0..6),
                relays: Vec::new(),
                timers: Vec::new(),
                counters: Vec::new(),
            },
            // [`avr_located`]'s registers; timers are named in-line boxes
            // (an instance keeps its name), and there are no counters.
            MachineId::AvrPlc => {
                let bits = |registers: std::ops::Range<u8>| -> Vec<String> {
                    registers
                        .flat_map(|r| (0..8).map(move |b| format!("R{r}.{b}")))
                        .collect()
                };
                Pools {
                    inputs: bits(AVR_INPUTS),
                    outputs: bits(AVR_OUTPUTS),
                    relays: bits(AVR_RELAYS),
                    timers: Vec::new(),
                    counters: Vec::new(),
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn located_variables_map_by_rule_within_the_machines_sizes() {
        let io = MachineId::Io86a;
        assert_eq!(located(io, "%IX0.3").as_deref(), Ok("X03"));
        assert_eq!(located(io, "%QX0.5").as_deref(), Ok("Y05"));
        assert_eq!(located(io, "%MX1.2").as_deref(), Ok("M10"));
        assert_eq!(located(io, "%m0.1").as_deref(), Ok("M01"));
        assert!(located(io, "%QX0.6").is_err(), "IO86A has Y00-Y05");
        assert_eq!(
            located(io, "%IW1").as_deref(),
            Ok("D07"),
            "X05's analog value"
        );
        assert!(located(io, "%IW2").is_err(), "a word IO86A lacks");
        assert!(located(MachineId::MinasecU, "%IW0").is_err(), "a word");
        assert!(located(io, "IX0.0").is_err());
        assert!(located(io, "%IX0.9").is_err());
        let m = MachineId::MinasecU;
        assert_eq!(located(m, "%MX1.3").as_deref(), Ok("M13"));
        assert!(located(m, "%MX1.4").is_err(), "MINASEC-U has M10-M13");
        assert_eq!(
            located(MachineId::ArduinoPlc, "%QX0.0").as_deref(),
            Ok("Y000")
        );
        let avr = MachineId::AvrPlc;
        assert_eq!(located(avr, "%IX0.3").as_deref(), Ok("R4.3"));
        assert_eq!(located(avr, "%QX0.7").as_deref(), Ok("R5.7"));
        assert_eq!(located(avr, "%MX1.2").as_deref(), Ok("R7.2"));
        assert_eq!(located(avr, "%MX9.7").as_deref(), Ok("R15.7"));
        let past = located(avr, "%MX10.0").expect_err("R16 is the compiler's");
        assert_eq!(
            past,
            "%MX10.0 is past the AVR PLC's relays (R6.0-R15.7 in Hashigo)"
        );
        assert!(located(avr, "%IX1.0").is_err(), "R4 holds the inputs");
        assert!(located(avr, "%QX0.8").is_err());
    }

    #[test]
    fn map_files_read_and_refuse_by_line() {
        let map = VarMap::parse("name,device\n# lamps\nStart, X00\nTON0,T00 # the timer\n\n")
            .expect("a map");
        assert_eq!(
            map.entries,
            vec![
                ("Start".into(), "X00".into(), 3),
                ("TON0".into(), "T00".into(), 4)
            ]
        );
        let errors = VarMap::parse("Start\nA,X00\na,X01\nB,\n").expect_err("bad lines");
        let lines: Vec<usize> = errors.iter().map(|e| e.line).collect();
        assert_eq!(lines, vec![1, 3, 4]);
    }
}
