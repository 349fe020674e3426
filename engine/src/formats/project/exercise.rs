//! An exercise (issue #49, docs/tests.md "Exercises"): the task a student
//! reads, in English and Japanese as its author wrote it, and whether
//! the tests are shown to the student. Older projects say
//! `"exercise": true`, which reads as an exercise without a task, its
//! tests shown, and is written back the same way.

use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// Most bytes a task may have in one language (a page of text).
pub const MAX_TASK_BYTES: usize = 16 * 1024;

/// The task and how the tests are shown.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Exercise {
    /// What the student is asked to do.
    #[serde(default, skip_serializing_if = "Task::is_empty")]
    pub task: Task,
    /// Whether the student sees the tests.
    #[serde(default)]
    pub tests: TestsShown,
}

/// The task in each language its author wrote it in (docs/tests.md:
/// paragraphs, `- ` lists, `**bold**` and `` `code` ``).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Task {
    /// In English.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub en: String,
    /// In Japanese.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub ja: String,
}

impl Task {
    /// Neither language has a word.
    pub fn is_empty(&self) -> bool {
        self.en.trim().is_empty() && self.ja.trim().is_empty()
    }

    /// The task in `lang` (`"en"`, `"ja"`), or in the other language when
    /// the author wrote only that one.
    pub fn in_lang(&self, lang: &str) -> &str {
        let (first, other) = if lang == "ja" {
            (&self.ja, &self.en)
        } else {
            (&self.en, &self.ja)
        };
        if first.trim().is_empty() {
            other
        } else {
            first
        }
    }
}

/// Whether an exercise's tests are shown to the student.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum TestsShown {
    /// The student sees the tests (not editable).
    #[default]
    Shown,
    /// The student sees only each failing case's name and hint. Hidden,
    /// not secret: a link can be decoded.
    Hidden,
}

impl Exercise {
    /// An exercise as `"exercise": true` said: no task, tests shown.
    pub fn is_plain(&self) -> bool {
        self.task.is_empty() && self.tests == TestsShown::Shown
    }

    /// Whether the tests are hidden from the student.
    pub fn hidden(&self) -> bool {
        self.tests == TestsShown::Hidden
    }
}

/// Reads `"exercise"`: `true` (an exercise without a task), `false` (none)
/// or the exercise; a task longer than [`MAX_TASK_BYTES`] is refused.
/// A visitor rather than an untagged enum, so that an error inside the
/// exercise (`"tests": "secret"`) is reported as itself, at its line.
pub(super) fn read<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Exercise>, D::Error> {
    struct Field;
    impl<'de> serde::de::Visitor<'de> for Field {
        type Value = Option<Exercise>;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("true, false or {\"task\": …, \"tests\": \"shown\"|\"hidden\"}")
        }
        fn visit_bool<E: serde::de::Error>(self, on: bool) -> Result<Self::Value, E> {
            Ok(on.then(Exercise::default))
        }
        fn visit_map<A: serde::de::MapAccess<'de>>(self, map: A) -> Result<Self::Value, A::Error> {
            let e = Exercise::deserialize(serde::de::value::MapAccessDeserializer::new(map))?;
            if e.task.en.len().max(e.task.ja.len()) > MAX_TASK_BYTES {
                return Err(serde::de::Error::custom(format!(
                    "the exercise's task is longer than the {MAX_TASK_BYTES} bytes it may have (docs/limits.md)"
                )));
            }
            Ok(Some(e))
        }
    }
    d.deserialize_any(Field)
}

/// Writes `"exercise"`: `true` for an exercise as older Hashigos knew it,
/// so that their files stay what they were; the exercise otherwise.
pub(super) fn write<S: Serializer>(e: &Option<Exercise>, s: S) -> Result<S::Ok, S::Error> {
    match e {
        Some(e) if !e.is_plain() => e.serialize(s),
        Some(_) => s.serialize_bool(true),
        None => s.serialize_bool(false),
    }
}
