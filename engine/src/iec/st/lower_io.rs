//! A POU's variables and a block's call, lowered, with VAR_IN_OUT: IL
//! has no reference, so an in-out parameter is **copied in and out**: the
//! block takes it as an input and gives it back as a hidden output
//! (`st_io_x`), written when its body ends (a `RETURN` too), and each call
//! passes the variable both ways (`CAL b(x := v, st_io_x => v)`). What
//! the body computes is what IEC's reference gives, unless the block
//! also reaches the same variable another way (a global) within the call.

use super::ast::{Arg, Expr, ExprKind, Item, Pou, PouKind, Source, Span, VarBlock, VarKind};
use super::error::StErrorKind;
use super::lower::Lower;
use super::types::at;

/// The hidden output an in-out parameter `pin` is copied out by (a
/// PLCopen block's external too, so that an ST call's arguments reach it).
pub(crate) fn io_pin(pin: &str) -> String {
    format!("st_io_{pin}")
}

fn in_out_names(p: &Pou) -> Vec<String> {
    p.vars
        .iter()
        .filter(|b| b.kind == VarKind::InOut || copied_external(p, b))
        .flat_map(|b| &b.decls)
        .flat_map(|d| d.names.iter().map(|n| n.name.clone()))
        .collect()
}

/// Whether `b` is a block's or function's VAR_EXTERNAL that is copied
/// out as an in-out parameter is (not a CONSTANT one: only read).
fn copied_external(p: &Pou, b: &VarBlock) -> bool {
    b.kind == VarKind::External && !b.constant && p.kind != PouKind::Program
}

/// A block's or function's VAR_EXTERNAL names, each with whether it is
/// copied back out.
fn external_names(p: &Pou) -> Vec<(String, bool)> {
    if p.kind == PouKind::Program {
        return Vec::new();
    }
    p.vars
        .iter()
        .filter(|b| b.kind == VarKind::External)
        .flat_map(|b| b.decls.iter().map(move |d| (d, !b.constant)))
        .flat_map(|(d, out)| d.names.iter().map(move |n| (n.name.clone(), out)))
        .collect()
}

impl Lower {
    /// Learns every own POU's VAR_IN_OUT parameters (`inouts`).
    pub(super) fn know_in_outs(&mut self, source: &Source) {
        for item in &source.items {
            let Item::Pou(p) = item else { continue };
            let externals = external_names(p);
            for n in in_out_names(p) {
                // A VAR_EXTERNAL is no argument a call gives.
                if externals.iter().any(|(e, _)| *e == n) {
                    continue;
                }
                let key = (p.name.name.to_ascii_uppercase(), n.to_ascii_uppercase());
                self.inouts.insert(key);
            }
            if !externals.is_empty() {
                self.externals
                    .insert(p.name.name.to_ascii_uppercase(), externals);
            }
        }
    }

    /// A POU's variable block as the IL's.
    pub(super) fn block(&mut self, b: &VarBlock) {
        let keyword = match (b.kind, b.retain) {
            (VarKind::Local, true) => "VAR_RETAIN",
            (VarKind::Local, false) => "VAR",
            (VarKind::Temp, _) => "VAR_TEMP",
            (VarKind::Input, _) => "VAR_INPUT",
            (VarKind::Output, _) => "VAR_OUTPUT",
            // Copied in as an input, out as a hidden output (`io_pin`).
            (VarKind::InOut, _) => "VAR_INPUT",
            // The PROGRAM declares the globals it reaches (`global_blocks`).
            (VarKind::External, _) if self.in_program => return,
            // A block's: the global copied in, and out as an in-out is.
            (VarKind::External, _) => "VAR_INPUT",
            (other, _) => return self.not_yet(b.span, other.keyword()),
        };
        self.emit(keyword, b.span);
        for d in &b.decls {
            let local = matches!(b.kind, VarKind::Local | VarKind::Temp);
            if self.flat_decl(d, local) {
                continue;
            }
            let (ty, init) = self.plain(d);
            let at = d
                .location
                .as_ref()
                .map(|a| format!(" AT {a}"))
                .unwrap_or_default();
            let init = init.map(|i| format!(" := {i}")).unwrap_or_default();
            for n in &d.names {
                self.emit(format!("  {}{at} : {ty}{init};", n.name), n.span);
            }
        }
        self.emit("END_VAR", b.span);
        let external = b.kind == VarKind::External && !b.constant;
        if b.kind == VarKind::InOut || external {
            self.emit("VAR_OUTPUT", b.span);
            for d in &b.decls {
                let ty = super::print::type_text(&d.ty);
                for n in &d.names {
                    self.emit(format!("  {} : {ty};", io_pin(&n.name)), n.span);
                }
            }
            self.emit("END_VAR", b.span);
        }
    }

    /// The source's `VAR_GLOBAL`s declared as the PROGRAM `p`'s own
    /// variables (`RETAIN` kept), but a name `p` declares itself, which
    /// shadows the global there.
    pub(super) fn global_blocks(&mut self, p: &Pou) {
        // Several programs are one IL program: declared with the first.
        if std::mem::replace(&mut self.globals_declared, true) {
            return;
        }
        let own: std::collections::HashSet<String> = p
            .vars
            .iter()
            .filter(|b| b.kind != VarKind::External)
            .flat_map(|b| &b.decls)
            .flat_map(|d| &d.names)
            .map(|n| n.name.to_ascii_uppercase())
            .collect();
        for g in std::mem::take(&mut self.globals) {
            let mut local = g.clone();
            local.kind = VarKind::Local;
            for d in &mut local.decls {
                d.names
                    .retain(|n| !own.contains(&n.name.to_ascii_uppercase()));
            }
            local.decls.retain(|d| !d.names.is_empty());
            self.block(&local);
            self.globals.push(g);
        }
    }

    /// A POU's body, then its in-out parameters copied out (where its
    /// `RETURN`s go too).
    pub(super) fn body_with_io(&mut self, p: &Pou) {
        let names = in_out_names(p);
        if names.is_empty() {
            return self.body(p);
        }
        if p.kind == PouKind::Program && p.vars.iter().any(|b| b.kind == VarKind::InOut) {
            // No caller gives a program its variable.
            let at = p.vars.iter().find(|b| b.kind == VarKind::InOut);
            self.not_yet(at.map_or(p.span, |b| b.span), "VAR_IN_OUT in a PROGRAM");
        }
        let end = self.label();
        self.ret = Some(end.clone());
        self.body(p);
        self.ret = None;
        self.place(&end, p.span);
        for n in names {
            self.emit(format!("LD {n}"), p.span);
            self.emit(format!("ST {}", io_pin(&n)), p.span);
        }
    }

    /// `RETURN`: the end of the scan or call, or the copy-out first.
    pub(super) fn return_stmt(&mut self, span: Span) {
        match self.ret.clone() {
            Some(end) => self.emit(format!("JMP {end}"), span),
            None => self.emit("RET", span),
        }
    }

    /// The arguments for `pin := e` when `pin` is an in-out parameter of
    /// own POU `callee` (upper-case): the variable both ways. `None` when
    /// it is not one.
    pub(super) fn in_out(&mut self, callee: &str, pin: &str, e: &Expr) -> Option<Vec<String>> {
        let key = (callee.to_ascii_uppercase(), pin.to_ascii_uppercase());
        if !self.inouts.contains(&key) {
            return None;
        }
        match (&e.kind, self.simple(e)) {
            (ExprKind::Variable(_), Some(v)) => Some(vec![
                format!("{pin} := {v}"),
                format!("{} => {v}", io_pin(pin)),
            ]),
            _ => {
                let kind = StErrorKind::InOutArgument(pin.to_string());
                self.errors.push(at(e.span, kind));
                Some(Vec::new())
            }
        }
    }

    /// `t0(IN := x, PT := T#1s, Q => y)`: a block instance's CAL; an
    /// input by position goes to the block's inputs in order, an output
    /// negated (`NOT Q => y`) is read inverted after the call.
    pub(super) fn block_call(&mut self, call: &super::ast::Call, span: Span) {
        let ty = self.instances.get(&call.callee.name.to_ascii_uppercase());
        let ty = ty.cloned().unwrap_or_default();
        let (mut args, mut after, mut position) = (Vec::new(), Vec::new(), 0);
        for a in &call.args {
            match a {
                Arg::Input(name, e) => self.block_input(&ty, &name.name, e, &mut args),
                Arg::Positional(e) => {
                    match self.pin_at(&ty, position) {
                        Some(pin) => self.block_input(&ty, &pin, e, &mut args),
                        None => self.not_yet(e.span, "a block's input by position"),
                    }
                    position += 1;
                }
                Arg::Output {
                    name,
                    negated,
                    target,
                } => {
                    let to = match self.leaf(target) {
                        Some(leaf) => leaf,
                        None if target.path.is_empty() => target.base.name.clone(),
                        None => {
                            self.not_yet(name.span, "a negated output or one to a member");
                            continue;
                        }
                    };
                    if *negated {
                        after.push((format!("{}.{}", call.callee.name, name.name), to));
                    } else {
                        args.push(format!("{} => {to}", name.name));
                    }
                }
            }
        }
        args.extend(self.external_args(&ty));
        self.emit(
            format!("CAL {}({})", call.callee.name, args.join(", ")),
            span,
        );
        for (output, to) in after {
            self.emit(format!("LDN {output}"), span);
            self.emit(format!("ST {to}"), span);
        }
    }

    /// The globals a call of own POU `ty` passes both ways, for its
    /// VAR_EXTERNALs (`g := g, st_io_g => g`; a CONSTANT one only in),
    /// under the caller's name for them (the PROGRAM's global, or the
    /// calling block's own VAR_EXTERNAL).
    pub(super) fn external_args(&self, ty: &str) -> Vec<String> {
        let names = self.externals.get(&ty.to_ascii_uppercase());
        let mut args = Vec::new();
        for (n, out) in names.into_iter().flatten() {
            args.push(format!("{n} := {n}"));
            if *out {
                args.push(format!("{} => {n}", io_pin(n)));
            }
        }
        args
    }

    /// `pin := e` of a call of a block of type `ty` (upper-case).
    fn block_input(&mut self, ty: &str, pin: &str, e: &Expr, args: &mut Vec<String>) {
        if let Some(pair) = self.in_out(ty, pin, e) {
            return args.extend(pair);
        }
        match self.input(ty, pin, e, false) {
            Some(t) => args.push(format!("{pin} := {t}")),
            None => self.not_yet(e.span, "this block's input as an expression"),
        }
    }

    /// The name of the `k`th input of a block of type `ty`: the
    /// program's own block's in their order, a standard block's as the
    /// standard lists them (`TON`: IN, PT).
    fn pin_at(&self, ty: &str, k: usize) -> Option<String> {
        match self.blocks.get(&ty.to_ascii_uppercase()) {
            Some(pins) => pins.get(k).map(|(n, _)| n.clone()),
            None => crate::iec::pins::inputs(&ty.to_ascii_uppercase())
                .get(k)
                .map(|(n, _)| n.to_string()),
        }
    }
}
