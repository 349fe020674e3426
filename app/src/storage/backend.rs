//! Where saved values live: the browser's localStorage on the page, a
//! map in memory in native tests (as Ruffle's `StorageBackend` with its
//! in-memory version). Every read and write of the page goes through the
//! one backend [`backend`] returns, so what the page saves can be tested
//! without a browser, storage full and storage blocked included.

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::rc::Rc;

/// Why a value could not be read or written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StorageFault {
    /// There is no storage (private mode, blocked by a setting or policy).
    Unavailable,
    /// The storage refused the write (its quota is used up).
    Full,
}

/// A store of strings by key.
pub trait StorageBackend {
    /// The value under `key`, `None` when nothing is saved there.
    fn get(&self, key: &str) -> Result<Option<String>, StorageFault>;
    /// Saves `value` under `key`.
    fn set(&self, key: &str, value: &str) -> Result<(), StorageFault>;
    /// Forgets `key` (nothing when it is not there or storage is missing).
    fn remove(&self, key: &str);
}

/// The browser's localStorage.
pub struct BrowserStorage;

impl BrowserStorage {
    fn store() -> Result<web_sys::Storage, StorageFault> {
        web_sys::window()
            .and_then(|w| w.local_storage().ok().flatten())
            .ok_or(StorageFault::Unavailable)
    }
}

impl StorageBackend for BrowserStorage {
    fn get(&self, key: &str) -> Result<Option<String>, StorageFault> {
        Self::store()?
            .get_item(key)
            .map_err(|_| StorageFault::Unavailable)
    }

    fn set(&self, key: &str, value: &str) -> Result<(), StorageFault> {
        // With storage present, a refused write is its quota (the
        // browsers' QuotaExceededError).
        Self::store()?
            .set_item(key, value)
            .map_err(|_| StorageFault::Full)
    }

    fn remove(&self, key: &str) {
        if let Ok(store) = Self::store() {
            let _ = store.remove_item(key);
        }
    }
}

/// Storage in memory, with a quota in bytes of keys and values (as the
/// browsers count it, roughly) or none at all (storage blocked).
#[derive(Default)]
pub struct MemoryStorage {
    values: RefCell<BTreeMap<String, String>>,
    quota: Option<usize>,
    blocked: bool,
}

impl MemoryStorage {
    /// Storage with room for `quota` bytes of keys and values.
    pub fn with_quota(quota: usize) -> MemoryStorage {
        MemoryStorage {
            quota: Some(quota),
            ..MemoryStorage::default()
        }
    }

    /// No storage at all, as in a private window that blocks it.
    pub fn blocked() -> MemoryStorage {
        MemoryStorage {
            blocked: true,
            ..MemoryStorage::default()
        }
    }

    fn used_without(&self, key: &str) -> usize {
        self.values
            .borrow()
            .iter()
            .filter(|(k, _)| k.as_str() != key)
            .map(|(k, v)| k.len() + v.len())
            .sum()
    }
}

impl StorageBackend for MemoryStorage {
    fn get(&self, key: &str) -> Result<Option<String>, StorageFault> {
        if self.blocked {
            return Err(StorageFault::Unavailable);
        }
        Ok(self.values.borrow().get(key).cloned())
    }

    fn set(&self, key: &str, value: &str) -> Result<(), StorageFault> {
        if self.blocked {
            return Err(StorageFault::Unavailable);
        }
        if let Some(quota) = self.quota {
            if self.used_without(key) + key.len() + value.len() > quota {
                return Err(StorageFault::Full);
            }
        }
        self.values
            .borrow_mut()
            .insert(key.to_string(), value.to_string());
        Ok(())
    }

    fn remove(&self, key: &str) {
        self.values.borrow_mut().remove(key);
    }
}

thread_local! {
    static BACKEND: RefCell<Rc<dyn StorageBackend>> = RefCell::new(default_backend());
}

#[cfg(target_arch = "wasm32")]
fn default_backend() -> Rc<dyn StorageBackend> {
    Rc::new(BrowserStorage)
}

#[cfg(not(target_arch = "wasm32"))]
fn default_backend() -> Rc<dyn StorageBackend> {
    // Natively there is no browser: tests save in memory.
    Rc::new(MemoryStorage::default())
}

/// The page's storage.
pub fn backend() -> Rc<dyn StorageBackend> {
    BACKEND.with(|b| Rc::clone(&b.borrow()))
}

/// Puts `store` in place of the page's storage (tests).
pub fn use_backend(store: Rc<dyn StorageBackend>) {
    BACKEND.with(|b| *b.borrow_mut() = store);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn memory_storage_refuses_what_passes_its_quota_and_keeps_what_it_had() {
        let store = MemoryStorage::with_quota(20);
        assert_eq!(store.set("a", "0123456789"), Ok(()));
        assert_eq!(store.set("b", "0123456789"), Err(StorageFault::Full));
        assert_eq!(store.get("a"), Ok(Some("0123456789".into())));
        assert_eq!(store.get("b"), Ok(None));
        // Replacing a value counts its new size only.
        assert_eq!(store.set("a", "012345678901234567"), Ok(()));
        let blocked = MemoryStorage::blocked();
        assert_eq!(blocked.get("a"), Err(StorageFault::Unavailable));
        assert_eq!(blocked.set("a", "x"), Err(StorageFault::Unavailable));
    }
}
