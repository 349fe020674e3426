//! A loaded program's scan and its I/O: the input terminals are read at
//! the scan's start, the steps run top to bottom (jumps as written), the
//! outputs are what the `%Q` variables hold at its end.

use std::cmp::Ordering;

use super::address::{Address, Area};
use super::data::DataType;
use super::data::{self, Data, Shift};
use super::il::Function;
use super::pins::Instance;
use super::program::{Binary, Cmp, Program, Src, Step, STEPS_PER_SCAN};

impl Program {
    /// Runs one scan at simulated time `now` (ns).
    pub fn scan(&mut self, now: i64) {
        for &(slot, v) in &self.input_terminals {
            self.values[slot] = v;
        }
        let mut cr = Data::Bool(false);
        let mut open: Vec<(Binary, Data)> = Vec::new();
        let mut pc = 0;
        let mut ran = 0;
        self.overran = false;
        // Taken out while they run, so that a call can change the blocks
        // and values without copying its step; put back below.
        let steps = std::mem::take(&mut self.steps);
        while let Some(step) = steps.get(pc) {
            ran += 1;
            if ran > STEPS_PER_SCAN {
                self.overran = true;
                break;
            }
            pc += 1;
            let on = |when: Option<bool>, cr: Data| when.is_none_or(|w| cr == Data::Bool(w));
            match step {
                Step::Ld(src, neg) => cr = negate(read(&self.values, *src), *neg),
                Step::St(slot, neg) => self.values[*slot] = negate(cr, *neg),
                Step::Set(slot) if cr == Data::Bool(true) => self.values[*slot] = Data::Bool(true),
                Step::Reset(slot) if cr == Data::Bool(true) => {
                    self.values[*slot] = Data::Bool(false)
                }
                Step::Set(_) | Step::Reset(_) => {}
                Step::Not => cr = negate(cr, true),
                Step::Binary(op, src) => cr = apply(*op, cr, read(&self.values, *src)),
                Step::Open(op, src) => {
                    open.push((*op, cr));
                    if let Some(src) = src {
                        cr = read(&self.values, *src);
                    }
                }
                Step::Close => {
                    if let Some((op, saved)) = open.pop() {
                        cr = apply(op, saved, cr);
                    }
                }
                Step::Func(f, args) => {
                    // At most two operands: read without allocating.
                    let mut values = [cr; 2];
                    for (v, &a) in values.iter_mut().zip(args) {
                        *v = read(&self.values, a);
                    }
                    cr = function(*f, cr, &values[..args.len().min(2)]);
                }
                Step::Jmp(when, target) => {
                    if on(*when, cr) {
                        pc = *target;
                    }
                }
                Step::Ret(when) => {
                    if on(*when, cr) {
                        break;
                    }
                }
                Step::Cal {
                    when,
                    block,
                    inputs,
                    outputs,
                } => {
                    if on(*when, cr) {
                        self.call_block(*block, inputs, outputs, now);
                    }
                }
            }
        }
        self.steps = steps;
    }

    /// Calls block instance `block` with `inputs` and copies its `outputs`.
    fn call_block(
        &mut self,
        block: usize,
        inputs: &[(usize, Src)],
        outputs: &[(usize, usize)],
        now: i64,
    ) {
        // The values and the blocks are apart: read one, write the other.
        let Some(instance) = self.blocks.get_mut(block) else {
            return;
        };
        for &(i, src) in inputs {
            if let Some(slot) = instance.inputs.get_mut(i) {
                *slot = read(&self.values, src);
            }
        }
        instance.call(now);
        for &(i, slot) in outputs {
            self.values[slot] = instance.output(i);
        }
    }

    /// Sets what an input's terminal gives (read at the next scan's
    /// start); `false` when the program has no such input or the value's
    /// type is not the input's.
    pub fn set_input(&mut self, address: Address, value: Data) -> bool {
        let Some(&(_, slot)) = self.addresses.iter().find(|(a, _)| *a == address) else {
            return false;
        };
        match self.input_terminals.iter_mut().find(|(s, _)| *s == slot) {
            Some(t) if address.area == Area::Input && t.1.data_type() == value.data_type() => {
                t.1 = value;
                true
            }
            _ => false,
        }
    }

    /// The value of a declared name (any case) or an address the program
    /// uses.
    pub fn value(&self, name_or_address: &str) -> Option<Data> {
        let slot = match Address::parse(name_or_address) {
            Ok(a) => self.addresses.iter().find(|(b, _)| *b == a)?.1,
            Err(_) => {
                self.names
                    .iter()
                    .find(|(n, _)| n.eq_ignore_ascii_case(name_or_address))?
                    .1
            }
        };
        self.values.get(slot).copied()
    }

    /// The addresses the program uses, in their order of first use.
    pub fn io(&self) -> impl Iterator<Item = Address> + '_ {
        self.addresses.iter().map(|&(a, _)| a)
    }

    /// Whether the last scan was cut short at [`STEPS_PER_SCAN`].
    pub fn overran(&self) -> bool {
        self.overran
    }

    /// A power cycle: every value back to its declared start but the
    /// `VAR_RETAIN` ones; every block starts over.
    pub fn power_cycle(&mut self) {
        for (slot, v) in self.values.iter_mut().enumerate() {
            if !self.retained.contains(&slot) {
                *v = self.initial[slot];
            }
        }
        for (b, (_, kind)) in self.blocks.iter_mut().zip(&self.block_names) {
            *b = Instance::new(kind);
        }
    }
}

/// What `src` holds: a value of the table, or a constant.
fn read(values: &[Data], src: Src) -> Data {
    match src {
        Src::Slot(s) => values[s],
        Src::Const(d) => d,
    }
}

/// `d` negated when `neg`: a BOOL inverted, an integer's bits inverted.
fn negate(d: Data, neg: bool) -> Data {
    if neg {
        d.invert().unwrap_or(d)
    } else {
        d
    }
}

/// `a OP b` (types checked at load: a mismatch cannot reach here, and
/// gives FALSE if it did).
fn apply(op: Binary, a: Data, b: Data) -> Data {
    let result = match op {
        Binary::Logic(bitwise, neg) => a.bitwise(bitwise, negate(b, neg)),
        Binary::Arith(arith) => a.arith(arith, b),
        Binary::Cmp(cmp) => Some(Data::Bool(a.compare(b).is_some_and(|o| match cmp {
            Cmp::Gt => o == Ordering::Greater,
            Cmp::Ge => o != Ordering::Less,
            Cmp::Eq => o == Ordering::Equal,
            Cmp::Ne => o != Ordering::Equal,
            Cmp::Le => o != Ordering::Greater,
            Cmp::Lt => o == Ordering::Less,
        }))),
    };
    result.unwrap_or(Data::Bool(false))
}

/// A function of the current result `cr` and `args` (types checked at
/// load; a mismatch cannot reach here and leaves `cr` as it was).
fn function(f: Function, cr: Data, args: &[Data]) -> Data {
    let count = |d: &Data| match d.convert(DataType::Udint) {
        Data::Int(_, n) => u32::try_from(n).unwrap_or(u32::MAX),
        _ => 0,
    };
    let shift = |op| args.first().and_then(|n| cr.shift(op, count(n)));
    let result = match f {
        Function::Neg => cr.negate(),
        Function::Move => Some(cr),
        Function::Shl => shift(Shift::Shl),
        Function::Shr => shift(Shift::Shr),
        Function::Rol => shift(Shift::Rol),
        Function::Ror => shift(Shift::Ror),
        Function::Min => args.first().and_then(|&b| data::min(cr, b)),
        Function::Max => args.first().and_then(|&b| data::max(cr, b)),
        Function::Limit => match args {
            [input, mx] => data::limit(cr, *input, *mx),
            _ => None,
        },
        Function::Sel => match args {
            [in0, in1] => Some(data::select(cr == Data::Bool(true), *in0, *in1)),
            _ => None,
        },
        Function::Convert { to, .. } => Some(cr.convert(to)),
    };
    result.unwrap_or(cr)
}
