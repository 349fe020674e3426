//! The reference evaluator's word data (issue #30): the soft PLC's boxes
//! run by the book on typed values, with the meaning `ladder::block`
//! states. It shares the soft PLC's arithmetic (`iec::data`, tested
//! on its own) and block state machines (`runtime`), not its compiler
//! or its IL:
//! what the differential tests compare is the compiled program against
//! this.

use std::cmp::Ordering;
use std::collections::HashMap;

use crate::iec::data::{self, Arith, Bitwise, Data, DataType, Shift};
use crate::iec::pins;
use crate::iec::{literal_type, parse_literal, Address};
use crate::ladder::block::{BlockCall, Shape};
use crate::ladder::variables::Variable;
use crate::runtime::instance::Instance;

/// Typed values by name (upper-case; a located variable also by its
/// address) and block instances; BOOLs live in the evaluator's bits.
#[derive(Clone, Debug, Default)]
pub(super) struct Words {
    /// Every declared name and address: its type and, for a word, its
    /// value (a BOOL's value is its bit).
    values: HashMap<String, Data>,
    /// Located names: the address (as IEC writes it) → the name.
    located: HashMap<String, String>,
    instances: HashMap<String, Instance>,
    /// Block instance kinds declared.
    kinds: HashMap<String, String>,
    /// The serial port of LDmicro's UART blocks (nothing is typed at it
    /// here: the evaluator checks the ladder's logic).
    uart: crate::runtime::uart::Uart,
}

/// Where a box's BOOLs are: the evaluator's bits by name.
pub(super) trait Bits {
    fn get_bit(&mut self, name: &str) -> bool;
    fn set_bit(&mut self, name: &str, on: bool);
}

impl Words {
    /// The ladder's declared variables at their start values.
    pub fn new(variables: &[Variable]) -> Words {
        let mut w = Words::default();
        for v in variables {
            let upper = v.name.to_ascii_uppercase();
            match v.elementary() {
                Some(t) => {
                    let init = parse_literal(&v.initial, Some(t)).unwrap_or(t.zero());
                    w.values.insert(upper.clone(), init);
                    if let Ok(a) = Address::parse(&v.address) {
                        w.located.insert(a.to_string(), upper);
                    }
                }
                None => {
                    w.kinds
                        .insert(upper, v.data_type.trim().to_ascii_uppercase());
                }
            }
        }
        w
    }

    /// The storage key and type of a name or address.
    fn key(&self, text: &str) -> Option<(String, DataType)> {
        let text = text.trim();
        let key = if text.starts_with('%') {
            let a = Address::parse(text).ok()?;
            match self.located.get(&a.to_string()) {
                Some(name) => name.clone(),
                None => return Some((a.to_string(), a.default_type()?)),
            }
        } else {
            text.to_ascii_uppercase()
        };
        let t = self.values.get(&key)?.data_type();
        Some((key, t))
    }

    /// A block instance's output read as an operand (`c0.CV`, `t0.Q`):
    /// its value now (an instance not called yet gives its first).
    fn output_of(&self, text: &str) -> Option<Data> {
        let (instance, pin) = text.trim().split_once('.')?;
        let upper = instance.to_ascii_uppercase();
        let kind = self.kinds.get(&upper)?;
        let i = pins::outputs(kind)
            .iter()
            .position(|(p, _)| p.eq_ignore_ascii_case(pin))?;
        Some(match self.instances.get(&upper) {
            Some(x) => x.output(i),
            None => Instance::new(kind).output(i),
        })
    }

    /// The spelling the bits use for a BOOL name (as written).
    fn read(&mut self, text: &str, want: Option<DataType>, bits: &mut dyn Bits) -> Option<Data> {
        if let Some(d) = self.output_of(text) {
            return Some(d);
        }
        match self.key(text) {
            Some((_, DataType::Bool)) => Some(Data::Bool(bits.get_bit(text.trim()))),
            Some((key, t)) => Some(self.values.entry(key).or_insert_with(|| t.zero()).clone()),
            None => {
                let (d, fixed) = literal_type(text).ok()?;
                if fixed.is_some() {
                    return Some(d);
                }
                match want {
                    Some(DataType::Bool) => Some(Data::Bool(d.is_on())),
                    Some(t) if t.bits().is_some() => Some(d.convert(t)),
                    Some(DataType::Real) => Some(d.convert(DataType::Real)),
                    _ => Some(d),
                }
            }
        }
    }

    fn write(&mut self, text: &str, value: Data, bits: &mut dyn Bits) {
        match self.key(text) {
            Some((_, DataType::Bool)) => bits.set_bit(text.trim(), value.is_on()),
            Some((key, _)) => {
                self.values.insert(key, value);
            }
            None => bits.set_bit(text.trim(), value.is_on()),
        }
    }

    /// Sets a variable or address from outside (a test's input).
    pub fn set(&mut self, text: &str, value: Data) {
        if let Some((key, _)) = self.key(text) {
            self.values.insert(key, value);
        }
    }

    /// A word's value, if `text` names one.
    pub fn get(&self, text: &str) -> Option<Data> {
        let (key, _) = self.key(text)?;
        self.values.get(&key).cloned()
    }

    /// Box `b` with power `power` at time `now` (ns): its power out.
    pub fn run(&mut self, b: &BlockCall, power: bool, now: i64, bits: &mut dyn Bits) -> bool {
        let kind = b.kind();
        match b.shape() {
            Some(Shape::FunctionBlock) => self.function_block(b, &kind, power, now, bits),
            Some(Shape::Compare) => {
                let args = self.args(b, bits);
                let holds = match args.as_slice() {
                    [x, y] => x.compare(y).is_some_and(|o| compare(&kind, o)),
                    _ => false,
                };
                power && holds
            }
            Some(Shape::Function(..)) => {
                if power {
                    let args = self.args(b, bits);
                    if let Some(result) = function(&kind, &args) {
                        for (_, v) in &b.outputs {
                            self.write(v, result.clone(), bits);
                        }
                    }
                }
                power
            }
            None => false,
        }
    }

    /// A function's or comparison's data inputs, typed as the soft PLC
    /// types them: the first typed operand's type, literals taking it.
    fn args(&mut self, b: &BlockCall, bits: &mut dyn Bits) -> Vec<Data> {
        let pins = b.data_pins();
        // SEL's G and a shift's N do not share the type.
        let shared = |pin: &str| !matches!(pin, "G" | "N");
        let mut ty = None;
        for pin in pins.iter().filter(|p| shared(p)) {
            if let Some(text) = b.input(pin) {
                if let Some(t) = self
                    .key(text)
                    .map(|(_, t)| t)
                    .or_else(|| Some(self.output_of(text)?.data_type()))
                {
                    ty = Some(t);
                    break;
                }
                if let Ok((_, Some(t))) = literal_type(text) {
                    ty = Some(t);
                    break;
                }
            }
        }
        if ty.is_none() {
            ty = b
                .outputs
                .first()
                .and_then(|(_, v)| self.key(v))
                .map(|(_, t)| t);
        }
        let ty = ty.or(Some(DataType::Dint));
        pins.iter()
            .map(|pin| {
                let want = if shared(pin) {
                    ty
                } else if pin == "G" {
                    Some(DataType::Bool)
                } else {
                    None
                };
                b.input(pin)
                    .and_then(|t| self.read(t, want, bits))
                    .unwrap_or(Data::Bool(false))
            })
            .collect()
    }

    fn function_block(
        &mut self,
        b: &BlockCall,
        kind: &str,
        power: bool,
        now: i64,
        bits: &mut dyn Bits,
    ) -> bool {
        if !pins::is_block_type(kind) {
            // The project's own ST block: only the soft PLC runs it.
            return false;
        }
        let upper = b.instance.to_ascii_uppercase();
        let ins = pins::inputs(kind);
        let mut given = vec![Some(Data::Bool(power))];
        for (pin, t) in ins.iter().skip(1) {
            given.push(
                b.input(pin)
                    .and_then(|text| self.read(text, Some(*t), bits)),
            );
        }
        // Its outputs may be read as operands (`c0.CV`).
        self.kinds
            .entry(upper.clone())
            .or_insert_with(|| kind.to_string());
        let instance = self
            .instances
            .entry(upper)
            .or_insert_with(|| Instance::new(kind));
        for (slot, value) in instance.inputs.iter_mut().zip(given) {
            if let Some(v) = value {
                *slot = v;
            }
        }
        instance.call(now, &mut self.uart);
        let outs = pins::outputs(kind);
        let values: Vec<(String, Data)> = b
            .outputs
            .iter()
            .filter_map(|(pin, v)| {
                let i = outs.iter().position(|(p, _)| p.eq_ignore_ascii_case(pin))?;
                Some((v.clone(), instance.output(i)))
            })
            .collect();
        let out = instance.output(0).is_on();
        for (v, d) in values {
            self.write(&v, d, bits);
        }
        out
    }
}

fn compare(kind: &str, o: Ordering) -> bool {
    match kind {
        "GT" => o == Ordering::Greater,
        "GE" => o != Ordering::Less,
        "EQ" => o == Ordering::Equal,
        "NE" => o != Ordering::Equal,
        "LE" => o != Ordering::Greater,
        _ => o == Ordering::Less,
    }
}

/// A function of its data inputs (in order), as IEC defines it.
fn function(kind: &str, args: &[Data]) -> Option<Data> {
    let fold = |f: &dyn Fn(&Data, &Data) -> Option<Data>| {
        let (first, rest) = args.split_first()?;
        rest.iter().try_fold(first.clone(), |acc, x| f(&acc, x))
    };
    let arith = |op| fold(&|a: &Data, b| a.arith(op, b));
    let logic = |op| fold(&|a: &Data, b| a.bitwise(op, b));
    let shift = |op| args.first()?.shift(op, args.get(1)?);
    match kind {
        "ADD" => arith(Arith::Add),
        "SUB" => arith(Arith::Sub),
        "MUL" => arith(Arith::Mul),
        "DIV" => arith(Arith::Div),
        "MOD" => arith(Arith::Mod),
        "AND" => logic(Bitwise::And),
        "OR" => logic(Bitwise::Or),
        "XOR" => logic(Bitwise::Xor),
        "MAX" => fold(&data::max),
        "MIN" => fold(&data::min),
        "NOT" => args.first()?.invert(),
        "NEG" => args.first()?.negate(),
        "MOVE" => args.first().cloned(),
        "SEL" => match args {
            [g, a, b] => Some(data::select(g.is_on(), a, b)),
            _ => None,
        },
        "LIMIT" => match args {
            [mn, x, mx] => data::limit(mn, x, mx),
            _ => None,
        },
        "SHL" => shift(Shift::Shl),
        "SHR" => shift(Shift::Shr),
        "ROL" => shift(Shift::Rol),
        "ROR" => shift(Shift::Ror),
        _ => {
            let (_, to) = kind.split_once("_TO_")?;
            Some(args.first()?.convert(DataType::from_name(to)?))
        }
    }
}
