//! One saved slot shared by every open tab of the page, with the revision
//! each save replaces, so that no tab overwrites work it has not seen
//! (docs/editor.md, "Two tabs"). Plain Rust over a [`StorageBackend`],
//! tested natively.
//!
//! The value stays under its key as it always was (a project's JSON); its
//! revision, a counter, is kept beside it under `<key>.rev`. A save writes
//! the value, then the revision one higher, and only when the revision
//! stored is still the one this tab last read or wrote.

use super::backend::{StorageBackend, StorageFault};

/// What this tab knows of one saved slot.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Slot {
    key: String,
    /// The revision this tab last read or wrote there.
    seen: u64,
    state: SlotState,
}

/// Whether this tab's work is in the slot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SlotState {
    /// Everything this tab made is saved.
    Saved,
    /// The storage refused the last save: the work is only in this page.
    Unsaved(StorageFault),
    /// Another tab saved newer work there while this one had work of its
    /// own: nothing is written until the user chooses.
    Conflict,
}

/// How a save went.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Saving {
    /// Written, as revision `n`.
    Saved(u64),
    /// Not written: the slot holds newer work from another tab.
    Conflict,
    /// Not written: the storage refused. `first` when the last save had
    /// gone through (the page says so once, not at every edit).
    Failed { fault: StorageFault, first: bool },
}

/// What another tab's save means for this one.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Elsewhere {
    /// Nothing new in the slot.
    Nothing,
    /// This tab had nothing unsaved: it shows the newer work (`value`),
    /// already taken as seen.
    Follow(String),
    /// This tab has work of its own: the user chooses.
    Conflict,
}

impl Slot {
    /// The slot under `key`, as it now is in `store`.
    pub fn open(store: &dyn StorageBackend, key: &str) -> Slot {
        Slot {
            key: key.to_string(),
            seen: revision(store, key),
            state: SlotState::Saved,
        }
    }

    /// Its key.
    pub fn key(&self) -> &str {
        &self.key
    }

    /// Whether this tab's work is in the slot.
    pub fn state(&self) -> SlotState {
        self.state
    }

    /// Saves `value` unless another tab saved since this one last looked.
    pub fn save(&mut self, store: &dyn StorageBackend, value: &str) -> Saving {
        if self.state == SlotState::Conflict {
            return Saving::Conflict;
        }
        let now = revision(store, &self.key);
        if now != self.seen {
            self.state = SlotState::Conflict;
            return Saving::Conflict;
        }
        self.write(store, value, now)
    }

    fn write(&mut self, store: &dyn StorageBackend, value: &str, now: u64) -> Saving {
        let next = now.wrapping_add(1);
        // The value first: a tab that hears of the new revision reads it.
        let written = store
            .set(&self.key, value)
            .and_then(|()| store.set(&revision_key(&self.key), &next.to_string()));
        match written {
            Ok(()) => {
                self.seen = next;
                self.state = SlotState::Saved;
                Saving::Saved(next)
            }
            Err(fault) => {
                let first = !matches!(self.state, SlotState::Unsaved(_));
                self.state = SlotState::Unsaved(fault);
                Saving::Failed { fault, first }
            }
        }
    }

    /// After another tab wrote `key` (the `storage` event): follow it when
    /// this tab has nothing unsaved, else a conflict.
    pub fn elsewhere(&mut self, store: &dyn StorageBackend) -> Elsewhere {
        let now = revision(store, &self.key);
        if now == self.seen {
            return Elsewhere::Nothing;
        }
        match self.state {
            SlotState::Saved => match store.get(&self.key) {
                Ok(Some(value)) => {
                    self.seen = now;
                    Elsewhere::Follow(value)
                }
                // Their revision without a value: nothing to show.
                Ok(None) | Err(_) => Elsewhere::Nothing,
            },
            SlotState::Unsaved(_) | SlotState::Conflict => {
                self.state = SlotState::Conflict;
                Elsewhere::Conflict
            }
        }
    }

    /// "Load theirs": the slot's value, now seen; this tab's work is
    /// replaced by it.
    pub fn theirs(&mut self, store: &dyn StorageBackend) -> Option<String> {
        let now = revision(store, &self.key);
        let value = store.get(&self.key).ok().flatten()?;
        self.seen = now;
        self.state = SlotState::Saved;
        Some(value)
    }

    /// Whether `key` is this slot's value or its revision (a `storage`
    /// event's key).
    pub fn is_about(&self, key: &str) -> bool {
        key == self.key || key == revision_key(&self.key)
    }
}

/// Where the revision of the value under `key` is kept.
pub fn revision_key(key: &str) -> String {
    format!("{key}.rev")
}

/// The revision stored for `key` (0 when none, as before revisions were
/// kept, or unreadable).
fn revision(store: &dyn StorageBackend, key: &str) -> u64 {
    store
        .get(&revision_key(key))
        .ok()
        .flatten()
        .and_then(|r| r.trim().parse().ok())
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::super::backend::MemoryStorage;
    use super::*;

    #[test]
    fn two_tabs_take_turns_and_nothing_is_lost() {
        let store = MemoryStorage::default();
        let mut a = Slot::open(&store, "k");
        let mut b = Slot::open(&store, "k");
        assert_eq!(b.save(&store, "B's rung"), Saving::Saved(1));
        // A had saved everything: it follows B.
        assert_eq!(a.elsewhere(&store), Elsewhere::Follow("B's rung".into()));
        assert_eq!(a.save(&store, "B's rung + A's edit"), Saving::Saved(2));
        assert_eq!(
            b.elsewhere(&store),
            Elsewhere::Follow("B's rung + A's edit".into())
        );
        assert_eq!(b.elsewhere(&store), Elsewhere::Nothing);
    }

    #[test]
    fn a_save_over_work_it_has_not_seen_is_a_conflict_and_writes_nothing() {
        let store = MemoryStorage::default();
        let mut a = Slot::open(&store, "k");
        let mut b = Slot::open(&store, "k");
        assert_eq!(b.save(&store, "theirs"), Saving::Saved(1));
        // A edits before it heard of B's save.
        assert_eq!(a.save(&store, "mine"), Saving::Conflict);
        assert_eq!(a.state(), SlotState::Conflict);
        assert_eq!(store.get("k"), Ok(Some("theirs".into())));
        // Every later save waits for the choice too.
        assert_eq!(a.save(&store, "mine, again"), Saving::Conflict);
        assert_eq!(a.theirs(&store), Some("theirs".into()));
        assert_eq!(a.save(&store, "theirs + mine"), Saving::Saved(2));
    }

    #[test]
    fn storage_full_is_said_once_the_work_stays_and_a_later_save_goes_through() {
        let store = MemoryStorage::with_quota(40);
        let mut a = Slot::open(&store, "k");
        assert_eq!(a.save(&store, "small"), Saving::Saved(1));
        let big = "x".repeat(100);
        let full = Saving::Failed {
            fault: StorageFault::Full,
            first: true,
        };
        assert_eq!(a.save(&store, &big), full);
        assert_eq!(
            a.save(&store, &big),
            Saving::Failed {
                fault: StorageFault::Full,
                first: false
            }
        );
        assert_eq!(a.state(), SlotState::Unsaved(StorageFault::Full));
        assert_eq!(store.get("k"), Ok(Some("small".into())), "kept as it was");
        // Another tab's save while this one has unsaved work: a conflict.
        let mut b = Slot::open(&store, "k");
        assert_eq!(b.save(&store, "b"), Saving::Saved(2));
        assert_eq!(a.elsewhere(&store), Elsewhere::Conflict);
        // Room again: after the user's choice (theirs), a save goes through.
        assert_eq!(a.theirs(&store), Some("b".into()));
        assert_eq!(a.save(&store, "mine"), Saving::Saved(3));
    }

    #[test]
    fn blocked_storage_fails_without_a_panic() {
        let store = MemoryStorage::blocked();
        let mut a = Slot::open(&store, "k");
        assert_eq!(
            a.save(&store, "x"),
            Saving::Failed {
                fault: StorageFault::Unavailable,
                first: true
            }
        );
        assert_eq!(a.elsewhere(&store), Elsewhere::Nothing);
    }

    #[test]
    fn a_value_saved_before_revisions_is_revision_zero() {
        let store = MemoryStorage::default();
        store.set("k", "old").expect("set");
        let mut a = Slot::open(&store, "k");
        assert_eq!(a.save(&store, "new"), Saving::Saved(1));
        assert!(a.is_about("k") && a.is_about("k.rev") && !a.is_about("k2"));
    }
}
