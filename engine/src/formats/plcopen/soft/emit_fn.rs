//! A drawn block that calls one of the project's own FUNCTIONs (in ST
//! or IL, issue #54): the function runs as a block whose output of its
//! own name is its result, so the box becomes a `CAL` of a hidden
//! instance of it, its result given to what the drawn output (`OUT`, as
//! Beremiz and OpenPLC Editor name it) feeds. EN and ENO as for any box.

use super::declare::Interface;
use super::emit::Emitter;
use super::SoftError;
use crate::formats::plcopen::graph::{Element, Graph};

impl Emitter<'_> {
    /// `CAL _<k>_f<id>(input := …, Name => _<k>_n<id>_OUT)`.
    pub(super) fn own_function(
        &mut self,
        g: &Graph,
        e: &Element,
        type_name: &str,
        iface: &Interface,
    ) -> Result<(), SoftError> {
        let Some((result, ty)) = iface
            .outputs
            .iter()
            .find(|(p, _)| p.eq_ignore_ascii_case(type_name))
            .cloned()
        else {
            return Err(SoftError::Block(type_name.to_string()));
        };
        let hidden = self.temp(&format!("f{}", e.id), type_name, e.line);
        let en = self.enable(g, e)?;
        super::formal::check_inputs(e, &iface.inputs)?;
        let mut params = Vec::new();
        for (pin, t) in &iface.inputs {
            if let Some(v) = self.input(g, e, pin)? {
                params.push(format!("{pin} := {}", v.at(Some(*t)).text));
            }
        }
        let drawn = e
            .outputs
            .iter()
            .find(|p| !p.eq_ignore_ascii_case("ENO"))
            .cloned()
            .unwrap_or_else(|| "OUT".into());
        let out = self.temp(&format!("n{}_{drawn}", e.id), ty.name(), e.line);
        params.push(format!("{result} => {out}"));
        params.extend(self.decl.external_args(&self.pou, type_name, iface)?);
        self.emit(format!("CAL {hidden}({})", params.join(", ")), e.line);
        self.enabled(e, en);
        Ok(())
    }
}
