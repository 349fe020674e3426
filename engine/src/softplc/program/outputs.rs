//! A block instance's outputs read as operands (`LD t0.Q`, `GT c0.CV`,
//! `CAL t1(IN := t0.Q)`), as IEC 61131-3 IL reads them. A standard
//! block's output read so gets a slot of its own, which every call of
//! the instance writes as it writes the outputs given with `=>`; an
//! output of an instance of the program's own blocks is its variable.
//! Outputs are read, never written.

use super::check::find_pin;
use super::{CallWhy, LoadError, Named, Program, Src, Step, TypeWhy};
use crate::iec::pins::{inputs, outputs};
use crate::runtime::instance::Instance;

/// Why `instance.pin` is not an output of a `kind`: IEC's IL may also
/// store to a block's input before a bare `CAL` (`ST t0.IN` / `CAL t0`);
/// the soft PLC gives inputs in the CAL, which says so.
fn no_output(kind: &str, instance: &str, pin: &str, input: bool) -> LoadError {
    if input {
        return LoadError::Call(CallWhy::InputRead {
            instance: instance.to_string(),
            pin: pin.to_string(),
            block: kind.to_string(),
        });
    }
    LoadError::NoPin {
        block: kind.to_string(),
        pin: pin.to_string(),
        output: true,
    }
}

impl Program {
    /// The source of `instance.pin`, an output of a block instance.
    pub(super) fn output_slot(&mut self, instance: &str, pin: &str) -> Result<Src, LoadError> {
        let named = self.by_name.get(&instance.to_ascii_uppercase()).copied();
        match named {
            Some(Named::Block(block)) => {
                let kind = self.block_names[block].1.clone();
                let input = find_pin(&inputs(&kind), pin).is_some();
                let (i, _) = find_pin(&outputs(&kind), pin)
                    .ok_or_else(|| no_output(&kind, instance, pin, input))?;
                if let Some(&(.., slot)) = self.shadows.iter().find(|s| (s.0, s.1) == (block, i)) {
                    return Ok(Src::Slot(slot));
                }
                let slot = self.values.len();
                self.values.push(Instance::new(&kind).output(i));
                self.shadows.push((block, i, slot));
                Ok(Src::Slot(slot))
            }
            Some(Named::User(u)) => {
                let ty = &self.user_types[self.instances[u].ty].name;
                self.instances[u]
                    .outputs
                    .iter()
                    .find(|(n, _)| n.eq_ignore_ascii_case(pin))
                    .map(|&(_, s)| Src::Slot(s))
                    .ok_or_else(|| {
                        let input = self.instances[u]
                            .inputs
                            .iter()
                            .any(|(n, _)| n.eq_ignore_ascii_case(pin));
                        no_output(ty, instance, pin, input)
                    })
            }
            Some(Named::Slot(_)) => Err(LoadError::Type(TypeWhy::NotInstance {
                name: instance.to_string(),
                pin: pin.to_string(),
            })),
            None => Err(LoadError::Undeclared(instance.to_string())),
        }
    }

    /// Whether `slot` (the operand `what`) may be written: a block's
    /// output is read, not written.
    pub(super) fn writable(&self, slot: usize, what: &str) -> Result<(), LoadError> {
        let own = || {
            self.instances
                .iter()
                .any(|u| u.outputs.iter().any(|&(_, s)| s == slot))
        };
        if (what.contains('.') && own()) || self.shadows.iter().any(|s| s.2 == slot) {
            return Err(LoadError::Type(TypeWhy::ReadOnly(what.to_string())));
        }
        Ok(())
    }

    /// Every call of a standard block whose outputs are read as operands
    /// writes them to their slots too.
    pub(super) fn wire_outputs(&mut self) {
        if self.shadows.is_empty() {
            return;
        }
        for step in &mut self.steps {
            if let Step::Cal { block, outputs, .. } = step {
                for &(b, pin, slot) in &self.shadows {
                    if b == *block {
                        outputs.push((pin, slot));
                    }
                }
            }
        }
    }
}
