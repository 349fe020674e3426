//! The engine's errors that the page shows, in the page's language
//! (issue #49), from their kind and arguments: the editor's refusals and
//! a rung's wiring problems ([`edit`]), the Tests pane's texts
//! ([`cases`]), the soft PLC's program errors ([`program`]). English is
//! the engine's own (`Display`, as the command line says it). Every
//! variant is matched by name (no `_`): a new kind does not compile
//! until it has its Japanese. Device names, mnemonics, keywords and what
//! a file or a user wrote are kept as written.

mod arduino;
mod avr;
mod cases;
pub(crate) use cases::time_ja;
mod decompile;
mod edit;
mod io86a;
mod program;
mod settings;
mod share;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_text;
#[cfg(test)]
mod tests_why;

use engine::cases::{CaseError, Observed};
use engine::ladder::edit::{ClipError, EditError, ReplaceError};
use engine::ladder::problem::RungProblem;
use engine::plc::PlcError;
use engine::softplc::LoadError;

use super::Lang;

pub(super) use edit::rung_problem_ja;

/// Why a break condition was refused.
pub fn condition_error(lang: Lang, e: &engine::record::ConditionError) -> String {
    use engine::record::ConditionError as C;
    match (lang, e) {
        (Lang::En, _) => e.to_string(),
        (Lang::Ja, C::Form(text)) => format!(
            "`{text}`: DEVICE rises|falls|on|off|changes か DEVICE = N (!=, <, <=, >, >= も) と書いてください。例: `Y01 rises`, `C0.v = 5`"
        ),
        (Lang::Ja, C::Device(e)) => cases::plc_ja(e),
    }
}

/// Why a share link does not open.
pub fn share_error(lang: Lang, e: &engine::formats::share::ShareError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => share::share_ja(e),
    }
}

/// An edit's refusal (placing, wiring, pasting, replacing, a variable).
pub fn edit_error(lang: Lang, e: &EditError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => edit::edit_ja(e),
    }
}

/// Why a clip does not paste.
pub fn clip_error(lang: Lang, e: &ClipError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => edit::clip_ja(e),
    }
}

/// Why a batch replace's names make no plan.
pub fn replace_error(lang: Lang, e: &ReplaceError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => edit::replace_ja(e),
    }
}

/// A rung's wiring or placement problem.
pub fn rung_problem(lang: Lang, p: &RungProblem) -> String {
    match lang {
        Lang::En => p.to_string(),
        Lang::Ja => rung_problem_ja(p),
    }
}

/// Why a test case could not run.
pub fn case_error(lang: Lang, e: &CaseError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => cases::case_error_ja(e),
    }
}

/// What a failed expectation saw.
pub fn observed(lang: Lang, o: &Observed) -> String {
    match lang {
        Lang::En => o.to_string(),
        Lang::Ja => cases::observed_ja(o),
    }
}

/// A machine's refusal of a command (a setting, a device, a program).
pub fn plc_error(lang: Lang, e: &PlcError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => cases::plc_ja(e),
    }
}

/// Why Load as ladder could not read a program text: its lines' errors,
/// or the step with no ladder form, in the page's language.
pub fn text_error(lang: Lang, e: &engine::ladder::decompile::TextError) -> String {
    use engine::ladder::decompile::TextError;
    match (lang, e) {
        (Lang::Ja, TextError::Program(problems)) => {
            cases::plc_ja(&PlcError::Program(problems.clone()))
        }
        (Lang::Ja, TextError::Decompile(e)) => decompile::decompile_ja(e),
        (Lang::En, _) => e.to_string(),
    }
}

/// Why a line of the Arduino PLC's listing is refused.
pub fn arduino_asm(lang: Lang, e: &engine::arduino::isa::AsmError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => arduino::arduino_asm_ja(e),
    }
}

/// Why a line of the AVR PLC's program text is refused.
pub fn avr_program(lang: Lang, e: &engine::avr::ProgramError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => avr::avr_program_ja(e),
    }
}

/// Why a line of IO86A's program text is refused.
pub fn io86a_asm(lang: Lang, e: &engine::io86a::AsmError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => io86a::io86a_asm_ja(e),
    }
}

/// Why a line of MINASEC-U's program text is refused.
pub fn minasec_asm(lang: Lang, e: &engine::minasec::AsmError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => program::minasec_asm_ja(e),
    }
}

/// Why a soft PLC program does not load.
pub fn load_error(lang: Lang, e: &LoadError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => program::load_ja(e),
    }
}

/// The first run of three or more English words in `text` (words of
/// lower-case letters, a capital allowed first: device names, mnemonics
/// and keywords are upper case or carry digits; only spaces join a run,
/// so a list such as `ns, us, ms` is not a sentence), if there is one.
/// The test the page's Japanese is held to; the e2e tests use the same
/// rule.
pub fn english_run(text: &str) -> Option<String> {
    let is_word = |w: &str| {
        let mut chars = w.chars();
        chars.next().is_some_and(|c| c.is_ascii_alphabetic())
            && chars.all(|c| c.is_ascii_lowercase() || c == '\'')
    };
    let mut run: Vec<&str> = Vec::new();
    for token in text.split(char::is_whitespace) {
        if token.is_empty() {
            continue;
        }
        // Punctuation after a word (`output:`) ends the run with it.
        let bare = token.trim_end_matches([',', '.', ';', ':', ')']);
        if !is_word(bare) {
            run.clear();
            continue;
        }
        run.push(bare);
        if run.len() >= 3 {
            return Some(run.join(" "));
        }
        if bare.len() != token.len() {
            run.clear();
        }
    }
    None
}

/// A text in both languages, made when it happens (a test's result, an
/// engine error), shown in the language of the moment: switching the
/// language does not leave it in the other.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Both {
    /// In English (the engine's words).
    pub en: String,
    /// In Japanese.
    pub ja: String,
}

impl Both {
    /// The text in each language, from `say`.
    pub fn new(say: impl Fn(Lang) -> String) -> Both {
        Both {
            en: say(Lang::En),
            ja: say(Lang::Ja),
        }
    }

    /// The text in `lang`.
    pub fn in_lang(&self, lang: Lang) -> &str {
        match lang {
            Lang::En => &self.en,
            Lang::Ja => &self.ja,
        }
    }
}

impl From<&str> for Both {
    /// The same words in both (a device name, a test's own text).
    fn from(text: &str) -> Both {
        Both {
            en: text.to_string(),
            ja: text.to_string(),
        }
    }
}
