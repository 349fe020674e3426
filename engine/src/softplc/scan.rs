//! A loaded program's scan and its I/O: the input terminals are read at
//! the scan's start, the steps run top to bottom (jumps as written), the
//! outputs are what the `%Q` variables hold at its end. A scan can also be
//! run one instruction at a time ([`Cursor`]), as the page's step button
//! and the tracer need.

use super::program::{Binary, Named, Program, Src, Step, STEPS_PER_SCAN};
use crate::iec::address::{Address, Area};
use crate::iec::data::DataType;
use crate::iec::data::{self, Data, Shift};
use crate::iec::il::Function;
use crate::plc::Tracer;
use crate::runtime::instance::Instance;

/// Where a scan under way stands: the next step, the current result, the
/// deferred `(` operations and how many steps it has run.
#[derive(Clone, Debug, PartialEq)]
pub struct Cursor {
    pc: usize,
    cr: Data,
    open: Vec<(Binary, Data)>,
    ran: usize,
    /// The calls of the program's own blocks under way.
    frames: Vec<Frame>,
}

/// Where a call of one of the program's own blocks returns to: the
/// step after it, the caller's current result and `(` depth, and the
/// call's own step (for its outputs).
#[derive(Clone, Debug, PartialEq)]
struct Frame {
    ret: usize,
    cr: Data,
    open: usize,
    call: usize,
}

impl Default for Cursor {
    fn default() -> Self {
        Cursor {
            pc: 0,
            cr: Data::Bool(false),
            open: Vec::new(),
            ran: 0,
            frames: Vec::new(),
        }
    }
}

impl Cursor {
    /// The next step's number.
    pub fn position(&self) -> usize {
        self.pc
    }
}

impl Program {
    /// Runs one whole scan at simulated time `now` (ns).
    pub fn scan(&mut self, now: i64) {
        let mut cursor = Cursor::default();
        let mut tracer = Tracer::default();
        self.begin_scan(&mut cursor);
        while self.execute(&mut cursor, now, &mut tracer) {}
    }

    /// Starts a scan: the input terminals copied in, the cursor at the
    /// first step (its buffer kept).
    pub fn begin_scan(&mut self, cursor: &mut Cursor) {
        for (slot, v) in &self.input_terminals {
            self.values[*slot] = v.clone();
        }
        cursor.pc = 0;
        cursor.cr = Data::Bool(false);
        cursor.open.clear();
        cursor.frames.clear();
        cursor.ran = 0;
        self.overran = false;
        self.fault = None;
        self.uart.begin_scan();
    }

    /// Runs the step at the cursor (told to `tracer`: the bit it read and
    /// the current result it left); false once the scan is over (past the
    /// last step, a RET, or cut at [`STEPS_PER_SCAN`]).
    #[inline(always)]
    pub fn execute(&mut self, cursor: &mut Cursor, now: i64, tracer: &mut Tracer) -> bool {
        let Program {
            steps,
            values,
            blocks,
            overran,
            fault,
            entries,
            uart,
            ..
        } = self;
        let Some(step) = steps.get(cursor.pc) else {
            return false;
        };
        cursor.ran += 1;
        if cursor.ran > STEPS_PER_SCAN {
            *overran = true;
            return stop(&mut None, 0, cursor, steps.len());
        }
        let number = cursor.pc;
        cursor.pc += 1;
        let mut read_bit = false;
        let cr = &mut cursor.cr;
        match step {
            Step::Ld(src, neg) => {
                let v = peek(values, src);
                read_bit = v.is_on();
                *cr = negate(v.clone(), *neg);
            }
            Step::St(slot, neg) => values[*slot] = negate(cr.clone(), *neg),
            Step::LdAt(..) | Step::StAt(_) => match element(values, step, cr) {
                Some(bit) => read_bit = bit,
                None => return stop(fault, number, cursor, steps.len()),
            },
            Step::Set(slot) if *cr == Data::Bool(true) => values[*slot] = Data::Bool(true),
            Step::Reset(slot) if *cr == Data::Bool(true) => values[*slot] = Data::Bool(false),
            Step::Set(_) | Step::Reset(_) => {}
            Step::Not => *cr = negate(std::mem::replace(cr, Data::Bool(false)), true),
            Step::Binary(op, src) => {
                let v = peek(values, src);
                read_bit = v.is_on();
                *cr = apply(*op, cr, v);
            }
            Step::Open(op, src) => {
                cursor.open.push((*op, cr.clone()));
                if let Some(src) = src {
                    let v = read(values, src);
                    read_bit = v.is_on();
                    *cr = v;
                }
            }
            Step::Close => {
                if let Some((op, saved)) = cursor.open.pop() {
                    *cr = apply(op, &saved, cr);
                }
            }
            Step::Func(f, args) => *cr = call_function(values, *f, cr, args),
            // A condition not met: the step does nothing.
            Step::Jmp(when, _)
            | Step::Ret(when)
            | Step::CallUser { when, .. }
            | Step::Cal { when, .. }
                if !on(*when, cr) => {}
            Step::Jmp(_, target) => cursor.pc = *target,
            Step::Ret(_) | Step::Return => {
                let c = (&mut cursor.frames, &mut cursor.open, &mut cursor.pc);
                give_back(c, cr, steps, values);
            }
            Step::CallUser {
                instance, inputs, ..
            } => {
                let entry = entries.get(*instance).copied().unwrap_or(steps.len());
                let c = (&mut cursor.frames, &mut cursor.open, &mut cursor.pc);
                enter(c, cr, values, inputs, number, entry);
            }
            call @ Step::Cal { .. } => call_block(values, (blocks, uart), call, now),
        }
        tracer.step(number, read_bit, cr.is_on());
        cursor.pc < steps.len()
    }

    /// Sets what an input's terminal gives (read at the next scan's
    /// start); `false` when the program has no such input or the value's
    /// type is not the input's.
    pub fn set_input(&mut self, address: Address, value: Data) -> bool {
        if address.area != Area::Input {
            return false;
        }
        match self.by_address.get(&address) {
            Some(&slot) => self.set_terminal(slot, value),
            None => false,
        }
    }

    /// The value of a declared name (any case) or an address the program
    /// uses.
    pub fn value(&self, name_or_address: &str) -> Option<Data> {
        self.values.get(self.slot_of(name_or_address)?).cloned()
    }

    /// The slot of a declared name (any case) or an address the program
    /// uses.
    pub fn slot_of(&self, name_or_address: &str) -> Option<usize> {
        match Address::parse(name_or_address) {
            Ok(a) => self.by_address.get(&a).copied(),
            // `a[1, 2]` as `A[1,2]`: an element's name has no spaces.
            Err(_) => match self
                .by_name
                .get(&name_or_address.replace(' ', "").to_ascii_uppercase())
            {
                Some(Named::Slot(s)) => Some(*s),
                _ => None,
            },
        }
    }

    /// How many value slots the program has.
    pub fn slots(&self) -> usize {
        self.values.len()
    }

    /// The type slot `slot` holds.
    pub fn slot_type(&self, slot: usize) -> Option<DataType> {
        self.values.get(slot).map(|v| v.data_type())
    }

    /// The address at slot `slot`, if it is located.
    pub fn slot_address(&self, slot: usize) -> Option<Address> {
        self.addresses
            .iter()
            .find(|(_, s)| *s == slot)
            .map(|&(a, _)| a)
    }

    /// Sets the terminal of the input at slot `slot`; false when it is
    /// not an input or `value` is not of its type.
    pub fn set_terminal(&mut self, slot: usize, value: Data) -> bool {
        match self.input_terminals.iter_mut().find(|(s, _)| *s == slot) {
            Some(t) if t.1.data_type() == value.data_type() => {
                t.1 = value;
                true
            }
            _ => false,
        }
    }

    /// Whether slot `slot` is an input read from its terminal.
    pub fn is_terminal(&self, slot: usize) -> bool {
        self.input_terminals.iter().any(|(s, _)| *s == slot)
    }

    /// Each input's address and what its terminal gives.
    pub fn input_values(&self) -> Vec<(Address, Data)> {
        self.input_terminals
            .iter()
            .filter_map(|(slot, v)| Some((self.slot_address(*slot)?, v.clone())))
            .collect()
    }

    /// A block instance by name (any case): its number and kind.
    pub fn block_of(&self, name: &str) -> Option<(usize, &str)> {
        match self.by_name.get(&name.to_ascii_uppercase()) {
            Some(&Named::Block(i)) => Some((i, self.block_names[i].1.as_str())),
            _ => None,
        }
    }

    /// How many block instances it has.
    pub fn block_count(&self) -> usize {
        self.blocks.len()
    }

    /// Output `pin` (its place in the kind's outputs) of block `block`.
    pub fn block_output(&self, block: usize, pin: usize) -> Option<Data> {
        let b = self.blocks.get(block)?;
        (pin < crate::iec::pins::outputs(&self.block_names[block].1).len()).then(|| b.output(pin))
    }

    /// Every declared variable's and used address's name with its slot:
    /// names first (as declared), then undeclared addresses.
    pub fn devices(&self) -> Vec<(String, usize)> {
        let mut out: Vec<(String, usize)> = self.names.clone();
        let named: std::collections::HashSet<usize> = self.names.iter().map(|&(_, s)| s).collect();
        for &(a, slot) in &self.addresses {
            if !named.contains(&slot) {
                out.push((a.to_string(), slot));
            }
        }
        out
    }

    /// The addresses the program uses, in their order of first use.
    pub fn io(&self) -> impl Iterator<Item = Address> + '_ {
        self.addresses.iter().map(|&(a, _)| a)
    }

    /// The step whose array index was outside its array in the last
    /// scan, which stopped there (`source_line` names its ST line).
    pub fn fault(&self) -> Option<usize> {
        self.fault
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
                *v = self.initial[slot].clone();
            }
        }
        for (b, (_, kind)) in self.blocks.iter_mut().zip(&self.block_names) {
            let (format, printing) = (b.format.take(), b.printing.take());
            *b = Instance::new(kind);
            (b.format, b.printing) = (format, printing);
        }
        self.uart.power_cycle();
    }
}

/// Whether a step conditional on `when` (C: TRUE, CN: FALSE, none:
/// always) runs with current result `cr`.
#[inline(always)]
fn on(when: Option<bool>, cr: &Data) -> bool {
    when.is_none_or(|w| *cr == Data::Bool(w))
}

/// A call of an instance of the program's own blocks: its inputs copied
/// in, the caller's place kept, the body's first step next.
#[inline(always)]
fn enter(
    (frames, open, pc): (&mut Vec<Frame>, &mut Vec<(Binary, Data)>, &mut usize),
    cr: &mut Data,
    values: &mut [Data],
    inputs: &[(usize, Src)],
    call: usize,
    entry: usize,
) {
    for (slot, src) in inputs {
        values[*slot] = read(values, src);
    }
    frames.push(Frame {
        ret: *pc,
        cr: cr.clone(),
        open: open.len(),
        call,
    });
    *pc = entry;
    *cr = Data::Bool(false);
}

/// The end of a body: back to the caller with its current result, the
/// call's outputs copied out; in the program, the end of the scan.
fn give_back(
    (frames, open, pc): (&mut Vec<Frame>, &mut Vec<(Binary, Data)>, &mut usize),
    cr: &mut Data,
    steps: &[Step],
    values: &mut [Data],
) {
    let Some(frame) = frames.pop() else {
        *pc = steps.len();
        return;
    };
    open.truncate(frame.open);
    *cr = frame.cr;
    *pc = frame.ret;
    if let Some(Step::CallUser { outputs, .. }) = steps.get(frame.call) {
        for &(to, from) in outputs {
            values[to] = values[from].clone();
        }
    }
}

/// Function `f` of the current result `cr` and the operands `args` (at
/// most two: read without allocating).
#[inline(always)]
fn call_function(values: &[Data], f: Function, cr: &Data, args: &[Src]) -> Data {
    if f == Function::Mux {
        // Any number of inputs: only the one K picks is read. K outside
        // 0 … n-1 takes the nearest input (decided; IEC calls it an error).
        let last = args.len().saturating_sub(1) as i128;
        let k = cr.int().unwrap_or(0).clamp(0, last) as usize;
        return args.get(k).map_or_else(|| cr.clone(), |a| read(values, a));
    }
    let mut operands = [Data::Bool(false), Data::Bool(false)];
    for (v, a) in operands.iter_mut().zip(args) {
        *v = read(values, a);
    }
    function(f, cr, &operands[..args.len().min(2)])
}

/// Runs a `CAL` step: its block instance called with its inputs, its
/// outputs copied.
fn call_block(
    values: &mut [Data],
    (blocks, uart): (&mut [Instance], &mut crate::runtime::uart::Uart),
    call: &Step,
    now: i64,
) {
    let Step::Cal {
        block,
        inputs,
        outputs,
        ..
    } = call
    else {
        return;
    };
    let Some(instance) = blocks.get_mut(*block) else {
        return;
    };
    for (i, src) in inputs {
        if let Some(slot) = instance.inputs.get_mut(*i) {
            *slot = read(values, src);
        }
    }
    instance.call(now, uart);
    for &(i, slot) in outputs {
        values[slot] = instance.output(i);
    }
}

/// What `src` holds: a value of the table, or a constant.
#[inline(always)]
fn peek<'a>(values: &'a [Data], src: &'a Src) -> &'a Data {
    match src {
        Src::Slot(s) => &values[*s],
        Src::Const(d) => d,
    }
}

/// An element's LD or ST: the bit it read, or `None` when an index is
/// outside its array (the scan stops there). Not inlined: inlined, the
/// scan's other steps cost 2.3 % more instructions (callgrind,
/// bench-256); out of line, 0.9 % (docs/performance.md).
#[inline(never)]
fn element(values: &mut [Data], step: &Step, cr: &mut Data) -> Option<bool> {
    match step {
        Step::LdAt(at, neg) => {
            let v = &values[at.slot(values)?];
            *cr = negate(v.clone(), *neg);
            Some(v.is_on())
        }
        Step::StAt(at) => {
            let s = at.slot(values)?;
            values[s] = cr.clone();
            Some(false)
        }
        _ => Some(false),
    }
}

/// The scan stopped at step `number` (`fault`: an index outside its
/// array; cut at [`STEPS_PER_SCAN`], the caller's flag says).
#[cold]
fn stop(fault: &mut Option<usize>, number: usize, cursor: &mut Cursor, end: usize) -> bool {
    *fault = Some(number);
    cursor.pc = end;
    false
}

/// A copy of what `src` holds.
#[inline(always)]
fn read(values: &[Data], src: &Src) -> Data {
    peek(values, src).clone()
}

/// `d` negated when `neg`: a BOOL inverted, an integer's bits inverted.
#[inline(always)]
fn negate(d: Data, neg: bool) -> Data {
    if neg {
        d.invert().unwrap_or(d)
    } else {
        d
    }
}

/// `a OP b` (types checked at load: a mismatch cannot reach here, and
/// gives FALSE if it did).
#[inline(always)]
fn apply(op: Binary, a: &Data, b: &Data) -> Data {
    let result = match op {
        Binary::Logic(bitwise, false) => a.bitwise(bitwise, b),
        Binary::Logic(bitwise, true) => a.bitwise(bitwise, &negate(b.clone(), true)),
        Binary::Arith(arith) => a.arith(arith, b),
        Binary::Cmp(cmp) => Some(Data::Bool(a.compare(b).is_some_and(|o| cmp.holds(o)))),
    };
    result.unwrap_or(Data::Bool(false))
}

/// A function of the current result `cr` and `args` (types checked at
/// load; a mismatch cannot reach here and leaves `cr` as it was).
fn function(f: Function, cr: &Data, args: &[Data]) -> Data {
    let shift = |op| args.first().and_then(|n| cr.shift(op, n));
    let result = match f {
        Function::Neg => cr.negate(),
        Function::Move => Some(cr.clone()),
        Function::Shl => shift(Shift::Shl),
        Function::Shr => shift(Shift::Shr),
        Function::Rol => shift(Shift::Rol),
        Function::Ror => shift(Shift::Ror),
        Function::Min => args.first().and_then(|b| data::min(cr, b)),
        Function::Max => args.first().and_then(|b| data::max(cr, b)),
        Function::Limit => match args {
            [input, mx] => data::limit(cr, input, mx),
            _ => None,
        },
        Function::Sel => match args {
            [in0, in1] => Some(data::select(*cr == Data::Bool(true), in0, in1)),
            _ => None,
        },
        Function::Convert { to, .. } => Some(cr.convert(to)),
        Function::Abs => cr.abs(),
        Function::Sqrt => match *cr {
            Data::Lreal(r) => Some(Data::Lreal(r.sqrt())),
            _ => cr.real().map(|r| Data::Real(r.sqrt())),
        },
        // Toward zero, saturating at DINT's limits (NaN gives 0).
        Function::Trunc => match *cr {
            Data::Lreal(r) => Some(Data::integer(DataType::Dint, (r as i32).into())),
            _ => cr
                .real()
                .map(|r| Data::integer(DataType::Dint, (r as i32).into())),
        },
        Function::Expt => args.first().and_then(|e| cr.expt(e)),
        // Read by `call_function`, which sees all its inputs.
        Function::Mux => None,
    };
    result.unwrap_or_else(|| cr.clone())
}
