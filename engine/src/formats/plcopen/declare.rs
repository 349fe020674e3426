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

pub use super::address::{located, AddressError};
use super::dom::Node;
use super::kinds::BlockKind;
pub use super::map_file::{MapError, VarMap};
use crate::ladder::element::Element;
use crate::ladder::machine_target::DevicePools;
use crate::ladder::target::check_element;
use crate::MachineId;

/// Why a name the body uses has no device.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NameError {
    /// A declared variable neither located nor mapped.
    Unmapped {
        /// The name as declared.
        declared: String,
        /// The declaration's line.
        line: usize,
    },
    /// A located variable whose address the machine has no device for.
    Refused {
        /// The name as declared.
        declared: String,
        /// The declaration's line.
        line: usize,
        /// Why (the address's own error, in words).
        why: String,
    },
}

impl std::fmt::Display for NameError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            NameError::Unmapped { declared, line } => write!(
                f,
                "variable {declared} (declared at line {line}) has no device: give it an \
                 address (%IX0.0, %QX0.0, %MX0.0) or map it (--map: {declared},DEVICE)"
            ),
            NameError::Refused {
                declared,
                line,
                why,
            } => write!(f, "variable {declared} (line {line}): {why}"),
        }
    }
}

impl std::error::Error for NameError {}

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
    pub fn device(&self, name: &str) -> Result<String, NameError> {
        match self.by_name.get(&name.trim().to_ascii_lowercase()) {
            None => Ok(name.trim().to_string()),
            Some((declared, meaning)) => match meaning {
                Meaning::Device(d, map_line) => {
                    if let Some(l) = map_line {
                        self.used_map_lines.borrow_mut().insert(*l);
                    }
                    Ok(d.clone())
                }
                Meaning::Unmapped(line) => Err(NameError::Unmapped {
                    declared: declared.clone(),
                    line: *line,
                }),
                Meaning::Refused(why, line) => Err(NameError::Refused {
                    declared: declared.clone(),
                    line: *line,
                    why: why.clone(),
                }),
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
        crate::sort::by_key(&mut out, |o| o.3);
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
        crate::sort::all(&mut out);
        out
    }

    /// The machine's relays no name stands for (a mapped instance's
    /// `T01+M20` counts its relay) and not in `also`: what the importer
    /// may take to hold a network's power (highest first, as
    /// [`Vec::pop`] gives them).
    pub fn spare_relays(&self, machine: MachineId, also: &HashSet<String>) -> Vec<String> {
        let mut taken = self.taken();
        taken.extend(also.iter().map(|d| d.to_ascii_uppercase()));
        machine
            .target()
            .spare_bits()
            .into_iter()
            .filter(|r| !taken.contains(&r.to_ascii_uppercase()))
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
        // Hashigo's own export names a bare soft PLC address `IX0_0`.
        let address = v.attr("address").unwrap_or_default();
        if machine.target().capabilities().word_boxes && super::address::stands_for(name, address) {
            let device = Meaning::Device(address.trim().to_string(), None);
            let key = name.to_ascii_lowercase();
            names.by_name.insert(key, (name.to_string(), device));
            continue;
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
                Err(why) => Meaning::Refused(why.to_string(), v.line),
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
    let used = used_names(scope);
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
    let instances = block_instances(scope);
    let pools = machine.target().pools();
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
    out.extend(propose_instances(
        &names, machine, instances, &pools, &mut taken,
    ));
    out
}

/// The first device of `pool` not `taken`, then taken.
fn next(pool: &[String], taken: &mut HashSet<String>) -> Option<String> {
    let free = pool.iter().find(|d| !taken.contains(*d))?.clone();
    taken.insert(free.clone());
    Some(free)
}

/// A device for each block instance neither mapped nor named as a device:
/// the next free timer, counter or relay (IO86A's TOF and TP a timer and a
/// relay, `T01+M20`).
fn propose_instances(
    names: &Names,
    machine: MachineId,
    instances: Vec<(String, BlockKind)>,
    pools: &DevicePools,
    taken: &mut HashSet<String>,
) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for (name, ty) in instances {
        if names.instance(&name).is_some() || check_element(machine, &Element::no(&name)).is_ok() {
            continue;
        }
        // IO86A's timers are on-delay: a TOF or TP also holds its output
        // in a relay (`T01+M20`).
        if machine.target().capabilities().timer_counter_coils
            && matches!(ty, BlockKind::Tof | BlockKind::Tp)
        {
            let timer = next(&pools.timers, taken);
            let relay = next(&pools.relays, taken);
            if let (Some(t), Some(m)) = (timer, relay) {
                out.push((name, format!("{t}+{m}")));
            }
            continue;
        }
        let pool = match ty {
            BlockKind::Ton | BlockKind::Tof | BlockKind::Tp => &pools.timers,
            BlockKind::Ctu | BlockKind::Ctd | BlockKind::Ctud => &pools.counters,
            BlockKind::Sr | BlockKind::Rs => &pools.relays,
            _ => continue,
        };
        if let Some(d) = next(pool, taken) {
            out.push((name, d));
        }
    }
    out
}

/// Every name `scope`'s bodies use for power (contacts, coils, output
/// boxes), once each, and whether something writes it.
fn used_names(scope: &Node) -> Vec<(String, bool)> {
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
    used
}

/// Every block instance `scope` names, once each, with its type.
fn block_instances(scope: &Node) -> Vec<(String, BlockKind)> {
    let mut blocks = Vec::new();
    scope.descendants("block", &mut blocks);
    let mut instances: Vec<(String, BlockKind)> = Vec::new();
    for b in blocks {
        let (Some(ty), Some(name)) = (b.attr("typeName"), b.attr("instanceName")) else {
            continue;
        };
        // Blocks Hashigo has no form for take no device (the import says so).
        let Some(kind) = BlockKind::parse(ty) else {
            continue;
        };
        if !name.is_empty() && !instances.iter().any(|(n, _)| n.eq_ignore_ascii_case(name)) {
            instances.push((name.to_string(), kind));
        }
    }
    instances
}

#[cfg(test)]
#[path = "declare_tests.rs"]
mod tests;
