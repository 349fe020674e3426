//! What a machine's front shows beyond its devices (MINASEC-U's panel of
//! LEDs, switches and knobs; the IO86A's pin modes and output signals),
//! copied each frame into a value the caller keeps. Each front is the
//! machine's own type (`minasec::Panel`, `io86a::Fronts`), so this module
//! names no machine.

use std::any::Any;

/// A machine's front, as [`super::Plc::front_into`] fills it: empty for a
/// machine with nothing beyond its devices (the Arduino sketch, the AVR
/// PLC) or before the first copy; else the machine's own type, kept
/// between frames so that a copy allocates nothing.
#[derive(Default)]
pub struct Front(Option<Box<dyn Any + Send + Sync>>);

impl Front {
    /// An empty front.
    pub fn none() -> Front {
        Front(None)
    }

    /// Whether nothing has been copied into it.
    pub fn is_none(&self) -> bool {
        self.0.is_none()
    }

    /// The front as `T`, if it is one.
    pub fn get<T: Any>(&self) -> Option<&T> {
        self.0.as_deref().and_then(|f| f.downcast_ref::<T>())
    }

    /// Fills the front in place as `T` with `fill`: the one kept, or a new
    /// default one when it held nothing or another machine's.
    pub fn fill<T: Any + Default + Send + Sync>(&mut self, fill: impl FnOnce(&mut T)) {
        match self.0.as_deref_mut().and_then(|f| f.downcast_mut::<T>()) {
            Some(front) => fill(front),
            None => {
                let mut front = T::default();
                fill(&mut front);
                self.0 = Some(Box::new(front));
            }
        }
    }

    /// Empties it.
    pub fn clear(&mut self) {
        self.0 = None;
    }
}

impl std::fmt::Debug for Front {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.is_none() {
            "Front(none)"
        } else {
            "Front(..)"
        })
    }
}
