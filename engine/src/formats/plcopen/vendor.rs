//! A tool's own elements in a drawn body (`<vendorElement>`), sorted by
//! what they do (issue #44): CODESYS writes each network's title as one
//! and the FBD body's implementation attributes as another, neither of
//! which runs; an element wired into the network, or holding data no
//! reader here knows (in-line code), carries logic and is refused.

use super::dom::Node;

/// What a vendor element is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Vendor {
    /// A network's title (CODESYS's `networktitle`): its text.
    Title(String),
    /// Settings of the body's editor (CODESYS's implementation
    /// attributes): nothing to run or say.
    Cosmetic,
    /// Neither wired nor holding data: its alternative text, skipped
    /// with a warning.
    Unknown(String),
    /// Wired into the network, or holding data of its own: why.
    Logic(String),
}

/// The pins an element wired into the network has.
const WIRING: [&str; 5] = [
    "connectionPointIn",
    "connectionPointOut",
    "inputVariables",
    "outputVariables",
    "inOutVariables",
];

/// What vendor element `n` is.
pub(crate) fn classify(n: &Node) -> Vendor {
    let mut found = Vec::new();
    for pin in WIRING {
        n.descendants(pin, &mut found);
    }
    if !found.is_empty() {
        return Vendor::Logic("it is wired into the network".into());
    }
    let text = n
        .child("alternativeText")
        .map(|t| t.deep_text().trim().to_string())
        .unwrap_or_default();
    let mut data = Vec::new();
    n.descendants("data", &mut data);
    let mut title = false;
    for d in &data {
        let name = d.attr("name").unwrap_or_default();
        let kind = name.rsplit('/').next().unwrap_or_default();
        let value = d.deep_text();
        match kind {
            "fbdelementtype" if value.trim().eq_ignore_ascii_case("networktitle") => title = true,
            "implementationattributes" => {}
            _ => {
                return Vendor::Logic(format!(
                    "it holds data {} no reader here knows",
                    crate::shown(name)
                ))
            }
        }
    }
    match (title, data.is_empty()) {
        (true, _) => Vendor::Title(text),
        (false, false) => Vendor::Cosmetic,
        (false, true) if text.is_empty() => Vendor::Unknown("a vendor element".into()),
        (false, true) => Vendor::Unknown(crate::shown(&text)),
    }
}

/// The words of a refusal of a vendor element carrying logic.
pub(crate) fn logic_refused(why: &str) -> String {
    format!("<vendorElement> carries logic ({why}): an element of the tool that wrote the file, which Hashigo cannot run")
}
