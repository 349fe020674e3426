//! STRUCT and ARRAY variables lowered by **flattening**: each elementary
//! value inside one (`s.m`, `a[2]`, `arr[1].m[2]`) becomes a hidden IL
//! variable of its own (`st_v3`), declared in order, with its initial
//! value from the declaration, the `TYPE`'s default or the member's; an
//! element or member written with constant indices is that variable.
//! Each is also named as written for the front ends (`--watch a[2]`,
//! `s.m`): its declaration's comment says the name (`(* st: a[2] *)`),
//! which the soft PLC's loader takes as another name of it. An index
//! that is an integer variable is the soft PLC's element operand
//! ([`Lower::element`]); a constant one outside the array is refused at
//! load, naming the element.

use super::ast::{
    ArrayInit, Expr, ExprKind, Init, Literal, Selector, Span, TypeDef, TypeRef, UnaryOp, VarDecl,
    Variable,
};
use super::error::StErrorKind;
use super::lower::Lower;
use super::types::at;

/// The most elementary values one flattened variable may hold.
const MAX_LEAVES: usize = 4096;

/// One elementary value inside a variable: its path as written
/// (`a[1,2].m`), its IL type and its initial value's IL text.
struct Leaf {
    path: String,
    ty: String,
    init: Option<String>,
}

/// Why a variable's leaves were not listed.
enum Stop {
    /// Its type is no STRUCT, ARRAY or alias of one: declared as it is.
    NotComposite,
    /// More than [`MAX_LEAVES`] values.
    TooBig,
}

/// The key a path is found by: upper-case, no spaces.
pub(super) fn key(path: &str) -> String {
    path.chars()
        .filter(|c| !c.is_whitespace())
        .collect::<String>()
        .to_ascii_uppercase()
}

impl Lower {
    /// The `TYPE` declared as `name` (any case).
    pub(super) fn type_def(&self, name: &str) -> Option<&TypeDef> {
        self.types.get(&name.to_ascii_uppercase())
    }

    /// Whether `ty` holds more than one value (a STRUCT, an ARRAY, or an
    /// alias of one), so a variable of it is flattened.
    fn composite(&self, ty: &TypeRef, depth: usize) -> bool {
        match ty {
            TypeRef::Array { .. } => true,
            TypeRef::Named(n) if depth < 32 => match self.type_def(&n.name) {
                Some(TypeDef::Struct(_)) => true,
                Some(TypeDef::Alias(t, _)) => self.composite(t, depth + 1),
                None => false,
            },
            _ => false,
        }
    }

    /// `ty` with its aliases followed to an elementary or block type,
    /// with the alias's default value when the declaration gives none.
    pub(super) fn resolved<'a>(
        &'a self,
        ty: &'a TypeRef,
        init: Option<&'a Init>,
    ) -> (&'a TypeRef, Option<&'a Init>) {
        let (mut ty, mut init) = (ty, init);
        for _ in 0..32 {
            match ty {
                TypeRef::Named(n) => match self.type_def(&n.name) {
                    Some(TypeDef::Alias(t, d)) => {
                        init = init.or(d.as_ref());
                        ty = t;
                    }
                    _ => break,
                },
                _ => break,
            }
        }
        (ty, init)
    }

    /// Declares `d`'s names (in a `VAR` or `VAR_TEMP`, `local`): a
    /// STRUCT or ARRAY one as its leaves, each a hidden variable;
    /// `false` when `d` is no composite (declared as written).
    pub(super) fn flat_decl(&mut self, d: &VarDecl, local: bool) -> bool {
        if !self.composite(&d.ty, 0) {
            return false;
        }
        if !local {
            self.not_yet(d.span, "a STRUCT or ARRAY as a block's input or output");
            return true;
        }
        for n in &d.names {
            let mut leaves = Vec::new();
            match self.leaves(&d.ty, d.init.as_ref(), n.name.clone(), &mut leaves, 0) {
                Ok(()) => {}
                Err(Stop::TooBig) => {
                    let what = format!("a variable of more than {MAX_LEAVES} values");
                    self.not_yet(n.span, what);
                    continue;
                }
                Err(Stop::NotComposite) => continue,
            }
            for leaf in leaves {
                let hidden = self.fresh_leaf();
                let init = leaf.init.map(|i| format!(" := {i}")).unwrap_or_default();
                // The name as written rides in the IL (`st: a[1, 2]`),
                // so a front end loading this IL text finds it.
                let decl = format!("  {hidden} : {}{init}; (* st: {} *)", leaf.ty, leaf.path);
                self.emit(decl, n.span);
                self.flat.insert(key(&leaf.path), hidden.clone());
                self.order.insert(hidden.clone(), self.shown.len());
                self.shown.push(hidden);
            }
            self.flat_bases.insert(n.name.to_ascii_uppercase());
            self.flat_types
                .insert(n.name.to_ascii_uppercase(), d.ty.clone());
        }
        true
    }

    /// `d`'s type and initial value as IL text, an alias (`TYPE Count :
    /// DINT := 3`) followed to its type and default.
    pub(super) fn plain(&self, d: &VarDecl) -> (String, Option<String>) {
        let (ty, init) = self.resolved(&d.ty, d.init.as_ref());
        let init = init.map(super::print::init_text);
        (super::print::type_text(ty), init)
    }

    /// The IL types of `p`'s elementary variables (and, in the PROGRAM,
    /// the globals'), for `index_type`.
    pub(super) fn know_scalars(&mut self, p: &super::ast::Pou) {
        self.scalars.clear();
        self.indexed.clear();
        let globals = self.globals.clone();
        let own = globals.iter().filter(|_| self.in_program).chain(&p.vars);
        let decls: Vec<VarDecl> = own.flat_map(|b| b.decls.iter().cloned()).collect();
        for d in &decls {
            if self.composite(&d.ty, 0) {
                continue;
            }
            let (ty, _) = self.plain(d);
            for n in &d.names {
                self.scalars.insert(n.name.to_ascii_uppercase(), ty.clone());
            }
        }
    }

    /// A hidden leaf's name: none the source declares.
    fn fresh_leaf(&mut self) -> String {
        loop {
            self.leaf_count += 1;
            let name = format!("{}st_v{}", self.tag, self.leaf_count);
            if self.taken.insert(name.to_ascii_uppercase()) {
                return name;
            }
        }
    }

    /// The leaves of a value of `ty` at `path`, in order.
    fn leaves(
        &self,
        ty: &TypeRef,
        init: Option<&Init>,
        path: String,
        out: &mut Vec<Leaf>,
        depth: usize,
    ) -> Result<(), Stop> {
        if out.len() > MAX_LEAVES {
            return Err(Stop::TooBig);
        }
        let (ty, init) = self.resolved(ty, init);
        match ty {
            TypeRef::Array { dims, of } => self.array_leaves(dims, of, init, &path, out, depth),
            TypeRef::Named(n) => match self.type_def(&n.name) {
                Some(TypeDef::Struct(members)) if depth < 32 => {
                    let given = match init {
                        Some(Init::Struct(fields)) => fields.as_slice(),
                        _ => &[],
                    };
                    for m in members {
                        for name in &m.names {
                            let own = given
                                .iter()
                                .find(|(f, _)| f.name.eq_ignore_ascii_case(&name.name))
                                .map(|(_, v)| v)
                                .or(m.init.as_ref());
                            let p = format!("{path}.{}", name.name);
                            self.leaves(&m.ty, own, p, out, depth + 1)?;
                        }
                    }
                    Ok(())
                }
                _ => Err(Stop::NotComposite),
            },
            elementary => {
                let init = match init {
                    Some(i @ Init::Expr(_)) => Some(super::print::init_text(i)),
                    _ => None,
                };
                let ty = super::print::type_text(elementary);
                out.push(Leaf { path, ty, init });
                Ok(())
            }
        }
    }

    fn array_leaves(
        &self,
        dims: &[(i128, i128)],
        of: &TypeRef,
        init: Option<&Init>,
        path: &str,
        out: &mut Vec<Leaf>,
        depth: usize,
    ) -> Result<(), Stop> {
        let count = dims.iter().try_fold(1usize, |n, (lo, hi)| {
            let len = usize::try_from(hi - lo + 1).ok()?;
            n.checked_mul(len).filter(|&n| n <= MAX_LEAVES)
        });
        let count = count.ok_or(Stop::TooBig)?;
        let mut values: Vec<Option<&Init>> = Vec::new();
        if let Some(Init::Array(items)) = init {
            for item in items {
                match item {
                    ArrayInit::One(v) => values.push(Some(v)),
                    ArrayInit::Repeat(n, v) => {
                        let n = (*n as usize).min(count.saturating_sub(values.len()));
                        values.extend(std::iter::repeat_n(v.as_ref(), n));
                    }
                }
            }
        }
        for k in 0..count {
            let (mut rest, mut index) = (k, Vec::new());
            for (lo, hi) in dims.iter().rev() {
                let len = usize::try_from(hi - lo + 1).unwrap_or(1).max(1);
                index.push(lo + (rest % len) as i128);
                rest /= len;
            }
            index.reverse();
            let shown: Vec<String> = index.iter().map(i128::to_string).collect();
            let p = format!("{path}[{}]", shown.join(", "));
            let v = values.get(k).copied().flatten();
            self.leaves(of, v, p, out, depth + 1)?;
        }
        Ok(())
    }

    /// The key of `v` as written with constant indices (`A[1,2].M`);
    /// `None` when an index is computed at run time.
    fn path_key(v: &Variable) -> Option<String> {
        let mut k = v.base.name.to_ascii_uppercase();
        for s in &v.path {
            match s {
                Selector::Member(m) => {
                    k.push('.');
                    k.push_str(&m.name.to_ascii_uppercase());
                }
                Selector::Index(ix) => {
                    let parts: Option<Vec<String>> = ix
                        .iter()
                        .map(|e| constant(e).map(|c| c.to_string()))
                        .collect();
                    k.push('[');
                    k.push_str(&parts?.join(","));
                    k.push(']');
                }
            }
        }
        Some(k)
    }

    /// The hidden variable `v` names, when it is one value inside a
    /// flattened variable.
    pub(super) fn leaf(&self, v: &Variable) -> Option<String> {
        if !self.flat_bases.contains(&v.base.name.to_ascii_uppercase()) {
            return None;
        }
        self.flat.get(&Self::path_key(v)?).cloned()
    }

    /// `v` read: its leaf, or the element operand of a run-time index.
    pub(super) fn flat_load(&mut self, v: &Variable, span: Span) {
        match self.leaf(v).or_else(|| self.element(v)) {
            Some(op) => self.emit(format!("LD {op}"), span),
            None => self.refuse_flat(v, span),
        }
    }

    /// The IL element operand (`st_v1[i:1:3:2]`) of `v` when an index of
    /// it is a variable known only at run time: the first element it can
    /// reach, and each such index with its dimension's low bound, length
    /// and the slots from one index to the next.
    pub(super) fn element(&self, v: &Variable) -> Option<String> {
        let base = v.base.name.to_ascii_uppercase();
        let mut ty = self.flat_types.get(&base)?;
        let mut parts = vec![base];
        // (index variable, low, length, the part it is in)
        let mut runtime: Vec<(String, i128, i128, usize)> = Vec::new();
        for s in &v.path {
            ty = self.resolved(ty, None).0;
            match (s, ty) {
                (Selector::Member(m), TypeRef::Named(n)) => {
                    let Some(TypeDef::Struct(ms)) = self.type_def(&n.name) else {
                        return None;
                    };
                    let d = ms
                        .iter()
                        .find(|d| d.names.iter().any(|x| x.name.eq_ignore_ascii_case(&m.name)))?;
                    ty = &d.ty;
                    parts.push(format!(".{}", m.name.to_ascii_uppercase()));
                }
                (Selector::Index(ix), TypeRef::Array { dims, of }) if ix.len() == dims.len() => {
                    parts.push("[".into());
                    for (k, (e, (lo, hi))) in ix.iter().zip(dims).enumerate() {
                        if k > 0 {
                            parts.push(",".into());
                        }
                        let temp = self.indexed.get(&(e.span.line, e.span.column));
                        match (constant(e), &e.kind, temp) {
                            (Some(c), _, _) => parts.push(c.to_string()),
                            (None, _, Some(t)) => {
                                runtime.push((t.clone(), *lo, hi - lo + 1, parts.len()));
                                parts.push(lo.to_string());
                            }
                            (None, ExprKind::Variable(_), None) => {
                                let name =
                                    self.simple(e).filter(|n| crate::iec::is_identifier(n))?;
                                runtime.push((name, *lo, hi - lo + 1, parts.len()));
                                parts.push(lo.to_string());
                            }
                            _ => return None,
                        }
                    }
                    parts.push("]".into());
                    ty = of;
                }
                _ => return None,
            }
        }
        if runtime.is_empty() {
            return None;
        }
        let first = self.flat.get(&parts.concat())?;
        let at = |h: &String| self.order.get(h).copied();
        let mut dims = Vec::new();
        for (name, lo, len, part) in runtime {
            let stride = if len > 1 {
                let mut next = parts.clone();
                next[part] = (lo + 1).to_string();
                let h = self.flat.get(&next.concat())?;
                at(h)? - at(first)?
            } else {
                0
            };
            dims.push(format!("{name}:{lo}:{len}:{stride}"));
        }
        Some(format!("{first}[{}]", dims.join(",")))
    }

    /// The own-function calls in `v`'s indices made, then each index of
    /// a flattened variable that is an expression (`a[i + 1]`) computed
    /// into a hidden variable of its type (`indexed`), before the
    /// statement that reads or writes the element.
    pub(super) fn hoist_indices(&mut self, v: &Variable) {
        for s in &v.path {
            let Selector::Index(ix) = s else { continue };
            for e in ix {
                self.hoist(e);
                let plain = constant(e).is_some() || self.simple(e).is_some();
                if plain || !self.is_flat(v) {
                    continue;
                }
                let Some(ty) = self.index_type(e) else {
                    continue;
                };
                let temp = self.fresh("st_i");
                self.hidden.push((temp.clone(), ty));
                self.expr(e);
                self.emit(format!("ST {temp}"), e.span);
                self.indexed.insert((e.span.line, e.span.column), temp);
            }
        }
    }

    /// An integer index expression's type: any plain variable's in it
    /// (the checker allows one type per operation and no conversion but
    /// a call's, so every variable in a call-free expression has the
    /// expression's type); `None` with a call or no variable.
    fn index_type(&self, e: &Expr) -> Option<String> {
        match &e.kind {
            ExprKind::Variable(v) if v.path.is_empty() => {
                self.scalars.get(&v.base.name.to_ascii_uppercase()).cloned()
            }
            ExprKind::Unary(_, x) => self.index_type(x),
            ExprKind::Binary(_, a, b) => self.index_type(a).or_else(|| self.index_type(b)),
            _ => None,
        }
    }

    /// Whether `v` reaches into (or is) a flattened variable.
    pub(super) fn is_flat(&self, v: &Variable) -> bool {
        self.flat_bases.contains(&v.base.name.to_ascii_uppercase())
    }

    /// Why `v`, inside a flattened variable, is no one value: an index
    /// computed at run time, one outside its array, or a whole STRUCT
    /// or ARRAY where one value is needed.
    pub(super) fn refuse_flat(&mut self, v: &Variable, span: Span) {
        let Some(k) = Self::path_key(v) else {
            let what = "an index that is an expression (compute it into a variable first)";
            return self.not_yet(span, what);
        };
        let inside = self.flat.keys().any(|f| {
            f.strip_prefix(k.as_str())
                .is_some_and(|rest| rest.starts_with(['.', '[']))
        });
        if inside {
            self.not_yet(span, "a whole STRUCT or ARRAY here (name one value of it)");
        } else {
            self.errors.push(at(span, StErrorKind::IndexOutOfRange(k)));
        }
    }

    /// `target := value` where either reaches into a flattened variable:
    /// one value, or a whole STRUCT or ARRAY copied value by value from
    /// one of the same type.
    pub(super) fn flat_assign(&mut self, target: &Variable, value: &Expr, span: Span) {
        self.hoist_indices(target);
        if let Some(t) = self.leaf(target).or_else(|| self.element(target)) {
            self.value(value);
            return self.emit(format!("ST {t}"), span);
        }
        let pairs = match (&value.kind, Self::path_key(target)) {
            (ExprKind::Variable(src), Some(to)) if self.is_flat(src) => {
                Self::path_key(src).map(|from| self.copies(&from, &to))
            }
            _ => None,
        };
        match pairs {
            Some(pairs) if !pairs.is_empty() => {
                for (from, to) in pairs {
                    self.emit(format!("LD {from}"), span);
                    self.emit(format!("ST {to}"), span);
                }
            }
            _ => self.refuse_flat(target, span),
        }
    }

    /// The (source, target) leaves of a copy from path `from` to `to`
    /// (keys), matched by what follows each; empty when they differ.
    fn copies(&self, from: &str, to: &str) -> Vec<(String, String)> {
        let under = |base: &str| -> Vec<(String, String)> {
            let mut v: Vec<(String, String)> = self
                .flat
                .iter()
                .filter_map(|(k, h)| {
                    let rest = k.strip_prefix(base)?;
                    rest.starts_with(['.', '['])
                        .then(|| (rest.to_string(), h.clone()))
                })
                .collect();
            v.sort();
            v
        };
        let (a, b) = (under(from), under(to));
        let same = a.len() == b.len() && a.iter().zip(&b).all(|(x, y)| x.0 == y.0);
        if !same {
            return Vec::new();
        }
        a.into_iter().zip(b).map(|(x, y)| (x.1, y.1)).collect()
    }
}

/// An index's value when it is a whole-number literal (maybe negated).
fn constant(e: &Expr) -> Option<i128> {
    match &e.kind {
        ExprKind::Literal(Literal::Integer(v, _)) => Some(*v),
        ExprKind::Unary(UnaryOp::Neg, x) => constant(x).map(|v| -v),
        ExprKind::Unary(UnaryOp::Plus, x) => constant(x),
        _ => None,
    }
}
