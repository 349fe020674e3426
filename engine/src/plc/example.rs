//! An example program: a program in one machine's own text with its
//! titles. Each machine folder lists its own (`examples.rs` there); the
//! registry joins them (`machines::EXAMPLES`, also `examples::EXAMPLES`).

use crate::MachineId;

/// One example program.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Example {
    /// Its id in the menu (unique per machine).
    pub id: &'static str,
    /// The machine it is for.
    pub machine: MachineId,
    /// Its title in English.
    pub title_en: &'static str,
    /// Its title in Japanese.
    pub title_ja: &'static str,
    /// The program text.
    pub text: &'static str,
}

/// The lists in `parts` one after another; `N` is their total length
/// (`fill` only fills the list before it is written over).
pub(crate) const fn joined<const N: usize>(parts: &[&[Example]], fill: Example) -> [Example; N] {
    let mut out = [fill; N];
    let (mut i, mut k) = (0, 0);
    while k < parts.len() {
        let mut j = 0;
        while j < parts[k].len() {
            out[i] = parts[k][j];
            i += 1;
            j += 1;
        }
        k += 1;
    }
    assert!(i == N, "joined: N is not the lists' total length");
    out
}

/// The total length of `parts`.
pub(crate) const fn total(parts: &[&[Example]]) -> usize {
    let (mut n, mut k) = (0, 0);
    while k < parts.len() {
        n += parts[k].len();
        k += 1;
    }
    n
}
